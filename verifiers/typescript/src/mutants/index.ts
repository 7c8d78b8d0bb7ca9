/**
 * Single-bug variants of the reference implementation. Each is a plausible mistake an emulator
 * author could make; the suite and this runner must reject every one (test/mutants.test.ts), or
 * the verifier could not fail and would prove nothing. Each names the comparison aspect it breaks.
 */
import { type Implementation, Memory, type StepInputs } from "../index.js";
import { machineImplementation, MACHINES, type MachineFactory } from "../reference/index.js";
import { Cp1eTimeCompare, FIELDS } from "../reference/cp1e-dt.js";
import { Fc6aHourMeter } from "../reference/fc6a-hour.js";
import { Fx5Compare, type Field, DATE_FIELDS } from "../reference/fx5-compare.js";
import { Fx5TimeAdd } from "../reference/fx5-tadd.js";
import type { Operands } from "../reference/machine.js";

export type Aspect =
  | "contact result"
  | "changed word"
  | "flag"
  | "device that must stay unchanged"
  | "write outside the vector"
  | "interpretation alternative";

export interface Mutant {
  readonly family: string;
  readonly aspect: Aspect;
  readonly bug: string;
  readonly machines: Readonly<Record<string, MachineFactory>>;
}

// -- FX5 time and date comparison ------------------------------------------------------------

/** `<=` evaluated as `<`: equal times give non-continuity. */
class LeAsLt extends Fx5Compare {
  protected override evaluate(condition: string, operands: Operands, clock: StepInputs["clock"]): boolean {
    return super.evaluate(condition === "<=" ? "<" : condition, operands, clock);
  }
}

/** SM709 cleared by an execution without error, though the manual holds it until power-off. */
class Sm709Cleared extends Fx5Compare {
  protected override evaluate(condition: string, operands: Operands, clock: StepInputs["clock"]): boolean {
    const before = this.mem.value("SM709");
    const result = super.evaluate(condition, operands, clock);
    if (this.mem.value("SM709") === before) this.mem.write("SM709", false);
    return result;
  }
}

/** The year accepted from 1970: a year before 1980 is compared instead of turning SM709 on. */
class YearFrom1970 extends Fx5Compare {
  override forDates(): this {
    super.forDates();
    this.fields = DATE_FIELDS.map((f): Field => (f.name === "year" ? { ...f, min: 1970 } : f));
    return this;
  }
}

/**
 * An AND form executed while the preceding logic is off, whatever the declared alternative, and its
 * comparison passed on without the preceding logic: SM709 as under always-executed (a reading), but
 * a contact that conducts with its logic off (a bug no reading explains).
 */
class AndAlwaysExecuted extends Fx5Compare {
  override execute(instruction: string, operands: Operands, step: StepInputs): boolean {
    if (instruction.startsWith("AND") && step.rlo_in === false) return this.evaluate(this.parse(instruction).condition, operands, step.clock);
    return super.execute(instruction, operands, step);
  }
}

/** The current clock written into the dummy (s2) words it replaces: a device that must stay unchanged. */
class ClockIntoS2 extends Fx5Compare {
  protected override evaluate(condition: string, operands: Operands, clock: StepInputs["clock"]): boolean {
    const s3 = this.mem.operand(operands["s3"]!);
    const s2 = operands["s2"];
    if (s3 & 0x8000 && clock !== undefined && s2 !== undefined && "device" in s2 && this.mem.inRange(s2.device, 3)) {
      this.mem.writeWords(s2.device, this.fields.map((f) => clock[f.name] ?? 0));
    }
    return super.evaluate(condition, operands, clock);
  }
}

// -- FX5 TADD / TADDP ------------------------------------------------------------------------------

/** Only SM700 carries; SM8022 is forgotten. */
class OneCarryFlag extends Fx5TimeAdd {
  protected override carryFlags: readonly string[] = ["SM700"];
}

/** The destination is written even when its three words pass the end of the device: a write outside the vector. */
class WritesPastRange extends Fx5TimeAdd {
  protected override add(operands: Operands): void {
    const d = operands["d"];
    if (d !== undefined && "device" in d && !this.mem.inRange(d.device, 3)) {
      this.mem.writeWords(d.device, [0, 0, 0]);
    }
    super.add(operands);
  }
}

/** The hour not wrapped: 23:00:00 + 02:00:00 gives 25:00:00. */
class HourNotWrapped extends Fx5TimeAdd {
  protected override wrap(total: number): { result: number; carry: boolean } {
    const { carry } = super.wrap(total);
    return { result: total, carry };
  }
}

/** TADDP executed on every scan while EN is on, not only on its rising edge. */
class PulseEveryScan extends Fx5TimeAdd {
  override execute(instruction: string, operands: Operands, step: StepInputs): undefined {
    return super.execute(instruction === "TADDP" ? "TADD" : instruction, operands, step);
  }
}

/**
 * (s1) copied into (d) word by word from the hour, then (s2) added to (d) in place: a word of (s2),
 * or a later word of (s1), that is also a word of (d) is overwritten before it is read.
 */
class S1CopiedIntoDFirst extends Fx5TimeAdd {
  protected override sumSeconds(s1Dev: string, s2Dev: string, dDev: string): number {
    for (let k = 0; k < 3; k++) this.mem.write(Memory.offset(dDev, k), this.mem.word(Memory.offset(s1Dev, k)));
    return super.sumSeconds(dDev, s2Dev, dDev);
  }
}

// -- FC6A HOUR ----------------------------------------------------------------------------------

/** The measuring cycle one hour short: 65535:00:00 wraps to 0. */
class CycleShort extends Fc6aHourMeter {
  protected override cycle = 65535 * 3600;
}

/** The output turns on one second late: reached only past the preset, not at it. */
class ReachedLate extends Fc6aHourMeter {
  protected override reached(total: number, preset: number): boolean {
    return total > preset;
  }
}

// -- CP1E time comparison --------------------------------------------------------------------------

/** The C mask read one bit off: bit 1 masks the seconds. */
class MaskShifted extends Cp1eTimeCompare {
  protected override fields = FIELDS.map((f) => ({ ...f, mask: f.mask + 1 }));
}

/** The arithmetic flags left as they were: only the contact result is given. */
class FlagsNotReflected extends Cp1eTimeCompare {
  protected override reflectFlags(): void {}
}

/** P_ER held from an earlier error, whatever the declared alternative, and taken for this execution's error. */
class ErHeld extends Cp1eTimeCompare {
  protected override evaluate(condition: string, operands: Operands): boolean {
    const before = this.mem.value("P_ER");
    const result = super.evaluate(condition, operands);
    if (before !== true) return result;
    // Held (a reading), then read back as this execution's error: the contact stays off (a bug).
    this.mem.write("P_ER", true);
    return false;
  }
}

/**
 * A low nibble of 10 (0x0A) compared as BCD, and P_ER turned on as well: neither reading (an error
 * that compares nothing, or raw bytes compared without an error) but a check that flags and goes on.
 */
class NibbleAbove9 extends Cp1eTimeCompare {
  #sawTen = false;
  protected override isBcd = (b: number): boolean => {
    const ok = b >> 4 <= 9 && (b & 0xf) <= 10;
    if (ok && (b & 0xf) === 10) this.#sawTen = true;
    return ok;
  };

  protected override evaluate(condition: string, operands: Operands): boolean {
    this.#sawTen = false;
    const result = super.evaluate(condition, operands);
    if (this.#sawTen) this.mem.write("P_ER", true);
    return result;
  }
}

/**
 * No end to the data area: S1 or S2 at its last one or two words is compared all the same, the words
 * past the end read as 0, instead of the error or program error CP1E-PAST-AREA-END names.
 */
function pastAreaCompared(mem: Memory, choices: Readonly<Record<string, string>>): Cp1eTimeCompare {
  mem.inRange = () => true;
  return new Cp1eTimeCompare(mem, choices);
}

function replacing(family: string, factory: MachineFactory): Readonly<Record<string, MachineFactory>> {
  return { ...MACHINES, [family]: factory };
}

const fx5Both = (make: (mem: Memory, choices: Readonly<Record<string, string>>) => Fx5Compare) => ({
  ...MACHINES,
  "fx5-time-compare": make,
  "fx5-date-compare": (mem: Memory, choices: Readonly<Record<string, string>>) => make(mem, choices).forDates(),
});

export const MUTANTS: Readonly<Record<string, Mutant>> = {
  "fx5-le-as-lt": { family: "fx5-time-compare", aspect: "contact result", bug: "<= evaluated as <", machines: fx5Both((m, c) => new LeAsLt(m, c)) },
  "fx5-sm709-cleared": { family: "fx5-time-compare", aspect: "flag", bug: "SM709 cleared by an execution without error", machines: fx5Both((m, c) => new Sm709Cleared(m, c)) },
  "fx5-year-from-1970": {
    family: "fx5-date-compare",
    aspect: "flag",
    bug: "years 1970..1979 accepted",
    machines: replacing("fx5-date-compare", (m, c) => new YearFrom1970(m, c).forDates()),
  },
  "fx5-and-always-executed": {
    family: "fx5-time-compare",
    aspect: "interpretation alternative",
    bug: "AND executed while the preceding logic is off, whatever is declared, its comparison passed on as the result",
    machines: fx5Both((m, c) => new AndAlwaysExecuted(m, c)),
  },
  "fx5-clock-into-s2": {
    family: "fx5-time-compare",
    aspect: "device that must stay unchanged",
    bug: "the current clock written into the dummy (s2) words",
    machines: fx5Both((m, c) => new ClockIntoS2(m, c)),
  },
  "tadd-one-carry-flag": { family: "fx5-time-add", aspect: "flag", bug: "SM8022 never written", machines: replacing("fx5-time-add", (m, c) => new OneCarryFlag(m, c)) },
  "tadd-writes-past-range": {
    family: "fx5-time-add",
    aspect: "write outside the vector",
    bug: "(d) written past the end of its device",
    machines: replacing("fx5-time-add", (m, c) => new WritesPastRange(m, c)),
  },
  "tadd-s1-copied-into-d-first": {
    family: "fx5-time-add",
    aspect: "changed word",
    bug: "(s1) copied into (d) first, then (s2) added to (d) in place",
    machines: replacing("fx5-time-add", (m, c) => new S1CopiedIntoDFirst(m, c)),
  },
  "tadd-hour-not-wrapped": { family: "fx5-time-add", aspect: "changed word", bug: "a sum past 24:00:00 not wrapped", machines: replacing("fx5-time-add", (m, c) => new HourNotWrapped(m, c)) },
  "taddp-every-scan": { family: "fx5-time-add", aspect: "changed word", bug: "TADDP executed on every scan", machines: replacing("fx5-time-add", (m, c) => new PulseEveryScan(m, c)) },
  "hour-cycle-short": { family: "fc6a-hour-meter", aspect: "changed word", bug: "wraps at 65535:00:00", machines: replacing("fc6a-hour-meter", (m, c) => new CycleShort(m, c)) },
  "hour-reached-late": { family: "fc6a-hour-meter", aspect: "flag", bug: "D2 on only past the preset", machines: replacing("fc6a-hour-meter", (m, c) => new ReachedLate(m, c)) },
  "cp1e-mask-shifted": { family: "cp1e-time-compare", aspect: "contact result", bug: "C mask bits read one off", machines: replacing("cp1e-time-compare", (m, c) => new MaskShifted(m, c)) },
  "cp1e-flags-not-reflected": {
    family: "cp1e-time-compare",
    aspect: "flag",
    bug: "P_EQ..P_GE never written",
    machines: replacing("cp1e-time-compare", (m, c) => new FlagsNotReflected(m, c)),
  },
  "cp1e-er-held": {
    family: "cp1e-time-compare",
    aspect: "interpretation alternative",
    bug: "P_ER held, whatever is declared, and a held P_ER keeps the contact off",
    machines: replacing("cp1e-time-compare", (m, c) => new ErHeld(m, c)),
  },
  "cp1e-past-area-compared": {
    family: "cp1e-time-compare",
    aspect: "flag",
    bug: "S1 or S2 past the end of the data area compared, the missing words read as 0",
    machines: replacing("cp1e-time-compare", pastAreaCompared),
  },
  "cp1e-nibble-above-9": { family: "cp1e-time-compare", aspect: "flag", bug: "a nibble of 10 compared as BCD, and P_ER turned on as well", machines: replacing("cp1e-time-compare", (m, c) => new NibbleAbove9(m, c)) },
};

/** The mutant as an Implementation, following `choices` like the reference. */
export function mutant(name: string, choices: Readonly<Record<string, string>> = {}): Implementation {
  const m = MUTANTS[name];
  if (m === undefined) throw new Error(`no mutant ${JSON.stringify(name)}; known: ${Object.keys(MUTANTS).sort().join(", ")}`);
  return machineImplementation(`plcvec-reference (TypeScript, mutant ${name})`, m.machines, choices);
}
