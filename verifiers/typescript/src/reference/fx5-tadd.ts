/** Mitsubishi MELSEC iQ-F FX5: TADD / TADDP (adding clock data), from fx5-time-add-TADD.txt. */
import { Memory, type StepInputs } from "../index.js";
import { BaseMachine, deviceOf, signed16, type Operands } from "./machine.js";

const DAY = 24 * 3600;
// "SM700 Carry ... SM8020 Zero ... SM8022 Carry"; "Error code (SD0/SD8067)".
export const CARRY_FLAGS: readonly string[] = ["SM700", "SM8022"];
const ZERO_FLAG = "SM8020";
const ERROR_REGISTERS = ["SD0", "SD8067"];
// "2820H The device range ... exceeds", "3405H Any of values ... is outside the following range".
const ERR_DEVICE_RANGE = 0x2820;
const ERR_VALUE_RANGE = 0x3405;
// hour 0 to 23, minute 0 to 59, second 0 to 59.
export const RANGES: readonly (readonly [number, number])[] = [
  [0, 23],
  [0, 59],
  [0, 59],
];
// Seconds in one hour, minute, second; and what each word counts up to before it carries.
const WEIGHTS: readonly number[] = [3600, 60, 1];
const RADIX: readonly number[] = [24, 60, 60];

/** Word `k` of the three from `dev` on, as "16-bit signed binary". */
function signedWord(mem: Memory, dev: string, k: number): number {
  return signed16(mem.word(Memory.offset(dev, k)));
}

/** The mathematical quotient and remainder (the remainder never negative), as "div" and "mod" say. */
function divmod(n: number, d: number): [number, number] {
  const q = Math.floor(n / d);
  return [q, n - q * d];
}

export class Fx5TimeAdd extends BaseMachine {
  readonly contact = false;
  protected carryFlags = CARRY_FLAGS;
  protected ranges = RANGES;
  /** TADDP: the state of EN before the first scan is off. */
  private previousEn = false;

  protected error(code: number): void {
    for (const reg of ERROR_REGISTERS) this.mem.write(reg, code);
  }

  protected setFlags(carry: boolean, zero: boolean): void {
    if (this.follows["TADD-FLAGS-OFF"] === "written-each-execution") {
      for (const f of this.carryFlags) this.mem.write(f, carry);
      this.mem.write(ZERO_FLAG, zero);
    } else {
      if (carry) for (const f of this.carryFlags) this.mem.write(f, true);
      if (zero) this.mem.write(ZERO_FLAG, true);
    }
  }

  /** The sum in seconds -> the result in seconds and the carry (TADD-EXACT-24 for exactly 24:00:00). */
  protected wrap(total: number): { result: number; carry: boolean } {
    const carry = this.follows["TADD-EXACT-24"] === "carry-at-24" ? total >= DAY : total > DAY;
    return { result: ((total % DAY) + DAY) % DAY, carry };   // a sum of negative words, too, lands in 0..23:59:59
  }

  /** Whether any word of hour, minute, second lies outside its range. */
  protected outOfRange(data: readonly number[]): boolean {
    for (let i = 0; i < data.length; i++) if (data[i]! < this.ranges[i]![0] || data[i]! > this.ranges[i]![1]) return true;
    return false;
  }

  protected add(operands: Operands): void {
    const mem = this.mem;
    const s1Dev = deviceOf(operands["s1"], "s1");
    const s2Dev = deviceOf(operands["s2"], "s2");
    const dDev = deviceOf(operands["d"], "d");
    // "These instructions occupy three points for each of three devices": an operand past its
    // device's range is 2820H; only an operand whose three words exist can be read and checked (3405H).
    if (!mem.inRange(s1Dev, 3) || !mem.inRange(s2Dev, 3) || !mem.inRange(dDev, 3)) {
      const fieldsBad = (dev: string): boolean => mem.inRange(dev, 3) && this.outOfRange(mem.words(dev, 3).map(signed16));
      // Both conditions at once: TADD-ERROR-ORDER says which code; nothing else is written.
      const both = fieldsBad(s1Dev) || fieldsBad(s2Dev);
      return this.error(both && this.follows["TADD-ERROR-ORDER"] === "field-range-first" ? ERR_VALUE_RANGE : ERR_DEVICE_RANGE);
    }
    const s1 = mem.words(s1Dev, 3).map(signed16);
    const s2 = mem.words(s2Dev, 3).map(signed16);
    const valid = !this.outOfRange(s1) && !this.outOfRange(s2);
    if (!valid) {
      this.error(ERR_VALUE_RANGE);
      if (this.follows["TADD-ON-ERROR"] === "not-executed") return;
    }
    // The words just read, unless an error code has been written since (it may lie among them).
    const total = valid ? this.sumSeconds(s1Dev, s2Dev, dDev, s1, s2) : this.sumSeconds(s1Dev, s2Dev, dDev);
    const { result, carry } = this.wrap(total);
    mem.writeWords(dDev, [Math.floor(result / 3600), Math.floor((result % 3600) / 60), result % 60]);
    // "If the result is 0 (0:00:00), the zero flag turns on."
    this.setFlags(carry, result === 0);
  }

  /**
   * (s1) + (s2) in seconds, the words read in the order TADD-OVERLAP says. The order shows only
   * when (d) shares words with (s1) or (s2) at another offset ((d) = (s1)+1, ...): a source word
   * read after a word of (d) was written then holds what was written. `s1` and `s2`: the words of
   * (s1) and (s2) as read before anything was written, when the caller has them.
   */
  protected sumSeconds(s1Dev: string, s2Dev: string, dDev: string, s1?: readonly number[], s2?: readonly number[]): number {
    const mem = this.mem;
    const order = this.follows["TADD-OVERLAP"];
    let total = 0;
    if (order === "sources-first") {
      // "add the time data stored in ... (s2) to the clock data stored in ... (s1)": all six words first.
      const a = s1 ?? mem.words(s1Dev, 3).map(signed16);
      const b = s2 ?? mem.words(s2Dev, 3).map(signed16);
      for (let k = 0; k < 3; k++) total += (a[k]! + b[k]!) * WEIGHTS[k]!;
    } else if (order === "second-first") {
      // Second, minute, hour: each word of (d) gets its digit as soon as it is known, the carry going up.
      let carry = 0;
      for (const k of [2, 1, 0]) {
        const sum = signedWord(mem, s1Dev, k) + signedWord(mem, s2Dev, k);
        total += sum * WEIGHTS[k]!;
        const [next, digit] = divmod(sum + carry, RADIX[k]!);
        mem.write(Memory.offset(dDev, k), digit);
        carry = next;
      }
    } else {
      // hour-first: each pair's plain sum into (d), hour to second; the caller settles the carries.
      for (const k of [0, 1, 2]) {
        const sum = signedWord(mem, s1Dev, k) + signedWord(mem, s2Dev, k);
        total += sum * WEIGHTS[k]!;
        mem.write(Memory.offset(dDev, k), sum);
      }
    }
    return total;
  }

  execute(instruction: string, operands: Operands, step: StepInputs): undefined {
    const en = step.en === true;
    let run: boolean;
    if (instruction === "TADD") run = en;
    else if (instruction === "TADDP") run = en && !this.previousEn;
    else throw new Error(`not TADD/TADDP: ${instruction}`);
    this.previousEn = en;
    if (run) this.add(operands);
    return undefined;
  }
}
