/**
 * The shapes of a vector file (verifiers/CONTRACT.md; schema vectors/schema/vector-file.schema.json).
 * A word is an integer 0..65535 (the raw 16 bits); a bit is true/false, never 1.
 *
 * `requestOf` gives what an implementation receives: the vector without its expectations, prepared
 * once per vector with what running it needs resolved.
 */
import { expectedLayout } from "./expect.js";
import { internString, interned } from "./intern.js";
import { InitialImage, layoutOf } from "./layout.js";

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

/**
 * A request prepared from a vector. Its fields are the contract's and nothing else (it prints,
 * serializes and spreads as them); it is also, privately, the vector's initial device image, whose
 * layout covers every device the vector names, so that Memory.forRequest copies an array.
 * The parts equal across vectors (operands, steps, device sizes) are shared; all but the vector's
 * own `initial.devices` is frozen.
 */
class PreparedRequest extends InitialImage implements VectorRequest {
  readonly id: string;
  readonly family: string;
  readonly instruction: string;
  readonly assumes: VectorRequest["assumes"];
  readonly initial: Initial;
  readonly steps: readonly StepInputs[];

  constructor(vector: Vector) {
    const image = InitialImage.of(expectedLayout(vector), vector.initial.devices);
    super(image.layout, image.values);
    this.id = vector.id;
    this.family = internString(vector.family);
    this.instruction = internString(vector.instruction);
    this.assumes = interned(vector.assumes);
    const { devices, operands, scratch } = vector.initial;
    this.initial = scratch === undefined ? { devices, operands: interned(operands) } : { devices, operands: interned(operands), scratch: interned(scratch) };
    this.steps = interned(vector.steps.map(({ expect: _expect, ...inputs }) => inputs));
    Object.freeze(this.initial);
    Object.freeze(this);
  }
}

/**
 * The part of a vector an implementation receives: everything needed to run it, no expectation.
 * Frozen, so one request per vector serves every run of it in a process.
 */
export function requestOf(vector: Vector): VectorRequest {
  let request = requests.get(vector);
  if (request === undefined) {
    request = new PreparedRequest(vector);
    requests.set(vector, request);
  }
  return request;
}

const requests = new WeakMap<Vector, VectorRequest>();

/** The initial image of a request: the one it was prepared with, or one worked out now (a request from elsewhere). */
export function initialImageOf(request: VectorRequest): InitialImage {
  if (request instanceof PreparedRequest) return request;
  const devices = request.initial.devices;
  return InitialImage.of(layoutOf(Object.keys(devices)), devices);
}
