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

export abstract class BaseMachine implements Machine {
  abstract readonly contact: boolean;

  constructor(
    protected readonly mem: Memory,
    private readonly declared: Readonly<Record<string, string>>,
  ) {}

  /** The alternative followed for `id`: the declared one, or the suite's default. */
  protected choice<I extends InterpretationId>(id: I): Alternative<I> {
    return (this.declared[id] ?? INTERPRETATIONS[id].default) as Alternative<I>;
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
