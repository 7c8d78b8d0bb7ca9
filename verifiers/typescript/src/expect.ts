/**
 * What a vector expects of an implementation that follows given alternatives.
 *
 * A vector stores per step only the devices that changed, and the full state at the end. An
 * implementation reports the full state after every step, which is simpler for any emulator; so
 * the expected full state after each step is worked out here once, and checked against the
 * vector's own `final`, so that an inconsistent vector file is caught rather than trusted.
 */
import { VerifyError } from "./errors.js";
import { interned, internedResults } from "./intern.js";
import { layoutOf, type Layout } from "./layout.js";
import type { AlternativeExpectation, Devices, Outcome, StepExpect, Value, Vector } from "./vector.js";

export interface Expected {
  // What judging a passing vector reads comes first, so that it shares a cache line.
  /** Per step: the contact result, or undefined for instructions that give none. */
  readonly results: readonly (boolean | undefined)[];
  /** The vector's devices as slots (see layout.ts). */
  readonly layout: Layout;
  /** The value expected in each slot after each step, step after step (undefined: not listed yet). */
  readonly image: readonly (Value | undefined)[];
  /** The slots compared: all but scratch and the unjudged devices. */
  readonly checked: readonly number[];
  readonly scratch: ReadonlySet<string>;
  /** Never compared: scratch, and the devices the alternatives followed leave unjudged. */
  readonly ignored: ReadonlySet<string>;
  /** Interpretation -> the devices its followed alternative leaves unjudged (sorted lists; empty: none). */
  readonly unjudged: Readonly<Record<string, readonly string[]>>;
  /** The alternative applied for each interpretation the vector depends on. */
  readonly applied: Readonly<Record<string, string>>;
  readonly id: string;
  /** Per step: every listed device after the step, scratch and unjudged devices left out. */
  readonly states: readonly Devices[];
  /** Per step: the state the step started from (after `set`; an unjudged device keeps its value), for messages. */
  readonly befores: readonly Devices[];
  /** Per step: its `set` (scratch left out), or undefined: what the implementation held before a step is its own report with this written over it. */
  readonly sets: readonly (Devices | undefined)[];
  readonly outcome: Outcome;
}

const NO_SCRATCH: ReadonlySet<string> = new Set();
const NONE_APPLIED: Readonly<Record<string, string>> = Object.freeze({});
const NONE_UNJUDGED: Readonly<Record<string, readonly string[]>> = Object.freeze({});

/** The slots of a layout compared: all but scratch (one list per layout and scratch list). */
function checkedSlots(layout: Layout, scratch: readonly string[]): readonly number[] {
  let byScratch = checkedByLayout.get(layout);
  if (byScratch === undefined) checkedByLayout.set(layout, (byScratch = new Map()));
  const key = scratch.join("\n");
  let checked = byScratch.get(key);
  if (checked === undefined) {
    checked = [...layout.names.keys()].filter((slot) => !scratch.includes(layout.names[slot]!));
    byScratch.set(key, checked);
  }
  return checked;
}

const checkedByLayout = new WeakMap<Layout, Map<string, readonly number[]>>();

/** The expectation a vector gives for `applied`: its own steps for the defaults, else the matching alternatives entry. */
function entryFor(vector: Vector, touched: readonly string[], applied: Readonly<Record<string, string>>, defaults: Readonly<Record<string, string>>): AlternativeExpectation | undefined {
  if (!touched.some((i) => applied[i] !== defaults[i])) return undefined;
  const alt = (vector.alternatives ?? []).find((a) => touched.every((i) => a.choices[i] === applied[i]));
  if (alt === undefined) {
    const wanted = Object.entries(applied).map(([i, a]) => `${i}=${a}`).sort().join(", ");
    throw new VerifyError(`vector ${vector.id}: no expectation for ${wanted} (the vector file lists no such alternative)`);
  }
  return alt;
}

/** The state after each step and before it (after `set`), never holding scratch; `states` without the unjudged devices either. */
function statesOf(vector: Vector, stepsExpect: readonly StepExpect[], scratch: ReadonlySet<string>, unjudged: ReadonlySet<string>) {
  const state: Record<string, boolean | number> = {};
  for (const [k, v] of Object.entries(vector.initial.devices)) if (!scratch.has(k)) state[k] = v;
  const states: Devices[] = [];
  const befores: Devices[] = [];
  const sets: (Devices | undefined)[] = [];
  const results: (boolean | undefined)[] = [];
  vector.steps.forEach((step, i) => {
    const set: Record<string, boolean | number> = {};
    for (const [k, v] of Object.entries(step.set ?? {})) if (!scratch.has(k)) state[k] = set[k] = v;
    sets.push(step.set === undefined ? undefined : set);
    befores.push({ ...state });
    const expect = stepsExpect[i] as StepExpect;
    Object.assign(state, expect.devices);
    states.push(unjudged.size === 0 ? { ...state } : Object.fromEntries(Object.entries(state).filter(([d]) => !unjudged.has(d))));
    results.push(expect.result);
  });
  return { states, befores, sets, results };
}

export function expectedOf(
  vector: Vector,
  choices: Readonly<Record<string, string>>,
  defaults: Readonly<Record<string, string>>,
): Expected {
  const touched = vector.outcome.interpretations ?? [];
  const applied: Record<string, string> = {};
  for (const i of touched) applied[i] = choices[i] ?? (defaults[i] as string);
  const alt = entryFor(vector, touched, applied, defaults);
  const outcome: Outcome = alt?.outcome ?? (touched.length ? (vector.outcome.default ?? vector.outcome) : vector.outcome);
  const final: Devices = alt?.final.devices ?? vector.final.devices;
  const scratch = new Set(vector.initial.scratch ?? []);
  const unjudged = alt?.unjudged ?? NONE_UNJUDGED;
  const unjudgedSet = new Set(Object.values(unjudged).flat());
  const { states, befores, sets, results } = statesOf(vector, alt?.expect ?? vector.steps.map((s) => s.expect), scratch, unjudgedSet);
  if (!sameDevices(states[states.length - 1] as Devices, final)) {
    throw new VerifyError(
      `vector ${vector.id}: the per-step changes do not add up to \`final\` (the vector file is inconsistent; regenerate it)`,
    );
  }
  const layout = expectedLayout(vector);
  const has = Object.prototype.hasOwnProperty;
  const image: (Value | undefined)[] = [];
  for (const state of states) for (const name of layout.names) image.push(has.call(state, name) ? state[name] : undefined);
  const ignored = unjudgedSet.size === 0 ? scratch : new Set([...scratch, ...unjudgedSet]);
  return {
    results: internedResults(results),
    layout,
    image,
    checked: checkedSlots(layout, [...ignored]),
    scratch: scratch.size === 0 ? NO_SCRATCH : scratch,
    ignored: ignored.size === 0 ? NO_SCRATCH : ignored,
    unjudged,
    applied: touched.length === 0 ? NONE_APPLIED : interned(applied),
    id: vector.id,
    states,
    befores,
    sets,
    outcome,
  };
}

/**
 * Every device a vector names, initial state first: the slots of its device image. Devices named
 * only by a later step, an alternative or `final` get a slot too, so that one layout serves the
 * request and every expectation of the vector.
 */
export function expectedLayout(vector: Vector): Layout {
  let layout = layouts.get(vector);
  if (layout === undefined) {
    layout = layoutOf(namedDevices(vector), true);
    layouts.set(vector, layout);
  }
  return layout;
}

/** Worked out once per vector: the request and each expectation of it share it. */
const layouts = new WeakMap<Vector, Layout>();

/** Each device the vector names, once, in the order first named (a list: a vector names a dozen or so). */
function namedDevices(vector: Vector): string[] {
  const names = Object.keys(vector.initial.devices);
  const add = (devices: Devices | undefined): void => {
    if (devices !== undefined) for (const name of Object.keys(devices)) if (!names.includes(name)) names.push(name);
  };
  for (const name of vector.initial.scratch ?? []) if (!names.includes(name)) names.push(name);
  for (const step of vector.steps) {
    add(step.set);
    add(step.expect.devices);
  }
  for (const alt of vector.alternatives ?? []) for (const e of alt.expect) add(e.devices);
  add(vector.final.devices);
  return names;
}

/**
 * Whether `got` holds exactly the devices expected after step `step` (the slots of `expected.image`
 * for that step, scratch and unjudged devices left out), with the same values and JSON types (true is not 1). This runs
 * once per step of every vector an implementation reports as plain objects: no key arrays, no
 * allocation.
 */
export function holds(got: Devices, expected: Expected, step: number): boolean {
  const { layout, image, checked, ignored } = expected;
  const names = layout.names;
  const from = step * names.length;
  let listed = 0;
  for (let i = 0; i < checked.length; i++) {
    const slot = checked[i]!;
    const want = image[from + slot];
    if (got[names[slot]!] !== want) return false; // a device not listed yet must be absent: undefined both sides
    if (want !== undefined) listed++;
  }
  let n = 0;
  if (ignored.size === 0) for (const _ in got) n++;
  else for (const k in got) if (!ignored.has(k)) n++;
  return n === listed;
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
