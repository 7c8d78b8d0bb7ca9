/** IDEC FC6A MICROSmart: HOUR (hour meter), from fc6a-hour-meter-HOUR.txt. */
import type { Operand, StepInputs } from "../index.js";
import { BaseMachine, deviceOf, type Operands } from "./machine.js";

const ERROR_FLAG = "M8004";
/** "returns to 0 hours 0 minutes 0 seconds" after "65,535 hours 59 minutes 59 seconds". */
export const CYCLE = 65536 * 3600;

export class HourMeter extends BaseMachine {
  readonly contact = false;
  protected cycle = CYCLE;
  /** The fraction of a second already measured (the CPU keeps it in the work area D3, never compared). */
  private fractionMs = 0;
  /** For "recompared": D2 stays on across a wrap. */
  private wrapped = false;
  /** The input at the previous execution (before the first one it counts as off). */
  private inputWasOn = false;

  protected preset(op: Operand): number[] {
    // A constant: "0 through 65,535 in hours, then minutes and seconds are set to 0."
    if ("constant" in op) return [op.constant & 0xffff, 0, 0];
    return this.mem.words(op.device, 3);
  }

  protected presetValid(p: readonly number[]): boolean {
    return p[0]! >= 0 && p[0]! <= 65535 && p[1]! >= 0 && p[1]! <= 59 && p[2]! >= 0 && p[2]! <= 59;
  }

  protected reached(total: number, preset: number): boolean {
    return total >= preset;
  }

  /** Read and check S1: the preset, or undefined when it is invalid (M8004 on, D2 off). */
  protected checkPreset(operands: Operands, d2: string): number[] | undefined {
    const p = this.preset(operands["S1"]!);
    if (!this.presetValid(p)) {
      // "a user program execution error ... turning on ... M8004 ... but the input ON duration is measured";
      // "... changed to an invalid value after the comparison output has turned on, the comparison output is turned off."
      this.mem.write(ERROR_FLAG, true);
      this.mem.write(d2, false);
      return undefined;
    }
    // The page never says M8004 turns off; HOUR-M8004-OFF=valid-preset does.
    if (this.choice("HOUR-M8004-OFF") === "valid-preset") this.mem.write(ERROR_FLAG, false);
    return p;
  }

  execute(instruction: string, operands: Operands, step: StepInputs): undefined {
    if (instruction !== "HOUR") throw new Error(`not HOUR: ${instruction}`);
    const mem = this.mem;
    const d1 = deviceOf(operands["D1"], "D1");
    const d2 = deviceOf(operands["D2"], "D2");
    const on = step.input === true;
    const turnedOn = on && !this.inputWasOn;
    this.inputWasOn = on;
    if (!on) {
      const off = this.choice("HOUR-INPUT-OFF");
      if (off === "reset") {
        mem.writeWords(d1, [0, 0, 0]);
        this.fractionMs = 0;
      } else if (off === "hold-drop-fraction") {
        this.fractionMs = 0; // D1 kept; the part of a second already measured is lost
      }
      // HOUR-PRESET-CHECK=every-execution: the preset is checked with the input off too.
      if (this.choice("HOUR-PRESET-CHECK") === "every-execution") this.checkPreset(operands, d2);
      return undefined;
    }
    // "Minute and second data can be 0 through 59." A D1 the program set outside that is counted
    // as seconds and carried back into range (HOUR-D1-OUT-OF-RANGE=as-seconds), or is an error that
    // stops this execution (error).
    const [, heldMinute, heldSecond] = mem.words(d1, 3) as [number, number, number];
    if ((heldMinute > 59 || heldSecond > 59) && this.choice("HOUR-D1-OUT-OF-RANGE") === "error") {
      mem.write(ERROR_FLAG, true);
      return undefined;
    }
    // The elapsed time since the previous execution is ON time; at the execution the input turns
    // on, only under HOUR-FIRST-SCAN=counts.
    if (!(turnedOn && this.choice("HOUR-FIRST-SCAN") === "from-next-scan")) this.fractionMs += step.elapsed_ms ?? 0;
    const whole = Math.floor(this.fractionMs / 1000);
    this.fractionMs %= 1000;
    const [h, m, s] = mem.words(d1, 3) as [number, number, number];
    let total = h * 3600 + m * 60 + s + whole;
    const wrappedNow = total >= this.cycle;
    total %= this.cycle;
    mem.writeWords(d1, [Math.floor(total / 3600), Math.floor((total % 3600) / 60), total % 60]);

    const p = this.checkPreset(operands, d2);
    if (p === undefined) return undefined;
    const preset = p[0]! * 3600 + p[1]! * 60 + p[2]!;
    let reached = this.reached(total, preset);
    if (preset === 0 && this.choice("HOUR-PRESET-ZERO") === "never") reached = false;
    if (this.choice("HOUR-OUTPUT-OFF") === "latched") {
      if (reached) mem.write(d2, true);
    } else {
      if (wrappedNow && mem.bit(d2)) this.wrapped = true;
      if (reached) this.wrapped = false;
      mem.write(d2, reached || (this.wrapped && mem.bit(d2)));
    }
    return undefined;
  }
}
