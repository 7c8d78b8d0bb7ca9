/**
 * A vector's verdict: its status, the problems found in what the implementation reported, and the
 * text a reader gets for it.
 */
import type { Value } from "./vector.js";

export const PASS = "pass";
export const FAIL = "fail";
export const ERROR = "error";
export const SKIP = "skip";
export const XFAIL = "xfail";
export const STALE = "stale";
export type Status = typeof PASS | typeof FAIL | typeof ERROR | typeof SKIP | typeof XFAIL | typeof STALE;
/** The statuses that fail a run. */
export const FAILING: ReadonlySet<Status> = new Set([FAIL, ERROR, STALE]);

export const NOT_REPORTED = "<not reported>";
export const NOT_IN_VECTOR = "<not in the vector>";

export interface Problem {
  /** The step, or undefined for the vector as a whole (the number of steps). */
  readonly step: number | undefined;
  /** "result", a device address, or "steps". */
  readonly field: string;
  readonly expected: Value | string;
  readonly actual: Value | string;
  /** The device's value before the step, when the field is a device. */
  readonly before?: Value | undefined;
}

/** The problems of a vector that passed: one shared, frozen empty list. */
export const NO_PROBLEMS: readonly Problem[] = Object.freeze([]);

export interface Verdict {
  readonly id: string;
  readonly status: Status;
  readonly problems: readonly Problem[];
  /** Why it was skipped or errored, or the known failure's reason. */
  readonly message?: string;
  /** The alternatives it was judged by (only the interpretations the vector depends on). */
  readonly judgedBy: Readonly<Record<string, string>>;
  readonly clauses: readonly string[];
}

export function show(value: unknown): string {
  if (typeof value === "string" && value.startsWith("<")) return value;
  return JSON.stringify(value) ?? String(value);
}

/** One problem as one line: `step 0 D30: expected 13, got 14 (before the step: 10)`. */
export function problemLine(p: Problem): string {
  if (p.step === undefined) return `${p.field}: expected ${String(p.expected)}, got ${String(p.actual)}`;
  let text = `step ${p.step} ${p.field}: expected ${show(p.expected)}, got ${show(p.actual)}`;
  if (p.before !== undefined && p.expected === p.before) text += " (the step must leave it unchanged)";
  else if (p.before !== undefined) text += ` (before the step: ${show(p.before)})`;
  return text;
}

/** A failing vector as a reader wants it: id, each differing field, the alternatives judged by, the clauses. */
export function describe(v: Verdict): string {
  const lines = [`${v.status.toUpperCase()} ${v.id}`];
  if (v.message !== undefined) lines.push(`  ${v.message}`);
  for (const p of v.problems) lines.push(`  ${problemLine(p)}`);
  const judgedBy = Object.entries(v.judgedBy);
  if (judgedBy.length) lines.push(`  judged by: ${judgedBy.map(([i, a]) => `${i}=${a}`).join(", ")}`);
  if (v.clauses.length) lines.push(`  clauses: ${v.clauses.join(", ")}`);
  return lines.join("\n");
}
