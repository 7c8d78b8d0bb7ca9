/**
 * Field-by-field comparison of what an implementation reported with what a vector expects.
 * Everything must match exactly, including the JSON type: `===` never takes 1 for true.
 */
import type { Expected } from "./expect.js";
import { holds } from "./expect.js";
import { MemoryStep } from "./memory.js";
import type { Devices, StepResult, Value } from "./types.js";

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

export function show(value: unknown): string {
  if (typeof value === "string" && value.startsWith("<")) return value;
  return JSON.stringify(value) ?? String(value);
}

export function problemLine(p: Problem): string {
  const where = p.step === undefined ? "" : `step ${p.step} `;
  if (p.step === undefined) return `${p.field}: expected ${String(p.expected)}, got ${String(p.actual)}`;
  let text = `${where}${p.field}: expected ${show(p.expected)}, got ${show(p.actual)}`;
  if (p.before !== undefined && p.expected === p.before) text += " (the step must leave it unchanged)";
  else if (p.before !== undefined) text += ` (before the step: ${show(p.before)})`;
  return text;
}

/** The problems of one vector's reported steps; an empty list means it passed. */
/** The problems of a vector that passed: one shared, frozen empty list. */
export const NO_PROBLEMS: readonly Problem[] = Object.freeze([]);

export function compare(expected: Expected, steps: readonly StepResult[]): readonly Problem[] {
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
    if (step instanceof MemoryStep && step.sameSlots(expected.layout, expected.image, i * expected.layout.names.length, expected.checked)) continue;
    // A step without `devices` (a spread or cloned MemoryStep, say) reports no device at all.
    let got: Devices = typeof step.devices === "object" && step.devices !== null ? step.devices : {};
    if (holds(got, expected, i)) continue;
    const want = expected.states[i]!;
    if (expected.scratch.size) {
      got = Object.fromEntries(Object.entries(got).filter(([k]) => !expected.scratch.has(k)));
    }
    const before = expected.befores[i]!;
    const names = [...new Set([...Object.keys(want), ...Object.keys(got)])].sort();
    for (const dev of names) {
      const w = Object.prototype.hasOwnProperty.call(want, dev) ? want[dev]! : NOT_IN_VECTOR;
      const g = Object.prototype.hasOwnProperty.call(got, dev) ? got[dev]! : NOT_REPORTED;
      if (w !== g) (problems ??= []).push({ step: i, field: dev, expected: w, actual: g, before: before[dev] });
    }
  }
  return problems ?? NO_PROBLEMS;
}
