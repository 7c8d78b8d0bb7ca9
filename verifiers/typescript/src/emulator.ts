/**
 * The thin helper for emulators that only want to implement "execute this instruction on my
 * memory": the loop over steps, the device image, `set`, and the report after each step are
 * done here, as CONTRACT.md says.
 */
import type { Implementation, RunOutcome, StepResult } from "./implementation.js";
import { Memory } from "./memory.js";
import type { StepInputs, VectorRequest } from "./vector.js";

export interface Execution {
  readonly instruction: string;
  readonly operands: VectorRequest["initial"]["operands"];
  readonly memory: Memory;
  readonly step: StepInputs;
  /** Lives for one vector: state the instruction keeps between scans (TADDP's previous EN, a timer's fraction). */
  readonly state: Record<string, unknown>;
}

/** An emulator that executes one instruction on its own memory, one scan at a time. */
export interface Emulator {
  readonly name: string;
  readonly version?: string;
  readonly instructions?: readonly string[];
  readonly choices?: Readonly<Record<string, string>>;
  /** Devices the CPU writes on its own account (Implementation.cpuWrites). */
  readonly cpuWrites?: readonly string[];
  /** Execute the instruction once; return the contact result for LD/AND/OR forms, nothing otherwise. */
  execute(execution: Execution): boolean | undefined;
}

/** An Implementation from an `execute` on a device image. */
export function emulate(emulator: Emulator): Implementation {
  return {
    name: emulator.name,
    ...(emulator.version !== undefined ? { version: emulator.version } : {}),
    ...(emulator.instructions !== undefined ? { instructions: emulator.instructions } : {}),
    ...(emulator.choices !== undefined ? { choices: emulator.choices } : {}),
    ...(emulator.cpuWrites !== undefined ? { cpuWrites: emulator.cpuWrites } : {}),
    run(request: VectorRequest): RunOutcome {
      const memory = Memory.forRequest(request);
      const state: Record<string, unknown> = {};
      const steps = new Array<StepResult>(request.steps.length);
      for (let i = 0; i < steps.length; i++) {
        const step = request.steps[i]!;
        memory.set(step.set);
        steps[i] = memory.report(emulator.execute({ instruction: request.instruction, operands: request.initial.operands, memory, step, state }));
      }
      return { steps };
    },
  };
}
