/**
 * The shapes of a vector file (verifiers/CONTRACT.md; schema vectors/schema/vector-file.schema.json).
 * A word is an integer 0..65535 (the raw 16 bits); a bit is true/false, never 1.
 *
 * Types only, a leaf every module may import: `requestOf` (request.ts) prepares what an
 * implementation receives.
 */
export type Value = number | boolean;
export type Devices = Record<string, Value>;

export type Operand = { readonly device: string } | { readonly constant: number };

export interface StepInputs {
  /** Values written by the outside world before this execution. */
  readonly set?: Devices;
  /** The logic state before an AND/OR form (absent for LD forms). */
  readonly rlo_in?: boolean;
  /** The current clock, for current-time comparisons (the fields the family compares). */
  readonly clock?: Readonly<Record<string, number>>;
  /** The execution condition of TADD/TADDP. */
  readonly en?: boolean;
  /** The HOUR input this scan, and the milliseconds since its previous execution. */
  readonly input?: boolean;
  readonly elapsed_ms?: number;
}

export interface StepExpect {
  readonly result?: boolean;
  /** Exactly the devices whose value changed in this step (after `set`). */
  readonly devices: Devices;
}

export interface Step extends StepInputs {
  readonly expect: StepExpect;
}

export interface Outcome {
  readonly category: "value" | "error" | "implementation-defined";
  readonly errors?: readonly { readonly step: number; readonly code?: number; readonly device?: string }[];
  readonly interpretations?: readonly string[];
  readonly default?: Outcome;
  readonly reason?: string;
}

export interface AlternativeExpectation {
  readonly choices: Readonly<Record<string, string>>;
  /**
   * Interpretation id (one of `choices`) -> the devices its alternative leaves unjudged (schema
   * 1.1): listed in `initial.devices`, absent from this entry's `expect` and `final`, never compared.
   */
  readonly unjudged?: Readonly<Record<string, readonly string[]>>;
  readonly expect: readonly StepExpect[];
  readonly final: { readonly devices: Devices };
  readonly outcome: Outcome;
}

export interface Initial {
  readonly devices: Devices;
  readonly operands: Readonly<Record<string, Operand>>;
  /** Work-area words whose contents are the implementation's own; never compared. */
  readonly scratch?: readonly string[];
}

export interface Vector {
  readonly id: string;
  readonly family: string;
  readonly instruction: string;
  readonly st?: string;
  readonly description?: string;
  readonly tags: readonly string[];
  readonly clauses: readonly string[];
  readonly assumes: { readonly device_sizes: Readonly<Record<string, number>> };
  readonly initial: Initial;
  readonly steps: readonly Step[];
  readonly final: { readonly devices: Devices };
  readonly outcome: Outcome;
  readonly alternatives?: readonly AlternativeExpectation[];
}

export interface InterpretationHeader {
  readonly id: string;
  readonly question: string;
  readonly default: string;
  readonly alternatives: readonly { readonly id: string; readonly says: string }[];
}

/** A family file without its vectors: line 1 of its JSON Lines form. */
export interface FamilyHeader {
  readonly family: string;
  readonly schema_version: string;
  readonly spec_sha256: string;
  readonly title?: string;
  readonly kind?: string;
  readonly instructions: readonly string[];
  readonly tags: Readonly<Record<string, string>>;
  readonly interpretations: readonly InterpretationHeader[];
  readonly count?: number;
}

/** What an implementation receives: one vector without its expectations. */
export interface VectorRequest {
  readonly id: string;
  readonly family: string;
  readonly instruction: string;
  readonly assumes: { readonly device_sizes: Readonly<Record<string, number>> };
  readonly initial: Initial;
  readonly steps: readonly StepInputs[];
}
