/**
 * What a vector expects of an implementation that follows given alternatives.
 *
 * A vector stores per step only the devices that changed, and the full state at the end. An
 * implementation reports the full state after every step, which is simpler for any emulator; so
 * the expected full state after each step is worked out here once, and checked against the
 * vector's own `final`, so that an inconsistent vector file is caught rather than trusted.
 */
import { PlcvecError } from "./errors.js";
import type { Devices, Outcome, StepExpect, Vector } from "./types.js";

export interface Expected {
  readonly id: string;
  /** Per step: the contact result, or undefined for instructions that give none. */
  readonly results: readonly (boolean | undefined)[];
  /** Per step: every listed device after the step, scratch left out. */
  readonly states: readonly Devices[];
  /** Per step: the state the step started from (after `set`), for messages. */
  readonly befores: readonly Devices[];
  readonly scratch: ReadonlySet<string>;
  readonly outcome: Outcome;
  /** The alternative applied for each interpretation the vector depends on. */
  readonly applied: Readonly<Record<string, string>>;
}

export function expectedOf(
  vector: Vector,
  choices: Readonly<Record<string, string>>,
  defaults: Readonly<Record<string, string>>,
): Expected {
  const touched = vector.outcome.interpretations ?? [];
  const applied: Record<string, string> = {};
  for (const i of touched) applied[i] = choices[i] ?? (defaults[i] as string);
  let stepsExpect: readonly StepExpect[] = vector.steps.map((s) => s.expect);
  let final: Devices = vector.final.devices;
  let outcome: Outcome = touched.length ? (vector.outcome.default ?? vector.outcome) : vector.outcome;
  if (touched.some((i) => applied[i] !== defaults[i])) {
    const alt = (vector.alternatives ?? []).find((a) => touched.every((i) => a.choices[i] === applied[i]));
    if (alt === undefined) {
      const wanted = Object.entries(applied).map(([i, a]) => `${i}=${a}`).sort().join(", ");
      throw new PlcvecError(`vector ${vector.id}: no expectation for ${wanted} (the vector file lists no such alternative)`);
    }
    stepsExpect = alt.expect;
    final = alt.final.devices;
    outcome = alt.outcome;
  }
  const scratch = new Set(vector.initial.scratch ?? []);
  const state: Record<string, boolean | number> = {};
  for (const [k, v] of Object.entries(vector.initial.devices)) if (!scratch.has(k)) state[k] = v;
  const states: Devices[] = [];
  const befores: Devices[] = [];
  const results: (boolean | undefined)[] = [];
  vector.steps.forEach((step, i) => {
    for (const [k, v] of Object.entries(step.set ?? {})) if (!scratch.has(k)) state[k] = v;
    befores.push({ ...state });
    const expect = stepsExpect[i] as StepExpect;
    Object.assign(state, expect.devices);
    states.push({ ...state });
    results.push(expect.result);
  });
  if (!sameDevices(states[states.length - 1] as Devices, final)) {
    throw new PlcvecError(
      `vector ${vector.id}: the per-step changes do not add up to \`final\` (the vector file is inconsistent; regenerate it)`,
    );
  }
  return { id: vector.id, results, states, befores, scratch, outcome, applied };
}

/** Same devices, same values, same JSON types (true is not 1). */
export function sameDevices(a: Devices, b: Devices): boolean {
  // for..in over small plain objects, no key arrays: this runs once per step of every vector.
  let n = 0;
  for (const k in a) {
    if (a[k] !== b[k]) return false; // a value is never undefined, so a missing key differs too
    n++;
  }
  for (const _ in b) n--;
  return n === 0;
}
