/**
 * A device image for an emulator that executes one instruction on its own memory (emulator.ts):
 * words and bits by address, the steps reported from it.
 */
import { inspect } from "node:util";

import { deviceOffset, InitialImage, layoutOf, parseAddress, type Layout } from "./layout.js";
import type { StepResult } from "./implementation.js";
import { SAME_SLOTS, type SlotStep } from "./layout.js";
import { initialImageOf } from "./request.js";
import type { Devices, Operand, Value, VectorRequest } from "./vector.js";

/** A device's value read as a word: a bit is 1 or 0, a device holding nothing reads 0. */
function asWord(v: Value | undefined): number {
  return typeof v === "number" ? v : v === true ? 1 : 0;
}

/**
 * A device image: word devices hold 0..65535, bit devices true/false.
 *
 * The devices the vector lists live in slots of an array (see layout.ts) that starts as the
 * prepared initial image; a device written that the vector does not list is kept apart, so that
 * a snapshot reports it and the runner can call it a write outside the vector.
 */
export class Memory {
  /** Points of each device type, e.g. {D: 8000} means D0..D7999. */
  readonly sizes: Readonly<Record<string, number>>;
  private readonly layout: Layout;
  private readonly slots: ReadonlyMap<string, number>;
  /**
   * Slot -> value; undefined while a device named only by a later step is not yet set or written.
   * Shared, read-only, with the prepared initial image or the last step reported until the next
   * write copies it: most vectors are one step, and many a step writes nothing.
   */
  private image: readonly (Value | undefined)[];
  private shared: boolean;
  /** Devices written or set that have no slot, in the order first written. */
  private others: Map<string, Value> | undefined;
  /** What inRange found for each base address under these sizes, shared by every image of them (see roomsOf). */
  private readonly rooms: Map<string, number> | undefined;

  /** From a vector's devices, or from a prepared initial image (Memory.forRequest). */
  constructor(devices: Devices | InitialImage, sizes: Readonly<Record<string, number>> = {}) {
    const initial = devices instanceof InitialImage ? devices : InitialImage.of(layoutOf(Object.keys(devices)), devices);
    this.layout = initial.layout;
    this.slots = initial.layout.slots;
    this.image = initial.values;
    this.shared = true;
    this.others = undefined;
    this.sizes = sizes;
    this.rooms = roomsOf(sizes);
  }

  /** The image a request starts from: its `initial.devices` with its `assumes.device_sizes`. */
  static forRequest(request: VectorRequest): Memory {
    return new Memory(initialImageOf(request), request.assumes.device_sizes);
  }

  /** The value a device holds, or undefined when it holds none (neither listed, set nor written). */
  value(address: string): Value | undefined {
    const slot = this.slots.get(address);
    return slot !== undefined ? this.image[slot] : this.others?.get(address);
  }

  /** A word (an unlisted device reads 0). */
  word(address: string): number {
    return asWord(this.value(address));
  }

  bit(address: string): boolean {
    const v = this.value(address);
    return v === true || (typeof v === "number" && v !== 0);
  }

  /** Store a value as it is. */
  private store(address: string, value: Value): void {
    const slot = this.slots.get(address);
    if (slot !== undefined) this.writable()[slot] = value;
    else (this.others ??= new Map()).set(address, value);
  }

  /** The image, copied first if it is shared. */
  private writable(): (Value | undefined)[] {
    if (this.shared) {
      this.image = this.image.slice();
      this.shared = false;
    }
    return this.image as (Value | undefined)[];
  }

  /** Write a word (stored as its raw 16 bits) or a bit. */
  write(address: string, value: Value): void {
    this.store(address, typeof value === "number" ? value & 0xffff : value);
  }

  /** Apply values written by the outside world (a step's `set`). */
  set(values: Devices | undefined): void {
    if (values !== undefined) for (const k in values) this.store(k, values[k]!);
  }

  /** `D100`, 2 -> `D102`. */
  static offset(base: string, offset: number): string {
    return deviceOffset(base, offset);
  }

  words(base: string, count: number): number[] {
    const run = this.layout.run(base, count);
    const out = new Array<number>(count);
    for (let i = 0; i < count; i++) {
      const slot = run[i]!;
      out[i] = asWord(slot >= 0 ? this.image[slot] : this.others?.get(deviceOffset(base, i)));
    }
    return out;
  }

  writeWords(base: string, words: readonly number[]): void {
    const run = this.layout.run(base, words.length);
    for (let i = 0; i < words.length; i++) {
      const slot = run[i]!;
      if (slot >= 0) this.writable()[slot] = words[i]! & 0xffff;
      else this.write(deviceOffset(base, i), words[i]!);
    }
  }

  /** True when base .. base+count-1 all exist (a device type of unstated size is assumed to). */
  inRange(base: string, count: number): boolean {
    let room = this.rooms?.get(base);
    if (room === undefined) {
      room = roomOf(this.sizes, base);
      this.rooms?.set(base, room);
    }
    return count <= room;
  }

  /** A one-word operand: a constant (K/H) or the word in its device. */
  operand(op: Operand): number {
    return "constant" in op ? op.constant & 0xffff : this.word(op.device);
  }

  /** Every device that holds a value: the listed ones in the vector's order, then any other written. */
  snapshot(): Devices {
    return devicesOf(this.layout.names, this.image, this.others);
  }

  /**
   * What an implementation reports after a step: the contact result (undefined for TADD and HOUR)
   * and this image as it is now. The step keeps the slots (the next write copies them first);
   * `devices` is built from them when first read, so a runner that compares slots never builds an
   * object of device names.
   */
  report(result: boolean | undefined): StepResult {
    this.shared = true;
    return new MemoryStep(result, this.layout, this.image, this.others === undefined ? undefined : new Map(this.others));
  }
}

/**
 * How many points of its device type there are from `base` on: Infinity for a type of unstated
 * size, -Infinity for an address without a number (no count of points lies there).
 */
function roomOf(sizes: Readonly<Record<string, number>>, base: string): number {
  const p = parseAddress(base);
  if (p === null) return -Infinity;
  const size = sizes[p[0]];
  return size === undefined ? Infinity : size - p[1];
}

/** The rooms found under each frozen table of sizes (a prepared request's, shared by the vectors assuming the same). */
const roomsBySizes = new WeakMap<object, Map<string, number>>();
let lastSizes: object | undefined;
let lastRooms: Map<string, number> | undefined;

/**
 * Where inRange keeps what it finds under `sizes`: one map per frozen table, so that a range check
 * is one lookup by address instead of parsing it and reading the table by its device type (a
 * read keyed by every type there is, which V8 leaves megamorphic). None for a table that is not
 * frozen: its owner may still change it, and each check then reads it afresh.
 */
function roomsOf(sizes: Readonly<Record<string, number>>): Map<string, number> | undefined {
  if (sizes === lastSizes) return lastRooms;
  if (!Object.isFrozen(sizes)) return undefined;
  let rooms = roomsBySizes.get(sizes);
  if (rooms === undefined) {
    rooms = new Map();
    roomsBySizes.set(sizes, rooms);
  }
  lastSizes = sizes;
  lastRooms = rooms;
  return rooms;
}

function devicesOf(names: readonly string[], image: readonly (Value | undefined)[], others: ReadonlyMap<string, Value> | undefined): Devices {
  const out: Record<string, Value> = {};
  for (let i = 0; i < image.length; i++) {
    const v = image[i];
    if (v !== undefined) out[names[i]!] = v;
  }
  if (others !== undefined) for (const [k, v] of others) out[k] = v;
  return out;
}

/**
 * A step reported from a Memory. It reads like any StepResult (`devices` is built on first read
 * and kept, and JSON.stringify writes it), but a runner comparing against the same layout checks
 * its slots instead, as long as nobody has read, and so perhaps changed, `devices`. Spreading or
 * cloning one gives an object without `devices`, which a runner reports as every device missing.
 */
export class MemoryStep implements StepResult, SlotStep {
  declare readonly result?: boolean;
  #devices: Devices | undefined = undefined;

  constructor(
    result: boolean | undefined,
    private readonly layout: Layout,
    private readonly image: readonly (Value | undefined)[],
    private readonly others: ReadonlyMap<string, Value> | undefined,
  ) {
    if (result !== undefined) (this as { result?: boolean }).result = result;
  }

  get devices(): Devices {
    return (this.#devices ??= devicesOf(this.layout.names, this.image, this.others));
  }

  /**
   * True when this step's slots of `layout` equal `want` (from index `from` on) at every slot in `checked` (undefined on
   * both sides: a device neither listed yet nor written) and nothing outside the layout was
   * written. False whenever that cannot be said from the slots alone: `devices` was read, the
   * layout is another, or any value differs; the caller then compares `devices`.
   */
  [SAME_SLOTS](layout: Layout, want: readonly (Value | undefined)[], from: number, checked: readonly number[]): boolean {
    if (this.#devices !== undefined || layout !== this.layout || this.others !== undefined) return false;
    const image = this.image;
    for (let i = 0; i < checked.length; i++) {
      const slot = checked[i]!;
      if (image[slot] !== want[from + slot]) return false;
    }
    return true;
  }

  toJSON(): StepResult {
    return this.result === undefined ? { devices: this.devices } : { result: this.result, devices: this.devices };
  }

  [inspect.custom](): StepResult {
    return this.toJSON();
  }
}
