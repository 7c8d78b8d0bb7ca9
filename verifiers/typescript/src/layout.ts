/**
 * Device names resolved to slots once, when a vector is prepared, so that running it looks up no
 * hash map for its initial state and builds its device image by copying an array.
 *
 * A layout is the list of devices a vector names, in the order a snapshot reports them. The golden
 * set holds a few dozen distinct lists among thousands of vectors, so layouts are interned: vectors
 * of the same shape share one, and with it its name lookups.
 */
import type { Devices, Value } from "./vector.js";

export class Layout {
  /** Slot -> device address. */
  readonly names: readonly string[];
  /** Device address -> slot. */
  readonly slots: ReadonlyMap<string, number>;

  /** Base address -> the slots of base, base+1, ... (-1: no slot), for reading and writing runs of words. */
  private readonly runs = new Map<string, number[]>();

  constructor(names: readonly string[]) {
    this.names = names;
    this.slots = new Map(names.map((name, slot) => [name, slot]));
  }

  /** The slots of `base` .. `base`+`count`-1, -1 where a device has none (resolved once per layout and base). */
  run(base: string, count: number): readonly number[] {
    let run = this.runs.get(base);
    if (run === undefined || run.length < count) {
      run = [];
      for (let i = 0; i < count; i++) run.push(this.slots.get(deviceOffset(base, i)) ?? -1);
      this.runs.set(base, run);
    }
    return run;
  }
}

const ADDRESS = /^([A-Za-z_]+?)(\d+)$/;

/** A numbered device address, parsed: `D100` is ["D", 100], `SM8020` is ["SM", 8020]. */
export type Address = readonly [kind: string, number: number];

/** Parsed device addresses, `D100` -> ["D", 100]: a program names few devices, so each is parsed once. */
const parsed = new Map<string, Address | null>();

/** `D100` -> ["D", 100]; null for an address without a number. */
export function parseAddress(address: string): Address | null {
  let p = parsed.get(address);
  if (p === undefined) {
    const m = ADDRESS.exec(address);
    p = m === null ? null : [m[1] as string, Number(m[2])];
    parsed.set(address, p);
  }
  return p;
}

/** `D100` -> ["D100", "D101", ...], filled as they are asked for. */
const following = new Map<string, string[]>();

/** `D100`, 2 -> `D102` (each name built once: a new string would be hashed afresh on every lookup). */
export function deviceOffset(base: string, offset: number): string {
  let names = following.get(base);
  if (names === undefined) {
    names = [base];
    following.set(base, names);
  }
  let name = names[offset];
  if (name === undefined) {
    const p = parseAddress(base);
    if (p === null) throw new Error(`${base} is not a numbered device`);
    name = names[offset] = `${p[0]}${p[1] + offset}`;
  }
  return name;
}

const interned = new Map<string, Layout>();

/** The layout of these device addresses (each once, in the order first given; `unique`: they already are). */
export function layoutOf(names: Iterable<string>, unique = false): Layout {
  const list = unique ? [...names] : [...new Set(names)];
  const key = list.join("\n"); // a device address never holds a newline (validate.ts)
  let layout = interned.get(key);
  if (layout === undefined) {
    layout = new Layout(list);
    interned.set(key, layout);
  }
  return layout;
}

/**
 * A device image's starting point: a layout and the value in each slot (undefined: not listed
 * yet). Kept in private fields, so that a class extending it (a prepared request, which is its
 * own initial image) shows only its own fields.
 */
export class InitialImage {
  readonly #layout: Layout;
  readonly #values: readonly (Value | undefined)[];

  constructor(layout: Layout, values: readonly (Value | undefined)[]) {
    this.#layout = layout;
    this.#values = values;
  }

  get layout(): Layout {
    return this.#layout;
  }

  get values(): readonly (Value | undefined)[] {
    return this.#values;
  }

  static of(layout: Layout, devices: Devices): InitialImage {
    const has = Object.prototype.hasOwnProperty;
    return new InitialImage(layout, layout.names.map((name) => (has.call(devices, name) ? devices[name] : undefined)));
  }
}

/**
 * The method of a step result that compares its own slots with an expectation's (a MemoryStep):
 * a symbol, so that comparing needs no import of the class that has it.
 */
export const SAME_SLOTS: unique symbol = Symbol("plcvec.sameSlots");

export interface SlotStep {
  /** True when the slots of `layout` equal `want` (from `from` on) at every slot in `checked`; false when unsure. */
  [SAME_SLOTS](layout: Layout, want: readonly (Value | undefined)[], from: number, checked: readonly number[]): boolean;
}
