/**
 * Plan and run: select, prepare, run and judge, the whole gate in process, and the run's
 * verdict as a whole (CONTRACT.md: a gate never passes by doing nothing).
 */
import { resolveChoices, type Followed } from "./choices.js";
import { judge, prepare } from "./compare.js";
import { VerifyError } from "./errors.js";
import type { Implementation } from "./implementation.js";
import { applyKnown, loadKnownFailures, unknownIds, writeExpectations, type KnownFailures } from "./known.js";
import { selectWithEnvironment, type Selection } from "./selection.js";
import { interpretationsOf, loadSuite, type Suite } from "./suite.js";
import { FAILING, type Status, type Verdict } from "./verdict.js";
import { guarded, timeoutSeconds } from "./watchdog.js";

export interface RunOptions {
  /** Default: the packaged vectors, or the folder PLCVEC_VECTORS names. */
  readonly suite?: Suite;
  readonly selection?: Selection;
  readonly known?: KnownFailures;
  /** A selection of no vector is a failure unless this is set. */
  readonly allowEmpty?: boolean;
  /** Fail when more vectors than this are skipped: a count, or a percentage such as "5%". */
  readonly maxSkipped?: number | `${number}%`;
}

export interface Report {
  readonly implementation: string;
  readonly verdicts: readonly Verdict[];
  readonly counts: Readonly<Record<Status, number>>;
  /** Why the run as a whole fails though no vector did (empty selection, all skipped, too many skipped). */
  readonly runProblems: readonly string[];
  readonly passed: boolean;
  /** The alternative followed for every interpretation, declared or default. */
  readonly choices: Readonly<Record<string, string>>;
  /** Every interpretation's default. */
  readonly defaults: Readonly<Record<string, string>>;
  /** The alternatives the implementation declared. */
  readonly declared: Readonly<Record<string, string>>;
  /** The interpretations of the families run, each with its alternatives in file order. */
  readonly interpretations: ReadonlyMap<string, readonly string[]>;
  /** The devices the implementation declares its CPU writes. */
  readonly cpuWrites: readonly string[];
  /** The vectors selected (stale ids of the known-failures file not counted). */
  readonly selected: number;
  /** The run's seconds, by the clock. */
  readonly seconds: number;
  readonly suite: Suite;
}

/**
 * Select, prepare, run and judge: the whole gate, in process. The environment is read as every
 * plcvec runner reads it: the PLCVEC_* selection narrows `selection`, PLCVEC_KNOWN_FAILURES is the
 * default `known`, PLCVEC_WRITE_EXPECTATIONS receives the failures, PLCVEC_TIMEOUT bounds each vector.
 */
export function runVectors(impl: Implementation, options: RunOptions = {}): Report {
  const started = performance.now();
  timeoutSeconds(); // a malformed PLCVEC_TIMEOUT is refused before anything runs
  const suite = options.suite ?? loadSuite();
  const vectors = selectWithEnvironment(suite, options.selection);
  const followed = resolveChoices(suite, impl.choices);
  const knownFile = process.env["PLCVEC_KNOWN_FAILURES"];
  const known = options.known ?? (knownFile ? loadKnownFailures(knownFile) : undefined);
  const verdicts = guarded(vectors.map((v) => v.id), (index) => applyKnown(judge(prepare(vectors[index]!, followed), impl), known));
  const selected = verdicts.length;
  verdicts.push(...unknownIds(known, suite));
  const write = process.env["PLCVEC_WRITE_EXPECTATIONS"];
  if (write) writeExpectations(write, verdicts);
  return summarize(impl, verdicts, suite, followed, { ...options, selected, seconds: (performance.now() - started) / 1000 });
}

/** The report of a run's verdicts (`selected`: how many were selected; default all but stale unknown ids). */
export function summarize(
  impl: Pick<Implementation, "name" | "version" | "choices" | "cpuWrites">,
  verdicts: Verdict[],
  suite: Suite,
  followed: Followed,
  options: Pick<RunOptions, "allowEmpty" | "maxSkipped"> & { readonly selected?: number; readonly seconds?: number } = {},
): Report {
  const counts: Record<Status, number> = { pass: 0, fail: 0, error: 0, skip: 0, xfail: 0, stale: 0 };
  for (const r of verdicts) counts[r.status] += 1;
  const runProblems: string[] = [];
  const total = verdicts.length;
  if (total === 0 && !options.allowEmpty) runProblems.push("the selection holds no vector (allowEmpty to accept that)");
  if (total > 0 && counts.pass + counts.xfail === 0 && counts.skip > 0 && !options.allowEmpty) {
    runProblems.push(`nothing passed: all ${counts.skip} selected vectors were skipped`);
  }
  const limit = skipLimit(options.maxSkipped, total);
  if (limit !== undefined && counts.skip > limit) {
    runProblems.push(`${counts.skip} vectors skipped, more than the ${String(options.maxSkipped)} allowed`);
  }
  const failed = verdicts.some((r) => FAILING.has(r.status));
  const families = new Set(verdicts.flatMap((v) => suite.byId.get(v.id)?.family ?? []));
  const interpretations = new Map(
    [...interpretationsOf(suite, families.size ? families : undefined)].map(([id, info]) => [id, info.alternatives] as const),
  );
  return {
    implementation: impl.version ? `${impl.name} ${impl.version}` : impl.name,
    verdicts,
    counts,
    runProblems,
    passed: !failed && runProblems.length === 0,
    choices: followed.choices,
    defaults: followed.defaults,
    declared: impl.choices ?? {},
    interpretations,
    cpuWrites: [...(impl.cpuWrites ?? [])].sort(),
    selected: options.selected ?? verdicts.filter((v) => !(v.status === "stale" && !suite.byId.has(v.id))).length,
    seconds: options.seconds ?? 0,
    suite,
  };
}

function skipLimit(max: RunOptions["maxSkipped"], total: number): number | undefined {
  if (max === undefined) return undefined;
  if (typeof max === "number") return max;
  const percent = Number(max.slice(0, -1));
  if (!Number.isFinite(percent) || percent < 0) throw new VerifyError(`maxSkipped ${JSON.stringify(max)}: a count or a percentage such as "5%"`);
  return Math.floor((total * percent) / 100);
}
