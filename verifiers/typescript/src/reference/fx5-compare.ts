/**
 * Mitsubishi MELSEC iQ-F FX5: LDTM□/ANDTM□/ORTM□ (time) and LDDT□/ANDDT□/ORDT□ (date), written
 * from the manual pages fx5-time-compare-LDTM.txt and fx5-date-compare-LDDT.txt. The two pages are
 * the same text with hour/minute/second replaced by year/month/day, so one class serves both.
 */
import { INSTRUCTION_INFO, type InstructionInfo, type StepInputs } from "../index.js";
import { BaseMachine, conditionHolds, deviceOf, signed16, type Operands } from "./machine.js";

export interface Field {
  readonly offset: number;
  readonly name: string;
  readonly min: number;
  readonly max: number;
  /** The (s3) bit that selects it. */
  readonly bit: number;
}

// Most significant first. 'Set the "hour" data ... 0 to 23', '"minute" ... (s1)+1 ... 0 to 59',
// '"second" ... (s1)+2 ... 0 to 59'; '(1) Set "second" as comparison target. (2) ... "minute" ... (3) ... "hour"'.
export const TIME_FIELDS: readonly Field[] = [
  { offset: 0, name: "hour", min: 0, max: 23, bit: 2 },
  { offset: 1, name: "minute", min: 0, max: 59, bit: 1 },
  { offset: 2, name: "second", min: 0, max: 59, bit: 0 },
];
// 'the 4 digit "year" data ... 1980 to 2079', '"month" ... 1 to 12', '"date" ... 1 to 31'.
export const DATE_FIELDS: readonly Field[] = [
  { offset: 0, name: "year", min: 1980, max: 2079, bit: 2 },
  { offset: 1, name: "month", min: 1, max: 12, bit: 1 },
  { offset: 2, name: "day", min: 1, max: 31, bit: 0 },
];

const SM709 = "SM709";

/** Parsed mnemonics of each kind ("LDTM<=" is not a date comparison): a vector's instruction is parsed once. */
const mnemonics = { TM: new Map<string, { form: string; condition: string }>(), DT: new Map<string, { form: string; condition: string }>() };


export class Fx5Compare extends BaseMachine {
  readonly contact = true;
  protected fields: readonly Field[] = TIME_FIELDS;
  protected kind: "TM" | "DT" = "TM";

  /** The date comparison: the same rules over year/month/day. */
  forDates(): this {
    this.fields = DATE_FIELDS;
    this.kind = "DT";
    return this;
  }

  /** "SM709 turns on ... and the operation result will be non-continuity"; held until power-off: never cleared here. */
  /** Whether the last evaluation found invalid data (turned SM709 on). */
  protected failed = false;

  protected error(): boolean {
    this.failed = true;
    this.mem.write(SM709, true);
    return false;
  }

  protected outOfRange(words: readonly number[], selected: number | undefined): boolean {
    for (const f of this.fields) {
      if (selected !== undefined && ((selected >> f.bit) & 1) === 0) continue;
      const v = signed16(words[f.offset]!);
      if (v < f.min || v > f.max) return true;
    }
    return false;
  }

  /** -1/0/1, field by field, the most significant selected field first. */
  protected order(s1: readonly number[], s2: readonly number[], s3: number): number {
    for (const f of this.fields) {
      if (((s3 >> f.bit) & 1) === 0) continue;
      const a = signed16(s1[f.offset]!);
      const b = signed16(s2[f.offset]!);
      if (a !== b) return a < b ? -1 : 1;
    }
    return 0;
  }

  /** (s3) is valid when bits 3..14 are 0 and at least one of bits 0..2 is 1. */
  protected s3Valid(s3: number): boolean {
    return (s3 & 0x7ff8) === 0 && (s3 & 0x0007) !== 0;
  }

  protected evaluate(condition: string, operands: Operands, clock: StepInputs["clock"]): boolean {
    const mem = this.mem;
    const s1Dev = deviceOf(operands["s1"], "s1");
    const s2Dev = deviceOf(operands["s2"], "s2");
    const s3 = mem.operand(operands["s3"]!);
    // "(5) When 1 is set to the 15 bit, ... compared with the current time ... (s2) is regarded as dummy data and ignored."
    const useClock = (s3 & 0x8000) !== 0;
    // "(4) Set 0. If a value other than 0 is set, the operation result will be non-continuity" (bits 3
    // to 14); "Other than 0001H to 0007H, 8001H to 8007H  None ... (The operation result will be non-continuity.)"
    const valid = this.s3Valid(s3);
    // "If the device areas specified by (s1) to (s1)+2 or (s2) to (s2)+2 exceed the corresponding device range, SM709 turns on"
    const s2Checked = !useClock || this.follows["FX5-CLOCK-S2-DEVICE-RANGE"] === "checked";
    if (!mem.inRange(s1Dev, 3) || (s2Checked && !mem.inRange(s2Dev, 3))) {
      // An invalid (s3) as well: which rule decides is FX5-INVALID-S3-DEVICE-RANGE.
      if (!valid && this.follows["FX5-INVALID-S3-DEVICE-RANGE"] === "s3-first") return false;
      return this.error();
    }

    const s1 = mem.words(s1Dev, 3);
    const s2 = useClock ? this.fields.map((f) => clock?.[f.name] ?? 0) : mem.words(s2Dev, 3);
    // "If the comparison target data in the device are not recognized as time data, SM709 turns on":
    // which words are comparison target data is FX5-SM709-SCOPE.
    const scope = this.follows["FX5-SM709-SCOPE"];
    if (scope === "all-words") {
      if (this.outOfRange(s1, undefined) || (!useClock && this.outOfRange(s2, undefined))) return this.error();
      if (!valid) return false;
    } else if (scope === "compared-operands") {
      // The operands as a whole are comparison target data, but only when a comparison is made.
      if (!valid) return false;
      if (this.outOfRange(s1, undefined) || (!useClock && this.outOfRange(s2, undefined))) return this.error();
    } else {
      if (!valid) return false;
      if (this.outOfRange(s1, s3) || (!useClock && this.outOfRange(s2, s3))) return this.error();
    }
    // Date page: "SM709 does not turn on if the data are within the setting range": 02/30 is compared as is.
    return conditionHolds(condition, this.order(s1, s2, s3));
  }

  execute(instruction: string, operands: Operands, step: StepInputs): boolean {
    const { form, condition } = this.parse(instruction);
    if (form === "LD") return this.evaluate(condition, operands, step.clock);
    const rlo = step.rlo_in === true;
    const logic = this.follows["FX5-AND-OR-WHEN-OFF"];
    // The MELSEC iQ-R Programming Manual's processing-time tables: "an AND/OR comparison is not
    // executed while the preceding logic is off" (the default).
    if (form === "AND") {
      if (!rlo && (logic === "and-skipped" || logic === "short-circuit")) return false;
      const contact = this.evaluate(condition, operands, step.clock);
      return rlo && contact;
    }
    if (rlo && logic === "short-circuit") return true;
    this.failed = false;
    const contact = this.evaluate(condition, operands, step.clock);
    // "SM709 turns on ... and the operation result will be non-continuity": a non-conductive
    // contact in parallel (contact-off), or the rung's result itself off (result-off).
    if (this.failed && this.follows["FX5-OR-ON-ERROR"] === "result-off") return false;
    return rlo || contact;
  }

  /** "ANDTM<=" -> {form: "AND", condition: "<="}: the values the generated names give (parsed once per mnemonic). */
  protected parse(instruction: string): { form: string; condition: string } {
    const parsedOfKind = this.kind === "TM" ? mnemonics.TM : mnemonics.DT; // not mnemonics[this.kind]: a keyed read of two keys goes megamorphic
    let parsed = parsedOfKind.get(instruction);
    if (parsed === undefined) {
      const info = (INSTRUCTION_INFO as Readonly<Record<string, InstructionInfo | undefined>>)[instruction];
      const family = this.kind === "TM" ? "fx5-time-compare" : "fx5-date-compare";
      if (info?.family !== family || info.form === null || info.condition === null) {
        throw new Error(`not an FX5 ${this.kind} comparison: ${instruction}`);
      }
      parsed = { form: info.form, condition: info.condition };
      parsedOfKind.set(instruction, parsed);
    }
    return parsed;
  }
}
