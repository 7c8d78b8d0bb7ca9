/**
 * What an implementation receives: a vector without its expectations, prepared once per vector
 * with what running it needs resolved (its initial device image, the parts it shares with other
 * vectors interned and frozen). Apart from vector.ts, so that the vector model stays a leaf that
 * the expectation (expect.ts) and the layouts (layout.ts) import without a circle.
 */
import { expectedLayout } from "./expect.js";
import { internString, interned } from "./intern.js";
import { InitialImage, layoutOf } from "./layout.js";
import type { Initial, StepInputs, Vector, VectorRequest } from "./vector.js";

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
