/**
 * The reference implementation: a plain implementation of the five families, written from the
 * manual pages the way an emulator author would, that must pass every vector under every
 * combination of alternatives. It is also what the mutants break, one bug each.
 */
import { FAMILIES, type Implementation, Memory, type RunOutcome, type StepResult, type VectorRequest } from "../index.js";
import { Cp1eTimeCompare } from "./cp1e-dt.js";
import { HourMeter } from "./fc6a-hour.js";
import { Fx5CompareMachine } from "./fx5-compare.js";
import { TaddMachine } from "./fx5-tadd.js";
import { followsOf, type Machine } from "./machine.js";

export type MachineFactory = (mem: Memory, choices: Readonly<Record<string, string>>) => Machine;

/** Each family's machine. */
export const MACHINES: Readonly<Record<string, MachineFactory>> = {
  "fx5-time-compare": (mem, choices) => new Fx5CompareMachine(mem, choices),
  "fx5-date-compare": (mem, choices) => new Fx5CompareMachine(mem, choices).forDates(),
  "fx5-time-add": (mem, choices) => new TaddMachine(mem, choices),
  "fc6a-hour-meter": (mem, choices) => new HourMeter(mem, choices),
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

export { Cp1eTimeCompare, Fx5CompareMachine, HourMeter, TaddMachine };
export type { Machine };
