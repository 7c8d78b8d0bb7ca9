/**
 * plcvec: conformance test vectors for PLC clock and calendar instructions, and the runner that
 * judges an implementation against them exactly as verifiers/CONTRACT.md says.
 *
 *     import { runVectors, summaryText } from "plcvec";
 *     const report = runVectors(myImplementation);
 *     console.log(summaryText(report));
 *
 * Test-runner integration: `plcvec/node-test` (one node:test test per vector) and `cases()`
 * below (a plain list for Vitest or Jest).
 */
export * from "./generated/names.js";
export { checkRun, cases, runReport, VectorFailure, type Case, type CaseOptions } from "./cases.js";
export { resolveChoices, type Followed } from "./choices.js";
export { compare, cpuWritesOf, judge, prepare, type Prepared } from "./compare.js";
export { emulate, type Execution, type Emulator } from "./emulator.js";
export { VerifyError } from "./errors.js";
export { expectedOf, type Expected } from "./expect.js";
export type { Implementation, RunOutcome, StepResult } from "./implementation.js";
export {
  applyKnown,
  loadKnownFailures,
  parseKnownFailures,
  unknownIds,
  writeExpectations,
  type KnownFailure,
  type KnownFailures,
} from "./known.js";
export { Memory, MemoryStep } from "./memory.js";
export { declaration, summaryText, type DeclarationSyntax } from "./reports.js";
export { runVectors, summarize, type Report, type RunOptions } from "./runner.js";
export {
  crc32,
  environmentSelection,
  globToRegExp,
  parseShard,
  select,
  selectWithEnvironment,
  shardOf,
  type Selection,
} from "./selection.js";
export { serve } from "./serve.js";
export { defaultVectorsPath, interpretationsOf, loadSuite, PACKAGED_VECTORS, SCHEMA_MAJOR, type InterpretationInfo, type Suite } from "./suite.js";
export { describe, FAILING, NOT_IN_VECTOR, NOT_REPORTED, problemLine, type Problem, type Status, type Verdict } from "./verdict.js";
export { requestOf } from "./request.js";
export type { AlternativeExpectation, Devices, FamilyHeader, Initial, InterpretationHeader, Operand, Outcome, Step, StepExpect, StepInputs, Value, Vector, VectorRequest } from "./vector.js";
export { DEFAULT_TIMEOUT_SECONDS, timeoutSeconds } from "./settings.js";
export {
  describeResult,
  executeOnMemory,
  formatReport,
  PlcvecError,
  withEnvironmentShard,
  type Interpretation,
  type MemoryImplementation,
  type VectorResult,
} from "./deprecated.js";
