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
import { setting, timeoutSeconds } from "./settings.js";
import { FAILING, STALE, STATUS_ORDER, type Status, type Verdict } from "./verdict.js";
import type { Vector } from "./vector.js";
import { guarded } from "./watchdog.js";

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
  /**
   * The exit status `plcvec verify` gives this run (CONTRACT.md): 0 passed; 1 a vector failed,
   * errored or is stale, or the run was cut short; 5 nothing tested (no vector selected, nothing
   * passed, too many skipped).
   */
  readonly exitCode: 0 | 1 | 5;
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
  /** The known-failures file as given, when there was one (the roll-up names it). */
  readonly knownFile?: string;
  /** @deprecated since 0.2.0: the name of `verdicts` in plcvec 0.1.0, kept until 0.3.0; read `verdicts`. */
  readonly results?: readonly Verdict[];
}

/** The exit status of a run that proves nothing or too little (CONTRACT.md, "Exit status"). */
const NOTHING_TESTED = 5;

/** What a run is made with, worked out before any vector runs (every set-up mistake is found here). */
export interface Plan {
  readonly suite: Suite;
  readonly vectors: readonly Vector[];
  readonly followed: Followed;
  readonly known: KnownFailures | undefined;
  /** The known-failures file as given (the path, or the variable's value), when one was. */
  readonly knownFile: string | undefined;
}

/**
 * The plan of a run of `impl`: the suite (`options.suite`, else PLCVEC_VECTORS or the packaged copy),
 * the vectors the code's selection and the PLCVEC_* selection pick, the alternatives followed, and the
 * known failures (`options.known`, else the file PLCVEC_KNOWN_FAILURES names). A malformed
 * PLCVEC_TIMEOUT is refused here too, before anything runs.
 */
export function planRun(impl: Implementation, options: RunOptions = {}): Plan {
  timeoutSeconds();
  const suite = options.suite ?? loadSuite();
  const vectors = selectWithEnvironment(suite, options.selection);
  const followed = resolveChoices(suite, impl.choices);
  const file = options.known === undefined ? setting("PLCVEC_KNOWN_FAILURES") : undefined;
  const known = options.known ?? (file !== undefined ? loadKnownFailures(file) : undefined);
  return { suite, vectors, followed, known, knownFile: file ?? knownFileOf(known) };
}

/** The verdict of vector `index` of the plan, known failures applied. */
export function runOne(plan: Plan, impl: Implementation, index: number): Verdict {
  return applyKnown(judge(prepare(plan.vectors[index]!, plan.followed), impl), plan.known);
}

/**
 * Select, prepare, run and judge: the whole gate, in process. The environment is read as every
 * plcvec runner reads it: the PLCVEC_* selection narrows `selection`, PLCVEC_KNOWN_FAILURES is the
 * default `known`, PLCVEC_WRITE_EXPECTATIONS receives the failures, PLCVEC_TIMEOUT bounds each vector.
 */
export function runVectors(impl: Implementation, options: RunOptions = {}): Report {
  const started = performance.now();
  const plan = planRun(impl, options);
  const verdicts = guarded(plan.vectors.map((v) => v.id), (index) => runOne(plan, impl, index));
  const selected = verdicts.length;
  verdicts.push(...unknownIds(plan.known, plan.suite));
  const write = setting("PLCVEC_WRITE_EXPECTATIONS");
  if (write !== undefined) writeExpectations(write, verdicts);
  return summarize(impl, verdicts, plan.suite, plan.followed, {
    ...options,
    selected,
    seconds: (performance.now() - started) / 1000,
    ...(plan.knownFile !== undefined ? { knownFile: plan.knownFile } : {}),
  });
}

/** Why a run without failures proves too little ("" when it is enough): CONTRACT.md's exit status 5. */
function shortfall(counts: Readonly<Record<Status, number>>, total: number, options: Pick<RunOptions, "allowEmpty" | "maxSkipped">): string[] {
  const allow = "(allowEmpty if this job means it)";
  if (total === 0) return options.allowEmpty ? [] : [`no vector selected: the selection matches nothing ${allow}`];
  const out: string[] = [];
  if (counts.pass === 0 && !options.allowEmpty) {
    const words: Partial<Record<Status, string>> = { skip: "skipped", xfail: "known failures" };
    const others = STATUS_ORDER.filter((s) => counts[s] > 0).map((s) => `${counts[s]} ${words[s] ?? s}`).join(", ");
    out.push(`nothing passed (${others}): the run proves nothing ${allow}`);
  }
  const limit = skipLimit(options.maxSkipped, total);
  if (limit !== undefined && counts.skip > limit) {
    out.push(`${counts.skip} of ${total} vectors skipped, more than maxSkipped ${String(options.maxSkipped)} allows`);
  }
  return out;
}

/** The report of a run's verdicts (`selected`: how many were selected; default all but stale unknown ids). */
export function summarize(
  impl: Pick<Implementation, "name" | "version" | "choices" | "cpuWrites">,
  verdicts: Verdict[],
  suite: Suite,
  followed: Followed,
  options: Pick<RunOptions, "allowEmpty" | "maxSkipped"> & { readonly selected?: number; readonly seconds?: number; readonly knownFile?: string } = {},
): Report {
  const counts: Record<Status, number> = { pass: 0, fail: 0, error: 0, skip: 0, xfail: 0, stale: 0 };
  for (const r of verdicts) counts[r.status] += 1;
  const selected = options.selected ?? verdicts.filter((v) => !(v.status === STALE && !suite.byId.has(v.id))).length;
  const runProblems = shortfall(counts, selected, options);
  const failed = verdicts.some((r) => FAILING.has(r.status));
  const families = new Set(verdicts.flatMap((v) => suite.byId.get(v.id)?.family ?? []));
  const interpretations = new Map(
    [...interpretationsOf(suite, families.size ? families : undefined)].map(([id, info]) => [id, info.alternatives] as const),
  );
  const report: Report = {
    implementation: impl.version ? `${impl.name} ${impl.version}` : impl.name,
    verdicts,
    counts,
    runProblems,
    passed: !failed && runProblems.length === 0,
    exitCode: failed ? 1 : runProblems.length ? NOTHING_TESTED : 0,
    choices: followed.choices,
    defaults: followed.defaults,
    declared: impl.choices ?? {},
    interpretations,
    cpuWrites: [...(impl.cpuWrites ?? [])].sort(),
    selected,
    seconds: options.seconds ?? 0,
    suite,
    ...(options.knownFile !== undefined ? { knownFile: options.knownFile } : {}),
  };
  return withDeprecatedResults(report);
}

/**
 * `results`, the name `verdicts` had in plcvec 0.1.0, kept as a getter that is not enumerable (a
 * spread or JSON of a report shows `verdicts` once): a script written for 0.1.0 still iterates it.
 */
function withDeprecatedResults(report: Report): Report {
  return Object.defineProperty(report, "results", { get: () => report.verdicts, enumerable: false, configurable: true });
}

/** The report failed as a whole for `runProblems` (a run the test runner's filter or an early exit cut short). */
export function reportWith(report: Report, runProblems: readonly string[], exitCode: 1 | 5): Report {
  return withDeprecatedResults({ ...report, passed: false, runProblems, exitCode: report.exitCode === 1 ? 1 : exitCode });
}

/** The known-failures file of a parsed list, from where its entries are listed (`file:line`). */
function knownFileOf(known: KnownFailures | undefined): string | undefined {
  const where = known?.values().next().value?.where;
  return where === undefined ? undefined : where.slice(0, where.lastIndexOf(":"));
}

function skipLimit(max: RunOptions["maxSkipped"], total: number): number | undefined {
  if (max === undefined) return undefined;
  if (typeof max === "number") return max;
  const percent = Number(max.slice(0, -1));
  if (!Number.isFinite(percent) || percent < 0) throw new VerifyError(`maxSkipped ${JSON.stringify(max)}: a count or a percentage such as "5%"`);
  return Math.floor((total * percent) / 100);
}
