/**
 * The names plcvec 0.1.0 published under which the API now has others (VOCABULARY.md's names), kept
 * working until 0.3.0 so that a pinned project upgrades without breaking; each says what replaces
 * it. CHANGES.md lists them under Deprecated.
 */
import { parseShard, type Selection } from "./selection.js";
import { emulate, type Emulator } from "./emulator.js";
import { VerifyError } from "./errors.js";
import type { Implementation } from "./implementation.js";
import { summaryText } from "./reports.js";
import type { Report } from "./runner.js";
import { setting } from "./settings.js";
import type { InterpretationInfo } from "./suite.js";
import { describe, type Verdict } from "./verdict.js";

/** @deprecated since 0.2.0, until 0.3.0: use `VerifyError` (the error's `name` is now "VerifyError"). */
export const PlcvecError = VerifyError;
/** @deprecated since 0.2.0, until 0.3.0: use `VerifyError`. */
export type PlcvecError = VerifyError;

/** @deprecated since 0.2.0, until 0.3.0: use `InterpretationInfo`. */
export type Interpretation = InterpretationInfo;

/** @deprecated since 0.2.0, until 0.3.0: use `Emulator`. */
export type MemoryImplementation = Emulator;

/** @deprecated since 0.2.0, until 0.3.0: use `Verdict` (its `applied` is now `judgedBy`). */
export type VectorResult = Verdict;

/** @deprecated since 0.2.0, until 0.3.0: use `emulate`. */
export function executeOnMemory(impl: MemoryImplementation): Implementation {
  return emulate(impl);
}

/** @deprecated since 0.2.0, until 0.3.0: use `describe(verdict, vector, reading)`, which adds the step's inputs and operands. */
export function describeResult(r: VectorResult): string {
  return describe(r);
}

/** @deprecated since 0.2.0, until 0.3.0: use `summaryText`. */
export function formatReport(report: Report): string {
  return summaryText(report);
}

/**
 * @deprecated since 0.2.0, until 0.3.0: `cases`, `vectorTests` and `runVectors` read PLCVEC_SHARD
 * and the rest of the PLCVEC_* selection themselves (`environmentSelection` gives it).
 */
export function withEnvironmentShard(selection: Selection = {}): Selection {
  const shard = setting("PLCVEC_SHARD");
  if (selection.shard !== undefined || shard === undefined) return selection;
  return { ...selection, shard: parseShard(shard) };
}
