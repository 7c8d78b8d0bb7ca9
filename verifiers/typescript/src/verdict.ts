/**
 * A vector's verdict: its status, the problems found in what the implementation reported, and the
 * failure block a reader gets for it, in the one text every plcvec runner prints
 * (verifiers/parity/TEXT.md, "The failure block" and "A field line").
 */
import { expectedOf, type Expected } from "./expect.js";
import type { StepResult } from "./implementation.js";
import type { Devices, StepInputs, Value, Vector } from "./vector.js";

export const PASS = "pass";
export const FAIL = "fail";
export const ERROR = "error";
export const SKIP = "skip";
export const XFAIL = "xfail";
export const STALE = "stale";
export type Status = typeof PASS | typeof FAIL | typeof ERROR | typeof SKIP | typeof XFAIL | typeof STALE;
/** The statuses in the order counts are shown (TEXT.md, "The summary lines"). */
export const STATUS_ORDER: readonly Status[] = [PASS, FAIL, ERROR, SKIP, XFAIL, STALE];
/** The statuses that fail a run. */
export const FAILING: ReadonlySet<Status> = new Set([FAIL, ERROR, STALE]);

export const NOT_REPORTED = "<not reported>";
export const NOT_IN_VECTOR = "<not in the vector>";

/** Field lines shown per failing vector. */
const SHOW_PROBLEMS = 12;
export const INDENT = "    ";

export interface Problem {
  /** The step, or undefined for the vector as a whole (the number of steps). */
  readonly step: number | undefined;
  /** "result", a device address, or "steps". */
  readonly field: string;
  readonly expected: Value | string;
  readonly actual: Value | string;
  /**
   * For a device the vector lists: the value the implementation held before the step (what the
   * vector gave it for step 0; its own report of the previous step, with this step's `set` over
   * it, after that), or NOT_REPORTED.
   */
  readonly held?: Value | string;
  /** The vector requires the step to leave the device as the vector had it before the step. */
  readonly keep?: boolean;
}

/** The problems of a vector that passed: one shared, frozen empty list. */
export const NO_PROBLEMS: readonly Problem[] = Object.freeze([]);

export interface Verdict {
  readonly id: string;
  readonly status: Status;
  readonly problems: readonly Problem[];
  /** Why it was skipped or errored, or the known failure's reason. */
  readonly message?: string;
  /** The alternatives its expectation follows (only the interpretations the vector depends on). */
  readonly judgedBy: Readonly<Record<string, string>>;
  readonly clauses: readonly string[];
  /** What the implementation answered, for a vector that failed: the inference judges it under other readings. */
  readonly answer?: readonly StepResult[];
}

/** A value as the failure text shows it: JSON's spelling (true, 13, "x"), or a <...> marker. */
export function show(value: unknown): string {
  if (value === NOT_REPORTED || value === NOT_IN_VECTOR) return value;
  // An integer as its digits; NaN and the infinities (which JSON cannot hold) by their names.
  if (typeof value === "number" && (Number.isInteger(value) || !Number.isFinite(value))) return String(value);
  return stableJson(value) ?? String(value);
}

function stableJson(value: unknown): string | undefined {
  if (typeof value !== "object" || value === null) return JSON.stringify(value);
  if (Array.isArray(value)) return `[${value.map((v) => stableJson(v) ?? "null").join(",")}]`;
  const record = value as Record<string, unknown>;
  return `{${Object.keys(record).sort().map((k) => `${JSON.stringify(k)}:${stableJson(record[k]) ?? "null"}`).join(",")}}`;
}

/** One problem as one line: `step 0 D30: expected 13, got 14 (before the step: 10)`. */
export function problemLine(p: Problem): string {
  if (p.step === undefined) return `${p.field}: expected ${String(p.expected)}, got ${String(p.actual)}`;
  const text = `step ${p.step} ${p.field}: expected ${show(p.expected)}, got ${show(p.actual)}`;
  if (p.held === undefined) return text;
  // "must leave it unchanged" only where the implementation wrote the device in this step: a
  // difference carried over from an earlier step shows the value it already held instead.
  const wrote = p.actual !== NOT_REPORTED && p.held !== p.actual;
  if (p.keep === true && wrote) {
    if (p.held === p.expected) return `${text} (the step must leave it unchanged)`;
    return `${text} (before the step: ${show(p.held)}; the step must leave it unchanged)`;
  }
  return `${text} (before the step: ${show(p.held)})`;
}

/** The followed alternative of every interpretation, and the defaults, for a verdict's context. */
export interface Reading {
  readonly followed: Readonly<Record<string, string>>;
  readonly defaults: Readonly<Record<string, string>>;
}

/**
 * The combinations of alternatives `vector` offers an expectation for: the defaults first (its own
 * `steps`), then each `alternatives` entry in file order (only the interpretations it touches).
 */
export function offered(vector: Vector, defaults: Readonly<Record<string, string>>): Record<string, string>[] {
  const touched = vector.outcome.interpretations ?? [];
  const combos: Record<string, string>[] = [Object.fromEntries(touched.map((i) => [i, defaults[i]!]))];
  for (const alt of vector.alternatives ?? []) {
    if (touched.every((i) => i in alt.choices)) combos.push(Object.fromEntries(touched.map((i) => [i, alt.choices[i]!])));
  }
  return combos;
}

/**
 * The interpretations that decide the differing fields: those of which another alternative (every
 * other interpretation as followed) expects something else of a field that differs.
 */
export function deciding(vector: Vector, problems: readonly Problem[], reading: Reading): string[] {
  const touched = [...(vector.outcome.interpretations ?? [])].sort();
  if (touched.length === 0 || problems.length === 0) return [];
  const { followed, defaults } = reading;
  const mine = expectedOf(vector, followed, defaults);
  const combos = offered(vector, defaults);
  const out: string[] = [];
  for (const interp of touched) {
    for (const combo of combos) {
      if (combo[interp] === followed[interp] || touched.some((i) => i !== interp && combo[i] !== followed[i])) continue;
      const other = expectedOf(vector, combo, defaults);
      if (problems.some((p) => differs(mine, other, p))) {
        out.push(interp);
        break;
      }
    }
  }
  return out;
}

function differs(mine: Expected, other: Expected, p: Problem): boolean {
  if (p.step === undefined) return false;
  if (p.field === "result") return mine.results[p.step] !== other.results[p.step];
  const has = Object.prototype.hasOwnProperty;
  const a = has.call(mine.states[p.step], p.field) ? mine.states[p.step]![p.field] : NOT_IN_VECTOR;
  const b = has.call(other.states[p.step], p.field) ? other.states[p.step]![p.field] : NOT_IN_VECTOR;
  return a !== b;
}

const INPUTS = ["clock", "rlo_in", "en", "input", "elapsed_ms"];
const DATE = ["year", "month", "day"];
const TIME = ["hour", "minute", "second"];
const byCodePoint = (a: string, b: string): number => (a < b ? -1 : a > b ? 1 : 0);

/** `2024/2/29`, `10:05:00`, or both with a space; other fields as ` name=value`, by name. */
export function clockText(clock: Readonly<Record<string, unknown>>): string {
  const date = DATE.filter((f) => f in clock).map((f) => show(clock[f])).join("/");
  const time = TIME.filter((f) => f in clock)
    .map((f, k) => {
      const v = clock[f];
      return k > 0 && typeof v === "number" && Number.isInteger(v) && v >= 0 ? String(v).padStart(2, "0") : show(v);
    })
    .join(":");
  const parts = [date, time].filter((p) => p !== "");
  for (const k of Object.keys(clock).sort(byCodePoint)) if (!DATE.includes(k) && !TIME.includes(k)) parts.push(`${k}=${show(clock[k])}`);
  return parts.join(" ");
}

/** A step's inputs: `clock=10:30:00, rlo_in=true, set D100=5 D101=0`, or `(none)`. */
export function inputsText(step: StepInputs & { readonly expect?: unknown }): string {
  const s = step as Readonly<Record<string, unknown>>;
  const parts: string[] = [];
  for (const key of INPUTS) {
    if (!(key in s)) continue;
    const v = s[key];
    parts.push(`${key}=${key === "clock" && typeof v === "object" && v !== null ? clockText(v as Record<string, unknown>) : show(v)}`);
  }
  for (const key of Object.keys(s).sort(byCodePoint)) if (!INPUTS.includes(key) && key !== "expect" && key !== "set") parts.push(`${key}=${show(s[key])}`);
  const set = step.set ?? {};
  const names = Object.keys(set).sort(byCodePoint);
  if (names.length) parts.push(`set ${names.map((d) => `${d}=${show(set[d])}`).join(" ")}`);
  return parts.join(", ") || "(none)";
}

const NUMBERED = /^([A-Za-z_]+)([0-9]+)$/;

function nextAddress(device: string): string | undefined {
  const m = NUMBERED.exec(device);
  return m === null ? undefined : `${m[1]}${Number(m[2]) + 1}`;
}

/** Each operand with the words it reads in `state`: `s1 D100=23 0 0`, `D2 M10=false`, `S1 constant 3600`, `D3 D300 (scratch)`. */
export function operandsText(vector: Vector, state: Devices): string {
  const operands = vector.initial.operands;
  const scratch = new Set(vector.initial.scratch ?? []);
  const starts = new Set(Object.values(operands).flatMap((o) => ("device" in o ? [o.device] : [])));
  const has = Object.prototype.hasOwnProperty;
  const parts: string[] = [];
  for (const name of Object.keys(operands).sort(byCodePoint)) {
    const operand = operands[name]!;
    if (!("device" in operand)) {
      parts.push(`${name} constant ${show(operand.constant)}`);
      continue;
    }
    const first = operand.device;
    if (scratch.has(first)) parts.push(`${name} ${first} (scratch)`);
    else if (!has.call(state, first)) parts.push(`${name} ${first} (not in the vector)`);
    else {
      const words: Value[] = [state[first]!];
      if (typeof words[0] !== "boolean") {
        let device = nextAddress(first);
        while (device !== undefined && has.call(state, device) && typeof state[device] !== "boolean" && !starts.has(device) && !scratch.has(device)) {
          words.push(state[device]!);
          device = nextAddress(device);
        }
      }
      parts.push(`${name} ${first}=${words.map(show).join(" ")}`);
    }
  }
  return parts.join(", ") || "(none)";
}

/**
 * The failure block of one verdict (TEXT.md): the status and id; the instruction and description;
 * the interpretations that decide a differing field; per step, its inputs and its operands' words
 * before the field lines; the message; the spec clauses. Without the vector (an id the suite does
 * not have), the status, id and message.
 */
export function describe(v: Verdict, vector?: Vector, reading?: Reading): string {
  const lines = [`${v.status.toUpperCase()} ${v.id}`];
  if (vector?.description) lines.push(`${INDENT}${vector.instruction}: ${vector.description}`);
  if (vector !== undefined && reading !== undefined && v.problems.length) {
    const judged = deciding(vector, v.problems, reading);
    if (judged.length) lines.push(`${INDENT}judged by: ${judged.map((i) => `${i}=${reading.followed[i]}`).join(", ")}`);
  }
  let expected = vector !== undefined && reading !== undefined && vector.alternatives?.some((a) => a.unjudged) ? expectedOf(vector, reading.followed, reading.defaults) : undefined;
  for (const id of Object.keys(expected?.unjudged ?? {}).sort(byCodePoint)) {
    lines.push(`${INDENT}not judged under ${id}=${reading!.followed[id]}: ${[...expected!.unjudged[id]!].sort(byCodePoint).join(", ")}`);
  }
  let stepShown: number | undefined;
  for (const p of v.problems.slice(0, SHOW_PROBLEMS)) {
    if (p.step !== undefined && p.step !== stepShown && vector !== undefined && reading !== undefined) {
      stepShown = p.step;
      expected ??= expectedOf(vector, reading.followed, reading.defaults);
      lines.push(`${INDENT}step ${p.step} inputs: ${inputsText(vector.steps[p.step]!)}`);
      lines.push(`${INDENT}step ${p.step} operands: ${operandsText(vector, expected.befores[p.step]!)}`);
    }
    lines.push(`${INDENT}${problemLine(p)}`);
  }
  if (v.problems.length > SHOW_PROBLEMS) lines.push(`${INDENT}... and ${v.problems.length - SHOW_PROBLEMS} more differences`);
  if (v.message) lines.push(`${INDENT}${v.message}`);
  const clauses = vector?.clauses ?? v.clauses;
  if (clauses.length) lines.push(`${INDENT}spec clauses: ${clauses.join(", ")}`);
  return lines.join("\n");
}
