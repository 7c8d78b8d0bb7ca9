/** Omron SYSMAC CP1E: LD/AND/OR =DT, <>DT, <DT, <=DT, >DT, >=DT, from cp1e-time-compare-DT.txt. */
import { INSTRUCTION_INFO, type InstructionInfo, type StepInputs } from "../index.js";
import { BaseMachine, conditionHolds, deviceOf, type Operands } from "./machine.js";

const ERROR_FLAG = "P_ER";
const FLAGS: readonly (readonly [string, string])[] = [
  ["=", "P_EQ"],
  ["<>", "P_NE"],
  ["<", "P_LT"],
  ["<=", "P_LE"],
  [">", "P_GT"],
  [">=", "P_GE"],
];

export interface BcdField {
  readonly offset: number;
  /** 0: bits 00-07, 1: bits 08-15. */
  readonly byte: number;
  readonly name: string;
  readonly min: number;
  readonly max: number;
  /** The bit of C that masks it. */
  readonly mask: number;
}

// "A351.00-07 Second, A351.08-15 Minute, A352.00-07 Hour, A352.08-15 Day of month, A353.00-07 Month,
// A353.08-15 Year"; "Bits 00 to 05 of C mask the seconds, minutes, hours, day, month, and year".
export const FIELDS: readonly BcdField[] = [
  { offset: 2, byte: 1, name: "year", min: 0, max: 99, mask: 5 },
  { offset: 2, byte: 0, name: "month", min: 1, max: 12, mask: 4 },
  { offset: 1, byte: 1, name: "day", min: 1, max: 31, mask: 3 },
  { offset: 1, byte: 0, name: "hour", min: 0, max: 23, mask: 2 },
  { offset: 0, byte: 1, name: "minute", min: 0, max: 59, mask: 1 },
  { offset: 0, byte: 0, name: "second", min: 0, max: 59, mask: 0 },
];

// The flag table, rows S1 = S2, S1 > S2, S1 < S2: each flag is on exactly when its condition holds
// for the ordering of S1 against S2, and the contact is the flag of the instruction's condition.

export function isBcd(b: number): boolean {
  return b >> 4 <= 9 && (b & 0xf) <= 9;
}

const bcdValue = (b: number): number => (b >> 4) * 10 + (b & 0xf);

/** Parsed mnemonics: a vector's instruction is parsed once, not at every execution. */
const mnemonics = new Map<string, readonly [string, string]>();

/** "AND <=DT" -> ["AND", "<="]: the form and condition the generated names give as values. */
function parseMnemonic(instruction: string): readonly [string, string] {
  let parsed = mnemonics.get(instruction);
  if (parsed === undefined) {
    const info = (INSTRUCTION_INFO as Readonly<Record<string, InstructionInfo | undefined>>)[instruction];
    if (info?.family !== "cp1e-time-compare" || info.form === null || info.condition === null) {
      throw new Error(`not a CP1E time comparison: ${instruction}`);
    }
    parsed = [info.form, info.condition];
    mnemonics.set(instruction, parsed);
  }
  return parsed;
}

export class Cp1eTimeCompare extends BaseMachine {
  readonly contact = true;
  protected fields = FIELDS;
  protected isBcd = isBcd;

  /** Error: P_ER on, the result off, the six arithmetic flags untouched. */
  protected error(): boolean {
    this.mem.write(ERROR_FLAG, true);
    // The flag table has no row for an execution without a comparison result: the six flags keep
    // their values, or (CP1E-ERROR-FLAGS=off) are all written off.
    if (this.follows["CP1E-ERROR-FLAGS"] === "off") for (const [, flag] of FLAGS) this.mem.write(flag, false);
    return false;
  }

  /** "the result of a time comparison instruction is reflected in the arithmetic flags (=, <>, <, <=, >, >=)". */
  protected reflectFlags(order: number): void {
    for (const [symbol, flag] of FLAGS) this.mem.write(flag, conditionHolds(symbol, order));
  }

  protected evaluate(condition: string, operands: Operands): boolean {
    const mem = this.mem;
    const s1Dev = deviceOf(operands["S1"], "S1");
    const s2Dev = deviceOf(operands["S2"], "S2");
    // "S1 to S1+2", "S2 to S2+2": three words each. One past the end of the data area (S1 or S2 in
    // one of its last two words) is CP1E-PAST-AREA-END, found before C or the data are looked at.
    if (!mem.inRange(s1Dev, 3) || !mem.inRange(s2Dev, 3)) {
      // A program error: not executed, nothing written, an OFF execution condition.
      if (this.follows["CP1E-PAST-AREA-END"] === "program-error") return false;
      return this.error();
    }
    const s1 = mem.words(s1Dev, 3);
    const s2 = mem.words(s2Dev, 3);
    const c = mem.operand(operands["C"]!);
    if (c & 0xffc0 && this.follows["CP1E-C-HIGH-BITS"] === "error") return this.error();
    // "To mask a time value, set the corresponding bit in the control word (C) to 1."
    let allMasked = true;
    for (const f of this.fields) if (((c >> f.mask) & 1) === 0) allMasked = false;
    if (allMasked && this.follows["CP1E-ALL-MASKED"] === "error") return this.error();
    if (allMasked && this.follows["CP1E-ALL-MASKED"] === "not-compared") {
      // Nothing compared, no result: OFF, the flags untouched, no error.
      if (this.follows["CP1E-ER-FLAG"] === "reflects-each-execution") mem.write(ERROR_FLAG, false);
      return false;
    }
    let order = 0;
    for (const f of this.fields) {
      if ((c >> f.mask) & 1) continue;
      const a = (s1[f.offset]! >> (8 * f.byte)) & 0xff;
      const b = (s2[f.offset]! >> (8 * f.byte)) & 0xff;
      if (this.invalidByte(a, f) || this.invalidByte(b, f)) return this.error();
      // "limited to comparing 8-bit time values": valid BCD bytes order as their numbers do.
      if (order === 0 && a !== b) order = a < b ? -1 : 1;
    }
    this.reflectFlags(order);
    if (this.follows["CP1E-ER-FLAG"] === "reflects-each-execution") mem.write(ERROR_FLAG, false);
    return conditionHolds(condition, order);
  }

  /** Whether a compared byte is an error under the declared alternatives: not BCD, or BCD outside the field's range. */
  protected invalidByte(raw: number, f: BcdField): boolean {
    if (!this.isBcd(raw)) return this.follows["CP1E-NON-BCD"] === "error";
    const v = bcdValue(raw);
    return (v < f.min || v > f.max) && this.follows["CP1E-OUT-OF-RANGE"] === "error";
  }

  execute(instruction: string, operands: Operands, step: StepInputs): boolean {
    const [form, condition] = parseMnemonic(instruction);
    if (form === "LD") return this.evaluate(condition, operands);
    const rlo = step.rlo_in === true;
    const logic = this.follows["CP1E-AND-OR-WHEN-OFF"];
    if (form === "AND") {
      if (!rlo && (logic === "and-skipped" || logic === "short-circuit")) return false;
      const contact = this.evaluate(condition, operands);
      return rlo && contact;
    }
    if (rlo && logic === "short-circuit") return true;
    const contact = this.evaluate(condition, operands);
    return rlo || contact;
  }
}
