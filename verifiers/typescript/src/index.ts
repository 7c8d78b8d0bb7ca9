/**
 * plcvec: conformance test vectors for PLC clock and calendar instructions, and the runner that
 * judges an implementation against them exactly as verifiers/CONTRACT.md says.
 *
 *     import { runVectors, formatReport } from "plcvec";
 *     const report = runVectors(myImplementation);
 *     console.log(formatReport(report));
 *
 * Test-runner integration: `plcvec/node-test` (one node:test test per vector) and `cases()`
 * below (a plain iterable for `test.each` in Vitest or Jest).
 */
export * from "./generated/names.js";
export { compare, problemLine, type Problem } from "./compare.js";
export { PlcvecError } from "./errors.js";
export { expectedOf, type Expected } from "./expect.js";
export { loadKnownFailures, parseKnownFailures, type KnownFailure, type KnownFailures } from "./known.js";
export { defaultVectorsPath, interpretationsOf, loadSuite, PACKAGED_VECTORS, SCHEMA_MAJOR, type Interpretation, type Suite } from "./load.js";
export { executeOnMemory, Memory, MemoryStep, type Execution, type MemoryImplementation } from "./memory.js";
export {
  applyKnown,
  describeResult,
  formatReport,
  judge,
  prepare,
  requestOf,
  resolveChoices,
  runVectors,
  summarize,
  type Implementation,
  type Prepared,
  type Report,
  type RunOptions,
  type Status,
  type VectorResult,
} from "./run.js";
export { crc32, globToRegExp, parseShard, select, shardOf, type Selection } from "./select.js";
export { cases, VectorFailure, withEnvironmentShard, type Case, type CaseOptions } from "./cases.js";
export type * from "./types.js";
