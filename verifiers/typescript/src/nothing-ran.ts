/**
 * A test run in which no plcvec vector ran tested nothing, whatever the test runner counts: the
 * reporters (plcvec/reporter for node:test, plcvec/vitest-reporter) fail such a run.
 */
import { FAMILIES } from "./generated/names.js";

/** Whether a test is a vector's: named by a vector id, which starts with its family. */
export function isVectorName(name: string | undefined): boolean {
  const id = name?.replace(/^'/, ""); // Vitest 4 quotes a name made from a string by test.each's "$id"
  return id !== undefined && FAMILIES.some((f) => id.startsWith(`${f}/`));
}

/** What a run in which no vector ran says. */
export const NOTHING_RAN =
  "no plcvec vector ran, so nothing was tested: no test file was found (node --test runs *.test.js files: compile TypeScript " +
  "first), none runs the vectors, or a filter (--test-name-pattern, vitest -t) left every vector out; the run fails";
