/**
 * The thin helper for emulators that only want to implement "execute this instruction on my
 * memory": the loop over steps, the device image, `set`, and the report after each step are
 * done here, as CONTRACT.md says.
 */
import type { Implementation } from "./run.js";
import type { Devices, Operand, RunOutcome, StepInputs, Value, VectorRequest } from "./types.js";

const ADDRESS = /^([A-Za-z_]+?)(\d+)$/;

/** A device image: word devices hold 0..65535, bit devices true/false. */
export class Memory {
  readonly values: Map<string, Value>;
  /** Points of each device type, e.g. {D: 8000} means D0..D7999. */
  readonly sizes: Readonly<Record<string, number>>;

  constructor(devices: Devices, sizes: Readonly<Record<string, number>> = {}) {
    this.values = new Map(Object.entries(devices));
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

  /** `D100`, 2 -> `D102`. */
  static offset(base: string, offset: number): string {
    const m = ADDRESS.exec(base);
    if (m === null) throw new Error(`${base} is not a numbered device`);
    return `${m[1]}${Number(m[2]) + offset}`;
  }

  words(base: string, count: number): number[] {
    return Array.from({ length: count }, (_, i) => this.word(Memory.offset(base, i)));
  }

  writeWords(base: string, words: readonly number[]): void {
    words.forEach((w, i) => this.write(Memory.offset(base, i), w));
  }

  /** True when base .. base+count-1 all exist (a device type of unstated size is assumed to). */
  inRange(base: string, count: number): boolean {
    const m = ADDRESS.exec(base);
    if (m === null) return false;
    const size = this.sizes[m[1] as string];
    return size === undefined || Number(m[2]) + count <= size;
  }

  /** A one-word operand: a constant (K/H) or the word in its device. */
  operand(op: Operand): number {
    return "constant" in op ? op.constant & 0xffff : this.word(op.device);
  }

  snapshot(): Devices {
    return Object.fromEntries(this.values);
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
        for (const [k, v] of Object.entries(step.set ?? {})) memory.values.set(k, v);
        const result = impl.execute({ instruction: request.instruction, operands: request.initial.operands, memory, step, state });
        return result === undefined ? { devices: memory.snapshot() } : { result, devices: memory.snapshot() };
      });
      return { steps };
    },
  };
}
