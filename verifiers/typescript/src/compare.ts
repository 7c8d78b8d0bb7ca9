/**
 * Judging: what an implementation reported, field by field, against what a vector expects.
 * Everything must match exactly, including the JSON type: `===` never takes 1 for true.
 */
import type { Followed } from "./choices.js";
import { expectedOf, holds, type Expected } from "./expect.js";
import type { Implementation, RunOutcome, StepResult } from "./implementation.js";
import { SAME_SLOTS, type SlotStep } from "./layout.js";
import {
  ERROR,
  FAIL,
  NO_PROBLEMS,
  NOT_IN_VECTOR,
  NOT_REPORTED,
  PASS,
  SKIP,
  type Problem,
  type Status,
  type Verdict,
} from "./verdict.js";
import { requestOf } from "./request.js";
import type { Devices, Vector, VectorRequest } from "./vector.js";

const NO_CPU_WRITES: ReadonlySet<string> = new Set();
const byCodePoint = (a: string, b: string): number => (a < b ? -1 : a > b ? 1 : 0);

/**
 * What the implementation held before step `i`: what the vector gave it for step 0; its own report
 * of the previous step with this step's `set` written over it after that.
 */
function heldBefore(expected: Expected, steps: readonly StepResult[], i: number): Devices {
  if (i === 0) return expected.befores[0]!;
  const previous = steps[i - 1]!.devices;
  const set = expected.sets[i];
  return { ...(typeof previous === "object" && previous !== null ? previous : {}), ...set };
}

/**
 * The problems of one vector's reported steps; an empty list means it passed. A device in
 * `cpuWrites` that the vector does not list is the CPU's own write, not a stray one.
 */
export function compare(expected: Expected, steps: readonly StepResult[], cpuWrites: ReadonlySet<string> = NO_CPU_WRITES): readonly Problem[] {
  return problemsOf(expected, steps, cpuWrites, undefined);
}

/**
 * compare, given the CPU's writes or the implementation that declares them (looked up only when a
 * step differs: judging a vector that passes, as most do, then looks nothing up per vector).
 */
function problemsOf(
  expected: Expected,
  steps: readonly StepResult[],
  given: ReadonlySet<string> | undefined,
  impl: Implementation | undefined,
): readonly Problem[] {
  const count = expected.results.length;
  if (steps.length !== count) {
    return [{ step: undefined, field: "steps", expected: `${count} steps`, actual: `${steps.length} steps` }];
  }
  let problems: Problem[] | undefined; // made only for a vector that fails: most pass
  for (let i = 0; i < steps.length; i++) {
    const step = steps[i]!;
    const wantResult = expected.results[i];
    if (wantResult !== undefined && step.result !== wantResult) {
      (problems ??= []).push({ step: i, field: "result", expected: wantResult, actual: step.result ?? NOT_REPORTED });
    }
    // Most vectors pass: one pass of strict equality first, the field-by-field diff only on a mismatch.
    const sameSlots = (step as Partial<SlotStep>)[SAME_SLOTS];
    if (sameSlots !== undefined && sameSlots.call(step, expected.layout, expected.image, i * expected.layout.names.length, expected.checked)) continue;
    // A step without `devices` (a spread or cloned MemoryStep, say) reports no device at all.
    let got: Devices = typeof step.devices === "object" && step.devices !== null ? step.devices : {};
    if (holds(got, expected, i)) continue;
    const want = expected.states[i]!;
    const cpuWrites = given ?? (impl === undefined ? NO_CPU_WRITES : cpuWritesOf(impl));
    if (expected.ignored.size || cpuWrites.size) {
      // Scratch and unjudged devices are never compared; a declared CPU write outside the vector is no stray write.
      const has = Object.prototype.hasOwnProperty;
      got = Object.fromEntries(
        Object.entries(got).filter(([k]) => !expected.ignored.has(k) && (!cpuWrites.has(k) || has.call(want, k))),
      );
    }
    const before = expected.befores[i]!;
    const held = heldBefore(expected, steps, i);
    const has = Object.prototype.hasOwnProperty;
    const names = [...new Set([...Object.keys(want), ...Object.keys(got)])].sort(byCodePoint);
    for (const dev of names) {
      const w = has.call(want, dev) ? want[dev]! : NOT_IN_VECTOR;
      const g = has.call(got, dev) ? got[dev]! : NOT_REPORTED;
      if (w === g) continue;
      if (w === NOT_IN_VECTOR) (problems ??= []).push({ step: i, field: dev, expected: w, actual: g });
      else {
        const h = has.call(held, dev) ? held[dev]! : NOT_REPORTED;
        (problems ??= []).push({ step: i, field: dev, expected: w, actual: g, held: h, keep: has.call(before, dev) && before[dev] === w });
      }
    }
  }
  return problems ?? NO_PROBLEMS;
}

/** A prepared vector: its request and its expectation under the followed alternatives, worked out once. */
export interface Prepared {
  readonly vector: Vector;
  readonly request: VectorRequest;
  readonly expected: Expected;
  /** The vector's clauses, for its verdict. */
  readonly clauses: readonly string[];
}

export function prepare(vector: Vector, followed: Followed): Prepared;
/** @deprecated since 0.2.0, until 0.3.0: pass the `Followed` that `resolveChoices` gives. */
export function prepare(vector: Vector, choices: Readonly<Record<string, string>>, defaults: Readonly<Record<string, string>>): Prepared;
export function prepare(vector: Vector, followed: Followed | Readonly<Record<string, string>>, defaults?: Readonly<Record<string, string>>): Prepared {
  const { choices, defaults: all } = defaults === undefined ? (followed as Followed) : { choices: followed as Readonly<Record<string, string>>, defaults };
  return { vector, request: requestOf(vector), expected: expectedOf(vector, choices, all), clauses: vector.clauses };
}

/** The devices an implementation declares its CPU writes, as a set (one per implementation). */
export function cpuWritesOf(impl: Implementation): ReadonlySet<string> {
  let set = cpuWriteSets.get(impl);
  if (set === undefined) {
    set = impl.cpuWrites === undefined || impl.cpuWrites.length === 0 ? NO_CPU_WRITES : new Set(impl.cpuWrites);
    cpuWriteSets.set(impl, set);
  }
  return set;
}

const cpuWriteSets = new WeakMap<Implementation, ReadonlySet<string>>();

/**
 * Run one prepared vector through `impl` and judge it (known failures not yet applied). The answer
 * nearly every vector gets, steps, is judged here, any other by answered(): kept this short, judge
 * is small enough for V8 to inline into the loop that calls it.
 */
export function judge(p: Prepared, impl: Implementation): Verdict {
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
    return threw(p, impl, err);
  }
  if (typeof outcome !== "object" || outcome === null || !("steps" in outcome) || !Array.isArray(outcome.steps)) {
    return answered(p, impl, outcome);
  }
  const problems = problemsOf(expected, outcome.steps, undefined, impl);
  if (problems.length === 0) return verdict(p, PASS, problems);
  return { ...verdict(p, FAIL, problems), answer: outcome.steps };
}

/** The verdict on an implementation that threw. */
function threw(p: Prepared, impl: Implementation, err: unknown): Verdict {
  if (!(err instanceof Error)) return verdict(p, ERROR, NO_PROBLEMS, `${impl.name} threw ${String(err)}`);
  const frame = ownFrame(err);
  return verdict(p, ERROR, NO_PROBLEMS, `${impl.name} threw ${err.name}: ${err.message}${frame === undefined ? "" : ` (${frame})`}`);
}

/** The verdict on an answer other than a list of steps. */
function answered(p: Prepared, impl: Implementation, outcome: RunOutcome): Verdict {
  if (typeof outcome !== "object" || outcome === null) {
    return verdict(p, ERROR, NO_PROBLEMS, `${impl.name} answered ${String(outcome)}, not {steps}, {skip} or {error}`);
  }
  if ("steps" in outcome) return verdict(p, ERROR, NO_PROBLEMS, `${impl.name} answered steps that are not a list`);
  if ("skip" in outcome) return verdict(p, SKIP, NO_PROBLEMS, String(outcome.skip));
  if ("error" in outcome) return verdict(p, ERROR, NO_PROBLEMS, `the implementation reported an error: ${String(outcome.error)}`);
  return verdict(p, ERROR, NO_PROBLEMS, `${impl.name} answered neither steps, skip nor error`);
}

const FRAME = /\(?((?:file:\/\/)?[^\s()]+):(\d+):\d+\)?$/;

/**
 * Where an error was thrown, as `file:line`: the first frame of its stack in the implementation's
 * own code, past Node's internals and installed packages (a date library's line says nothing).
 */
function ownFrame(err: Error): string | undefined {
  for (const line of (err.stack ?? "").split("\n").slice(1)) {
    const m = FRAME.exec(line.trim());
    if (m === null || m[1]!.startsWith("node:") || m[1]!.includes("/node_modules/")) continue;
    return `${m[1]!.slice(m[1]!.lastIndexOf("/") + 1)}:${m[2]}`;
  }
  return undefined;
}

function verdict(p: Prepared, status: Status, problems: readonly Problem[], message?: string): Verdict {
  const result = { id: p.request.id, status, problems, judgedBy: p.expected.applied, clauses: p.clauses };
  return message === undefined ? result : { ...result, message };
}
