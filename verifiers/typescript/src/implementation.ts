/**
 * The implementation interface (CONTRACT.md): one vector's initial state in, the state after each
 * step out. `emulate` (emulator.ts) builds one from an `execute` on a device image.
 */
import type { Devices, VectorRequest } from "./vector.js";

/** The state after one step: every listed device (plus any other written), and the contact result. */
export interface StepResult {
  readonly result?: boolean;
  readonly devices: Devices;
}

/** What an implementation answers for one vector. */
export type RunOutcome =
  | { readonly steps: readonly StepResult[] }
  | { readonly skip: string }
  | { readonly error: string };

export interface Implementation {
  /** Shown in reports. */
  readonly name: string;
  /** Shown in reports after the name. */
  readonly version?: string;
  /** The instructions it implements; vectors of any other are skipped. Default: all of them. */
  readonly instructions?: readonly string[];
  /** The alternative it follows for each interpretation (INTERPRETATIONS); undeclared ones take the default. */
  readonly choices?: Readonly<Record<string, string>>;
  /**
   * Devices its CPU writes on its own account (diagnostic relays and registers such as SM0, SD0):
   * a write to one of them outside the vector is not a stray write; one the vector lists is
   * compared as usual.
   */
  readonly cpuWrites?: readonly string[];
  /**
   * Run one vector from its own initial state (nothing carries over from another vector): apply
   * each step's `set`, execute, and report every listed device (and any other written) after it,
   * with the contact result for LD/AND/OR forms. Throwing counts as an error on that vector.
   */
  run(request: VectorRequest): RunOutcome;
}
