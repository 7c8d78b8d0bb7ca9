/**
 * The reference implementation: a plain implementation of the five families, written from the
 * manual pages the way an emulator author would, that must pass every vector under every
 * combination of alternatives. It is also what the mutants break, one bug each.
 */
import { FAMILIES, type Implementation, Memory, type RunOutcome, type StepResult, type VectorRequest } from "../index.js";
import { Cp1eTimeCompare } from "./cp1e-dt.js";
import { Fc6aHourMeter } from "./fc6a-hour.js";
import { Fx5Compare } from "./fx5-compare.js";
import { Fx5TimeAdd } from "./fx5-tadd.js";
import { followsOf, type Machine } from "./machine.js";

export type MachineFactory = (mem: Memory, choices: Readonly<Record<string, string>>) => Machine;

/** Each family's machine. */
export const MACHINES: Readonly<Record<string, MachineFactory>> = {
  "fx5-time-compare": (mem, choices) => new Fx5Compare(mem, choices),
  "fx5-date-compare": (mem, choices) => new Fx5Compare(mem, choices).forDates(),
  "fx5-time-add": (mem, choices) => new Fx5TimeAdd(mem, choices),
  "fc6a-hour-meter": (mem, choices) => new Fc6aHourMeter(mem, choices),
  "cp1e-time-compare": (mem, choices) => new Cp1eTimeCompare(mem, choices),
};

/** An Implementation running requests on the given machines (the reference's, or a mutant's). */
export function machineImplementation(
  name: string,
  machines: Readonly<Record<string, MachineFactory>>,
  choices: Readonly<Record<string, string>> = {},
): Implementation {
  // Every interpretation's alternative worked out once here, one record for every vector's machine.
  const follows = followsOf(choices);
  return {
    name,
    choices,
    run(request: VectorRequest): RunOutcome {
      const factory = machines[request.family];
      if (factory === undefined) return { skip: `no machine for family ${request.family}` };
      const mem = Memory.forRequest(request);
      const machine = factory(mem, follows);
      const steps = new Array<StepResult>(request.steps.length);
      for (let i = 0; i < steps.length; i++) {
        const step = request.steps[i]!;
        mem.set(step.set);
        const result = machine.execute(request.instruction, request.initial.operands, step);
        steps[i] = mem.report(machine.contact ? result === true : undefined);
      }
      return { steps };
    },
  };
}

/** The reference implementation, following `choices` (undeclared interpretations: their defaults). */
export function reference(choices: Readonly<Record<string, string>> = {}): Implementation {
  return machineImplementation("plcvec-reference (TypeScript)", MACHINES, choices);
}

/** Every family has a machine: checked when the module loads, so a new family cannot be forgotten. */
for (const family of FAMILIES) {
  if (MACHINES[family] === undefined) throw new Error(`the reference has no machine for ${family}`);
}

export { Cp1eTimeCompare, Fc6aHourMeter, Fx5Compare, Fx5TimeAdd };
export type { Machine };

// The machines' names before 0.3.0, each kept as a value (`new`, `extends`, `instanceof`) and as a
// type, so that code written against them still compiles until 0.4.0.

/** @deprecated since 0.3.0: use Fx5Compare; removed in 0.4.0. */
export const Fx5CompareMachine = Fx5Compare;
/** @deprecated since 0.3.0: use Fx5Compare; removed in 0.4.0. */
export type Fx5CompareMachine = Fx5Compare;

/** @deprecated since 0.3.0: use Fx5TimeAdd; removed in 0.4.0. */
export const TaddMachine = Fx5TimeAdd;
/** @deprecated since 0.3.0: use Fx5TimeAdd; removed in 0.4.0. */
export type TaddMachine = Fx5TimeAdd;

/** @deprecated since 0.3.0: use Fc6aHourMeter; removed in 0.4.0. */
export const HourMeter = Fc6aHourMeter;
/** @deprecated since 0.3.0: use Fc6aHourMeter; removed in 0.4.0. */
export type HourMeter = Fc6aHourMeter;
