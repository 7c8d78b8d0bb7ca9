/**
 * The suite as a plain list of test cases, for any test runner: `test.each` in Vitest or Jest,
 * or a loop of your own. Each case is named by its vector id; `check()` throws a VectorFailure
 * carrying the field-level diff when the implementation disagrees.
 *
 *     import { cases } from "plcvec";
 *     test.each(cases(myImplementation))("$id", (c) => c.check());
 */
import { PlcvecError } from "./errors.js";
import type { KnownFailures } from "./known.js";
import { loadSuite, type Suite } from "./load.js";
import { applyKnown, describeResult, judge, prepare, resolveChoices, type Implementation, type VectorResult } from "./run.js";
import { parseShard, select, type Selection } from "./select.js";

/** A vector the implementation does not pass; its message is the whole field-level diff, with no stack to read past. */
export class VectorFailure extends Error {
  override readonly name = "VectorFailure";
  constructor(message: string) {
    super(message);
    this.stack = `${this.name}: ${message}`;
  }
}

export interface CaseOptions {
  readonly suite?: Suite;
  readonly selection?: Selection;
  readonly known?: KnownFailures;
  /** A selection of no vector throws unless this is set. */
  readonly allowEmpty?: boolean;
}

export interface Case {
  readonly id: string;
  readonly family: string;
  readonly instruction: string;
  readonly tags: readonly string[];
  /** Run the vector and throw a VectorFailure with the diff unless it passes (or is a known failure that still fails). */
  check(): VectorResult;
}

/**
 * `PLCVEC_SHARD=K/N` in the environment picks a shard when the selection names none, so one test
 * file serves every job of a sharded CI matrix unchanged.
 */
export function withEnvironmentShard(selection: Selection = {}): Selection {
  const env = process.env["PLCVEC_SHARD"];
  if (selection.shard !== undefined || env === undefined || env === "") return selection;
  return { ...selection, shard: parseShard(env) };
}

/** One case per selected vector; expectations are worked out lazily, when a case runs. */
export function cases(impl: Implementation, options: CaseOptions = {}): Case[] {
  const suite = options.suite ?? loadSuite();
  const vectors = select(suite, withEnvironmentShard(options.selection));
  if (vectors.length === 0 && !options.allowEmpty) {
    throw new PlcvecError("the selection holds no vector: a gate that runs nothing would pass by accident (allowEmpty to accept that)");
  }
  const { choices, defaults } = resolveChoices(suite, impl.choices);
  return vectors.map((vector) => ({
    id: vector.id,
    family: vector.family,
    instruction: vector.instruction,
    tags: vector.tags,
    check(): VectorResult {
      const result = applyKnown(judge(prepare(vector, choices, defaults), impl), options.known);
      if (result.status === "fail" || result.status === "error" || result.status === "stale") {
        throw new VectorFailure(describeResult(result));
      }
      return result;
    },
  }));
}
