/**
 * Running vectors against an implementation and judging them, exactly as CONTRACT.md says.
 */
import { compare, NO_PROBLEMS, problemLine, type Problem } from "./compare.js";
import { PlcvecError } from "./errors.js";
import { expectedOf, type Expected } from "./expect.js";
import { requestOf } from "./request.js";
import type { KnownFailures } from "./known.js";
import { interpretationsOf, loadSuite, type Suite } from "./load.js";
import { select, type Selection } from "./select.js";
import type { RunOutcome, Vector, VectorRequest } from "./types.js";

export { requestOf };

/** An implementation at the level of the contract: one vector's initial state in, the state after each step out. */
export interface Implementation {
  /** Shown in reports. */
  readonly name: string;
  /** The instructions it implements; vectors of any other are skipped. Default: all of them. */
  readonly instructions?: readonly string[];
  /** The alternative it follows for each interpretation (INTERPRETATIONS); undeclared ones take the default. */
  readonly choices?: Readonly<Record<string, string>>;
  /**
   * Run one vector from its own initial state (nothing carries over from another vector): apply
   * each step's `set`, execute, and report every listed device (and any other written) after it,
   * with the contact result for LD/AND/OR forms. Throwing counts as an error on that vector.
   */
  run(request: VectorRequest): RunOutcome;
}

export const PASS = "pass";
export const FAIL = "fail";
export const ERROR = "error";
export const SKIP = "skip";
export const XFAIL = "xfail";
export const STALE = "stale";
export type Status = typeof PASS | typeof FAIL | typeof ERROR | typeof SKIP | typeof XFAIL | typeof STALE;
const FAILING: ReadonlySet<Status> = new Set([FAIL, ERROR, STALE]);

export interface VectorResult {
  readonly id: string;
  readonly status: Status;
  readonly problems: readonly Problem[];
  /** Why it was skipped or errored, or the known failure's reason. */
  readonly message?: string;
  /** The alternatives it was judged by (only the interpretations the vector depends on). */
  readonly applied: Readonly<Record<string, string>>;
  readonly clauses: readonly string[];
}

/** The declared alternatives checked against the suite, with every interpretation's default. */
export function resolveChoices(
  suite: Suite,
  declared: Readonly<Record<string, string>> = {},
): { choices: Record<string, string>; defaults: Record<string, string> } {
  const interps = interpretationsOf(suite);
  const defaults: Record<string, string> = {};
  for (const [id, i] of interps) defaults[id] = i.default;
  for (const [id, alt] of Object.entries(declared)) {
    const interp = interps.get(id);
    if (interp === undefined) {
      throw new PlcvecError(`declared interpretation ${JSON.stringify(id)} is not in the suite (known: ${[...interps.keys()].sort().join(", ")})`);
    }
    if (!interp.alternatives.includes(alt)) {
      throw new PlcvecError(`${id}=${alt}: no such alternative (known: ${interp.alternatives.join(", ")})`);
    }
  }
  return { choices: { ...defaults, ...declared }, defaults };
}

/** A prepared vector: its request and its expectation under the declared alternatives, worked out once. */
export interface Prepared {
  readonly vector: Vector;
  readonly request: VectorRequest;
  readonly expected: Expected;
  /** The vector's clauses, for its result. */
  readonly clauses: readonly string[];
}

export function prepare(vector: Vector, choices: Readonly<Record<string, string>>, defaults: Readonly<Record<string, string>>): Prepared {
  return { vector, request: requestOf(vector), expected: expectedOf(vector, choices, defaults), clauses: vector.clauses };
}

/** Run one prepared vector through `impl` and judge it (known failures not yet applied). */
export function judge(p: Prepared, impl: Implementation): VectorResult {
  // The vector itself is not read here: what judging needs of it is on the request and the
  // expectation, and a large object read for one field costs a cache miss per vector.
  const { request, expected } = p;
  if (impl.instructions !== undefined && !impl.instructions.includes(request.instruction)) {
    return verdict(p, SKIP, NO_PROBLEMS, `${request.instruction} is not implemented`);
  }
  let outcome: RunOutcome;
  try {
    outcome = impl.run(request);
  } catch (err) {
    return verdict(p, ERROR, NO_PROBLEMS, `${impl.name} threw ${err instanceof Error ? `${err.name}: ${err.message}` : String(err)}`);
  }
  if ("steps" in outcome) {
    const problems = compare(expected, outcome.steps);
    return verdict(p, problems.length ? FAIL : PASS, problems);
  }
  if ("skip" in outcome) return verdict(p, SKIP, NO_PROBLEMS, outcome.skip);
  return verdict(p, ERROR, NO_PROBLEMS, outcome.error);
}

function verdict(p: Prepared, status: Status, problems: readonly Problem[], message?: string): VectorResult {
  const result = { id: p.request.id, status, problems, applied: p.expected.applied, clauses: p.clauses };
  return message === undefined ? result : { ...result, message };
}


/** Turn a listed failure into xfail and a listed pass into stale. */
export function applyKnown(result: VectorResult, known: KnownFailures | undefined): VectorResult {
  const entry = known?.get(result.id);
  if (entry === undefined) return result;
  if (result.status === FAIL || result.status === ERROR) return { ...result, status: XFAIL, message: `known failure (${entry.where}): ${entry.reason}` };
  if (result.status === PASS) {
    return { ...result, status: STALE, message: `listed as a known failure at ${entry.where} but passes: remove it from the list` };
  }
  return result;
}

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
  readonly results: readonly VectorResult[];
  readonly counts: Readonly<Record<Status, number>>;
  /** Why the run as a whole fails though no vector did (empty selection, all skipped, too many skipped). */
  readonly runProblems: readonly string[];
  readonly passed: boolean;
  /** The alternative followed for every interpretation, declared or default. */
  readonly choices: Readonly<Record<string, string>>;
  readonly suite: Suite;
}

/** Select, prepare, run and judge: the whole gate, in process. */
export function runVectors(impl: Implementation, options: RunOptions = {}): Report {
  const suite = options.suite ?? loadSuite();
  const vectors = select(suite, options.selection);
  const { choices, defaults } = resolveChoices(suite, impl.choices);
  const results = vectors.map((v) => applyKnown(judge(prepare(v, choices, defaults), impl), options.known));
  // A listed id the suite does not have is stale; one merely not selected (another shard) is not.
  for (const [id, entry] of options.known ?? []) {
    if (!suite.byId.has(id)) {
      results.push({ id, status: STALE, problems: [], message: `listed at ${entry.where}, but the suite has no such vector`, applied: {}, clauses: [] });
    }
  }
  return summarize(impl.name, results, suite, choices, options);
}

export function summarize(
  implementation: string,
  results: readonly VectorResult[],
  suite: Suite,
  choices: Readonly<Record<string, string>>,
  options: Pick<RunOptions, "allowEmpty" | "maxSkipped"> = {},
): Report {
  const counts: Record<Status, number> = { pass: 0, fail: 0, error: 0, skip: 0, xfail: 0, stale: 0 };
  for (const r of results) counts[r.status] += 1;
  const runProblems: string[] = [];
  const total = results.length;
  if (total === 0 && !options.allowEmpty) runProblems.push("the selection holds no vector (allowEmpty to accept that)");
  if (total > 0 && counts.pass + counts.xfail === 0 && counts.skip > 0 && !options.allowEmpty) {
    runProblems.push(`nothing passed: all ${counts.skip} selected vectors were skipped`);
  }
  const limit = skipLimit(options.maxSkipped, total);
  if (limit !== undefined && counts.skip > limit) {
    runProblems.push(`${counts.skip} vectors skipped, more than the ${String(options.maxSkipped)} allowed`);
  }
  const failed = results.some((r) => FAILING.has(r.status));
  return { implementation, results, counts, runProblems, passed: !failed && runProblems.length === 0, choices, suite };
}

function skipLimit(max: RunOptions["maxSkipped"], total: number): number | undefined {
  if (max === undefined) return undefined;
  if (typeof max === "number") return max;
  const percent = Number(max.slice(0, -1));
  if (!Number.isFinite(percent) || percent < 0) throw new PlcvecError(`maxSkipped ${JSON.stringify(max)}: a count or a percentage such as "5%"`);
  return Math.floor((total * percent) / 100);
}

/** A failing vector as a reader wants it: id, each differing field, the alternatives judged by, the clauses. */
export function describeResult(r: VectorResult): string {
  const lines = [`${r.status.toUpperCase()} ${r.id}`];
  if (r.message !== undefined) lines.push(`  ${r.message}`);
  for (const p of r.problems) lines.push(`  ${problemLine(p)}`);
  const applied = Object.entries(r.applied);
  if (applied.length) lines.push(`  judged by: ${applied.map(([i, a]) => `${i}=${a}`).join(", ")}`);
  if (r.clauses.length) lines.push(`  clauses: ${r.clauses.join(", ")}`);
  return lines.join("\n");
}

/** The report as text: suite, choices, every failing vector, and the totals line. */
export function formatReport(report: Report): string {
  const s = report.suite;
  const lines = [
    `plcvec ${s.suiteVersion || "(unknown version)"}, schema ${s.schemaVersion}, spec ${s.specSha256.slice(0, 12)}, vectors from ${s.source}`,
    `implementation: ${report.implementation}`,
    `alternatives: ${Object.entries(report.choices).map(([i, a]) => `${i}=${a}`).join(", ")}`,
  ];
  for (const r of report.results) if (FAILING.has(r.status)) lines.push(describeResult(r));
  for (const p of report.runProblems) lines.push(`RUN FAILS: ${p}`);
  const c = report.counts;
  lines.push(`${c.pass} passed, ${c.fail + c.error + c.stale} failed, ${c.skip} skipped` +
    (c.xfail ? `, ${c.xfail} known failures` : "") + (c.error ? ` (${c.error} errors)` : "") + (c.stale ? ` (${c.stale} stale)` : ""));
  return lines.join("\n");
}
