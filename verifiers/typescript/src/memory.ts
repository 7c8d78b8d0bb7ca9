/**
 * The thin helper for emulators that only want to implement "execute this instruction on my
 * memory": the loop over steps, the device image, `set`, and the report after each step are
 * done here, as CONTRACT.md says.
 */
import type { Implementation } from "./run.js";
import type { Devices, Operand, RunOutcome, StepInputs, Value, VectorRequest } from "./types.js";

const ADDRESS = /^([A-Za-z_]+?)(\d+)$/;

/** Parsed device addresses, `D100` -> ["D", 100]: a program names few devices, so each is parsed once. */
const parsed = new Map<string, readonly [string, number] | null>();

function parse(address: string): readonly [string, number] | null {
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

/** A device image: word devices hold 0..65535, bit devices true/false. */
export class Memory {
  /** Device address -> value. A Map: every vector names other devices, and objects of ever-new shapes would make every access megamorphic. */
  readonly values: Map<string, Value>;
  /** Points of each device type, e.g. {D: 8000} means D0..D7999. */
  readonly sizes: Readonly<Record<string, number>>;

  constructor(devices: Devices, sizes: Readonly<Record<string, number>> = {}) {
    this.values = new Map();
    for (const k in devices) this.values.set(k, devices[k]!);
    this.sizes = sizes;
  }

  /** A word (an unlisted device reads 0). */
  word(address: string): number {
    const v = this.values.get(address);
    return typeof v === "number" ? v : v === true ? 1 : 0;
  }

  bit(address: string): boolean {
    const v = this.values.get(address);
    return v === true || (typeof v === "number" && v !== 0);
  }

  /** Write a word (stored as its raw 16 bits) or a bit. */
  write(address: string, value: Value): void {
    this.values.set(address, typeof value === "number" ? value & 0xffff : value);
  }

  /** Apply values written by the outside world (a step's `set`). */
  set(values: Devices | undefined): void {
    if (values !== undefined) for (const k in values) this.values.set(k, values[k]!);
  }

  /** `D100`, 2 -> `D102` (each name built once: a new string would be hashed afresh on every lookup). */
  static offset(base: string, offset: number): string {
    let names = following.get(base);
    if (names === undefined) {
      names = [base];
      following.set(base, names);
    }
    let name = names[offset];
    if (name === undefined) {
      const p = parse(base);
      if (p === null) throw new Error(`${base} is not a numbered device`);
      name = names[offset] = `${p[0]}${p[1] + offset}`;
    }
    return name;
  }

  words(base: string, count: number): number[] {
    const out: number[] = [];
    for (let i = 0; i < count; i++) out.push(this.word(Memory.offset(base, i)));
    return out;
  }

  writeWords(base: string, words: readonly number[]): void {
    for (let i = 0; i < words.length; i++) this.write(Memory.offset(base, i), words[i]!);
  }

  /** True when base .. base+count-1 all exist (a device type of unstated size is assumed to). */
  inRange(base: string, count: number): boolean {
    const p = parse(base);
    if (p === null) return false;
    const size = this.sizes[p[0]];
    return size === undefined || p[1] + count <= size;
  }

  /** A one-word operand: a constant (K/H) or the word in its device. */
  operand(op: Operand): number {
    return "constant" in op ? op.constant & 0xffff : this.word(op.device);
  }

  snapshot(): Devices {
    const out: Record<string, Value> = {};
    for (const [k, v] of this.values) out[k] = v;
    return out;
  }
}

export interface Execution {
  readonly instruction: string;
  readonly operands: VectorRequest["initial"]["operands"];
  readonly memory: Memory;
  readonly step: StepInputs;
  /** Lives for one vector: state the instruction keeps between scans (TADDP's previous EN, a timer's fraction). */
  readonly state: Record<string, unknown>;
}

export interface MemoryImplementation {
  readonly name: string;
  readonly instructions?: readonly string[];
  readonly choices?: Readonly<Record<string, string>>;
  /** Execute the instruction once; return the contact result for LD/AND/OR forms, nothing otherwise. */
  execute(execution: Execution): boolean | undefined;
}

/** An Implementation from an `execute` on a device image. */
export function executeOnMemory(impl: MemoryImplementation): Implementation {
  return {
    name: impl.name,
    ...(impl.instructions !== undefined ? { instructions: impl.instructions } : {}),
    ...(impl.choices !== undefined ? { choices: impl.choices } : {}),
    run(request: VectorRequest): RunOutcome {
      const memory = new Memory(request.initial.devices, request.assumes.device_sizes);
      const state: Record<string, unknown> = {};
      const steps = request.steps.map((step) => {
        memory.set(step.set);
        const result = impl.execute({ instruction: request.instruction, operands: request.initial.operands, memory, step, state });
        return result === undefined ? { devices: memory.snapshot() } : { result, devices: memory.snapshot() };
      });
      return { steps };
    },
  };
}
