/**
 * Plan and run: select, prepare, run and judge, the whole gate in process, and the run's
 * verdict as a whole (CONTRACT.md: a gate never passes by doing nothing).
 */
import { resolveChoices } from "./choices.js";
import { judge, prepare } from "./compare.js";
import { VerifyError } from "./errors.js";
import type { Implementation } from "./implementation.js";
import { applyKnown, unknownIds, type KnownFailures } from "./known.js";
import { select, type Selection } from "./selection.js";
import { loadSuite, type Suite } from "./suite.js";
import { FAILING, type Status, type Verdict } from "./verdict.js";
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
  /** The alternative followed for every interpretation, declared or default. */
  readonly choices: Readonly<Record<string, string>>;
  /** The devices the implementation declares its CPU writes. */
  readonly cpuWrites: readonly string[];
  readonly suite: Suite;
}

/** Select, prepare, run and judge: the whole gate, in process. */
export function runVectors(impl: Implementation, options: RunOptions = {}): Report {
  const suite = options.suite ?? loadSuite();
  const vectors = select(suite, options.selection);
  const followed = resolveChoices(suite, impl.choices);
  const verdicts = guarded(vectors.map((v) => v.id), (index) => applyKnown(judge(prepare(vectors[index]!, followed), impl), options.known));
  verdicts.push(...unknownIds(options.known, suite));
  return summarize(impl, verdicts, suite, followed.choices, options);
}

export function summarize(
  impl: Pick<Implementation, "name" | "cpuWrites">,
  verdicts: Verdict[],
  suite: Suite,
  choices: Readonly<Record<string, string>>,
  options: Pick<RunOptions, "allowEmpty" | "maxSkipped"> = {},
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
  return {
    implementation: impl.name,
    verdicts,
    counts,
    runProblems,
    passed: !failed && runProblems.length === 0,
    choices,
    cpuWrites: impl.cpuWrites ?? [],
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
