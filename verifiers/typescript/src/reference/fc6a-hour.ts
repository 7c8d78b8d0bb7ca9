/** IDEC FC6A MICROSmart: HOUR (hour meter), from fc6a-hour-meter-HOUR.txt. */
import type { Operand, StepInputs } from "../index.js";
import { BaseMachine, deviceOf, type Operands } from "./machine.js";

const ERROR_FLAG = "M8004";
/** "returns to 0 hours 0 minutes 0 seconds" after "65,535 hours 59 minutes 59 seconds". */
export const CYCLE = 65536 * 3600;
/** "Special internal relays cannot be designated as destination device D2": M8000 onwards (the spec's special_relays). */
const SPECIAL_RELAY = { kind: "M", first: 8000 } as const;

const toSeconds = (hms: readonly number[]): number => hms[0]! * 3600 + hms[1]! * 60 + hms[2]!;
const fromSeconds = (total: number): number[] => [Math.floor(total / 3600), Math.floor((total % 3600) / 60), total % 60];

/** Devices already classified: every execution asks of its D2, and a program names few devices. */
const specialRelays = new Map<string, boolean>();

function isSpecialRelay(device: string): boolean {
  let special = specialRelays.get(device);
  if (special === undefined) {
    const m = /^([A-Za-z_]+)(\d+)$/.exec(device);
    special = m !== null && m[1] === SPECIAL_RELAY.kind && Number(m[2]) >= SPECIAL_RELAY.first;
    specialRelays.set(device, special);
  }
  return special;
}

/** One second more on a D1 whose words count each on their own (HOUR-D1-OUT-OF-RANGE=by-field), and whether the hour went from 65535 to 0. */
function tick([h, m, s]: readonly number[]): [number[], boolean] {
  const second = (s! + 1) & 0xffff;
  if (second !== 60) return [[h!, m!, second], false];
  const minute = (m! + 1) & 0xffff;
  if (minute !== 60) return [[h!, minute, 0], false];
  const hour = (h! + 1) & 0xffff;
  return [[hour, 0, 0], hour === 0];
}

/** Whether `a` reaches `b` word by word: the hours first, then the minutes, then the seconds. */
function reachesByField(a: readonly number[], b: readonly number[]): boolean {
  for (let i = 0; i < 3; i++) if (a[i] !== b[i]) return a[i]! > b[i]!;
  return true;
}

export class Fc6aHourMeter extends BaseMachine {
  readonly contact = false;
  protected cycle = CYCLE;
  /** The fraction of a second already measured (the CPU keeps it in the work area D3, never compared). */
  private fractionMs = 0;
  /** For "recompared": D2 stays on across a wrap. */
  private wrapped = false;
  /** The input at the previous execution (before the first one it counts as off). */
  private inputWasOn = false;
  /** The first execution since the CPU started (HOUR-FIRST-SCAN=after-cpu-start). */
  private firstScan = true;
  /** What the previous check of S1 found (HOUR-M8004-REPEAT=once): valid before any check. */
  private lastCheckValid = true;

  protected preset(op: Operand): number[] {
    // A constant: "0 through 65,535 in hours, then minutes and seconds are set to 0"; one above is
    // HOUR-S1-CONSTANT-RANGE's question.
    if (!("constant" in op)) return this.mem.words(op.device, 3);
    const hours = op.constant;
    const outside = hours < 0 || hours > 65535;
    return [outside && this.follows["HOUR-S1-CONSTANT-RANGE"] === "low-16-bits" ? hours & 0xffff : hours, 0, 0];
  }

  protected presetValid(p: readonly number[]): boolean {
    const hourOk = (p[0]! >= 0 && p[0]! <= 65535) || this.follows["HOUR-S1-CONSTANT-RANGE"] === "as-is";
    return hourOk && p[1]! >= 0 && p[1]! <= 59 && p[2]! >= 0 && p[2]! <= 59;
  }

  /** A program the page forbids whose reading is `undefined`: the instruction does nothing a vector judges. */
  private forbidden(operands: Operands, d2: string): boolean {
    if (isSpecialRelay(d2) && this.follows["HOUR-D2-SPECIAL"] === "undefined") return true;
    const s1 = operands["S1"]!;
    return "constant" in s1 && (s1.constant < 0 || s1.constant > 65535) && this.follows["HOUR-S1-CONSTANT-RANGE"] === "undefined";
  }

  protected reached(total: number, preset: number): boolean {
    return total >= preset;
  }

  /** Read and check S1: the preset, or undefined when it is invalid (M8004 on, D2 off; `d2` undefined: D2 is not written). */
  protected checkPreset(operands: Operands, d2: string | undefined): number[] | undefined {
    const p = this.preset(operands["S1"]!);
    if (!this.presetValid(p)) {
      // "a user program execution error ... turning on ... M8004 ... but the input ON duration is measured";
      // "... changed to an invalid value after the comparison output has turned on, the comparison output is turned off."
      // Again at every such check, or only when S1 has just become invalid (HOUR-M8004-REPEAT).
      if (this.follows["HOUR-M8004-REPEAT"] === "every-check" || this.lastCheckValid) this.mem.write(ERROR_FLAG, true);
      this.lastCheckValid = false;
      if (d2 !== undefined) this.mem.write(d2, false);
      return undefined;
    }
    this.lastCheckValid = true;
    // The page never says M8004 turns off; HOUR-M8004-OFF=valid-preset does.
    if (this.follows["HOUR-M8004-OFF"] === "valid-preset") this.mem.write(ERROR_FLAG, false);
    return p;
  }

  execute(instruction: string, operands: Operands, step: StepInputs): undefined {
    if (instruction !== "HOUR") throw new Error(`not HOUR: ${instruction}`);
    const d1 = deviceOf(operands["D1"], "D1");
    let d2: string | undefined = deviceOf(operands["D2"], "D2");
    const on = step.input === true;
    const turnedOn = on && !this.inputWasOn;
    this.inputWasOn = on;
    const first = this.firstScan;
    this.firstScan = false;
    if (this.forbidden(operands, d2)) return undefined;
    // A special relay as D2 under HOUR-D2-SPECIAL=error: never written, M8004 on at each execution with the input on.
    const d2Error = isSpecialRelay(d2) && this.follows["HOUR-D2-SPECIAL"] === "error";
    if (d2Error) d2 = undefined;
    if (!on) {
      const off = this.follows["HOUR-INPUT-OFF"];
      if (off === "reset") {
        this.mem.writeWords(d1, [0, 0, 0]);
        this.fractionMs = 0;
      } else if (off === "hold-drop-fraction") {
        this.fractionMs = 0; // D1 kept; the part of a second already measured is lost
      }
      // HOUR-PRESET-CHECK=every-execution: the preset is checked with the input off too.
      if (this.follows["HOUR-PRESET-CHECK"] === "every-execution") this.checkPreset(operands, d2);
      return undefined;
    }
    this.measureAndCompare(operands, d1, d2, step, turnedOn, first);
    if (d2Error) this.mem.write(ERROR_FLAG, true);
    return undefined;
  }

  /** An execution with the input on: measure into D1 (as HOUR-D1-OUT-OF-RANGE reads an out-of-range D1), then compare with S1. */
  private measureAndCompare(operands: Operands, d1: string, d2: string | undefined, step: StepInputs, turnedOn: boolean, first: boolean): void {
    const held = this.mem.words(d1, 3);
    // "Minute and second data can be 0 through 59": a D1 the program set outside is HOUR-D1-OUT-OF-RANGE's question.
    const reading = held[1]! > 59 || held[2]! > 59 ? this.follows["HOUR-D1-OUT-OF-RANGE"] : "as-seconds";
    if (reading === "undefined") return;
    if (reading === "error") {
      this.mem.write(ERROR_FLAG, true);
      return;
    }
    // The elapsed time since the previous execution is ON time, but not at the execution the input
    // turns on (HOUR-FIRST-SCAN=from-next-scan) or the first since the CPU started (after-cpu-start).
    const firstScan = this.follows["HOUR-FIRST-SCAN"];
    if (!((turnedOn && firstScan === "from-next-scan") || (first && firstScan === "after-cpu-start"))) this.fractionMs += step.elapsed_ms ?? 0;
    const whole = Math.floor(this.fractionMs / 1000);
    this.fractionMs %= 1000;
    let hms: number[];
    let wraps = 0;
    if (reading === "by-field") {
      hms = held;
      for (let i = 0; i < whole; i++) {
        const [next, wrapped] = tick(hms);
        hms = next;
        if (wrapped) wraps++;
      }
    } else {
      const total = toSeconds(held) + whole;
      wraps = Math.floor(total / this.cycle);
      hms = fromSeconds(total % this.cycle);
    }
    if (whole > 0 || reading !== "as-seconds-if-added") this.mem.writeWords(d1, hms);
    const p = this.checkPreset(operands, d2);
    if (p === undefined) return;
    // HOUR-WRAP-REACH=before-wrap: an execution that wraps compares the count before the wrap.
    const beforeWrap = wraps > 0 && this.follows["HOUR-WRAP-REACH"] === "before-wrap";
    const counted = [hms[0]! + (beforeWrap ? 65536 * wraps : 0), hms[1]!, hms[2]!];
    let reached = reading === "by-field" ? reachesByField(counted, p) : this.reached(toSeconds(counted), toSeconds(p));
    if (toSeconds(p) === 0 && this.follows["HOUR-PRESET-ZERO"] === "never") reached = false;
    if (d2 !== undefined) this.setOutput(d2, reached, wraps > 0, beforeWrap);
  }

  /** D2 after a comparison: latched on, or recompared and kept on across a wrap (HOUR-OUTPUT-OFF). */
  private setOutput(d2: string, reached: boolean, wrappedNow: boolean, comparedFirst: boolean): void {
    const mem = this.mem;
    if (this.follows["HOUR-OUTPUT-OFF"] === "latched") {
      if (reached) mem.write(d2, true);
      return;
    }
    if (wrappedNow && !comparedFirst && mem.bit(d2)) this.wrapped = true;
    if (reached) this.wrapped = false;
    mem.write(d2, reached || (this.wrapped && mem.bit(d2)));
    if (wrappedNow && comparedFirst && mem.bit(d2)) this.wrapped = true; // on when D1 wrapped, after the comparison
  }
}
