/**
 * What every family's reference machine shares: the device image, the declared alternatives
 * (each interpretation's default from the generated names, unless declared), and the words
 * read as "16-bit signed binary".
 */
import { type Alternative, type InterpretationId, INTERPRETATIONS, type Memory, type Operand, type StepInputs } from "../index.js";

export type Operands = Readonly<Record<string, Operand>>;

export interface Machine {
  /** LD/AND/OR forms give a contact result; TADD and HOUR do not. */
  readonly contact: boolean;
  execute(instruction: string, operands: Operands, step: StepInputs): boolean | undefined;
}

/** Every interpretation's followed alternative, under its id. */
export type Follows = { readonly [I in InterpretationId]: Alternative<I> };

const INTERPRETATION_IDS = Object.keys(INTERPRETATIONS) as InterpretationId[];
/** The records followsOf made: complete and frozen, each its own answer. */
const made = new WeakSet<object>();
let lastMade: Follows | undefined;

/**
 * Every interpretation's alternative: the declared one, or the suite's default. One frozen record
 * with the same keys in the same order every time, built whole by Object.fromEntries: V8 gives
 * every such record one shape, so that `follows["FX5-SM709-SCOPE"]` at a call site is a field read
 * at a fixed offset. A record it made is returned as it is (machineImplementation passes the same
 * one to every vector's machine, so making a machine builds nothing).
 */
export function followsOf(declared: Readonly<Record<string, string>>): Follows {
  if (declared === lastMade || made.has(declared)) return declared as Follows;
  const follows = Object.freeze(Object.fromEntries(INTERPRETATION_IDS.map((id) => [id, declared[id] ?? INTERPRETATIONS[id].default]))) as Follows;
  made.add(follows);
  lastMade = follows;
  return follows;
}

export abstract class BaseMachine implements Machine {
  abstract readonly contact: boolean;
  /**
   * The alternative followed for each interpretation, as declared when the machine is made. Read
   * by a literal id (`this.follows["FX5-SM709-SCOPE"]`), not through choice(): a read that names
   * its key is, once optimized, a load at a fixed offset; choice's one `follows[id]`, which sees
   * every id of every caller, stays a megamorphic lookup (V8's stub cache) at every execution.
   */
  protected readonly follows: Follows;

  constructor(
    protected readonly mem: Memory,
    declared: Readonly<Record<string, string>>,
  ) {
    this.follows = followsOf(declared);
  }

  /** The alternative followed for `id`: the declared one, or the suite's default. */
  protected choice<I extends InterpretationId>(id: I): Alternative<I> {
    return this.follows[id];
  }

  abstract execute(instruction: string, operands: Operands, step: StepInputs): boolean | undefined;
}

/** A word read as "16-bit signed binary". */
export function signed16(word: number): number {
  const w = word & 0xffff;
  return w & 0x8000 ? w - 0x10000 : w;
}

export function deviceOf(op: Operand | undefined, name: string): string {
  const device = (op as { readonly device?: unknown } | undefined)?.device;
  if (typeof device !== "string") throw new Error(`operand ${name} must be a device`);
  return device;
}

/** The six comparison conditions of the FX5 and CP1E pages, in the manuals' order. */
export const CONDITIONS: readonly string[] = ["=", "<>", ">", "<=", "<", ">="];

/** Whether `condition` holds for an ordering of the first operand against the second (-1, 0, 1). */
export function conditionHolds(condition: string, order: number): boolean {
  switch (condition) {
    case "=":
      return order === 0;
    case "<>":
      return order !== 0;
    case ">":
      return order > 0;
    case "<=":
      return order <= 0;
    case "<":
      return order < 0;
    case ">=":
      return order >= 0;
    default:
      throw new Error(`not a comparison condition: ${condition}`);
  }
}
