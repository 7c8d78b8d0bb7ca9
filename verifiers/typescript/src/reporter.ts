/**
 * A node:test reporter that prints a plcvec run as `plcvec verify` does: each failing vector's
 * block once, then the run's text (the roll-up by reading, the skips, the interpretations followed
 * and the totals), then node:test's own counts.
 *
 *     node --test --test-reporter=plcvec/reporter
 *
 * Why a reporter of its own: node's `spec` reporter prints each failing test twice (where it fails
 * and again in its closing list of failures), and `dot` prints each once but drops what a test file
 * writes on stderr, where `vectorTests` writes the run's text when the file's process ends.
 * Tests that are not vectors are reported too: a failure with its error, a pass as one line.
 *
 * A run in which no vector ran (no test file found, which is what `node --test` on uncompiled
 * TypeScript finds, or a file without vectorTests) fails: node:test alone says `tests 0` and exits 0.
 */
import { inspect } from "node:util";

import { isVectorName, NOTHING_RAN } from "./nothing-ran.js";

/** The members of node:test's reporter events this reporter reads (node 20 and later). */
interface EventData {
  readonly name?: string;
  readonly nesting?: number;
  readonly message?: unknown;
  readonly todo?: unknown;
  readonly skip?: unknown;
  readonly details?: { readonly error?: unknown; readonly type?: string };
}

interface TestEvent {
  readonly type: string;
  readonly data: EventData;
}

/** What a test threw: node wraps it (`ERR_TEST_FAILURE`) with the thrown error as its `cause`. */
function thrown(error: unknown): { failureType: string | undefined; cause: unknown } {
  if (error !== null && typeof error === "object") {
    const e = error as { failureType?: string; cause?: unknown };
    return { failureType: e.failureType, cause: e.cause ?? error };
  }
  return { failureType: undefined, cause: error };
}

function indented(text: string): string {
  return text
    .split("\n")
    .map((line) => (line ? `    ${line}` : line))
    .join("\n");
}

/** The text of one failed test, or "" when the failure says nothing of its own. */
export function failureText(data: EventData): string {
  const { failureType, cause } = thrown(data.details?.error);
  // A suite or the whole-run test fails because tests under it failed: each was printed already.
  if (failureType === "subtestsFailed") return "";
  const c = cause as { name?: unknown; message?: unknown } | null;
  if (c !== null && typeof c === "object" && c.name === "VectorFailure" && typeof c.message === "string") {
    return c.message.endsWith("\n") ? c.message : `${c.message}\n`; // the vector's block, as plcvec verify prints it
  }
  const what = typeof c?.message === "string" && c.message !== "" ? c.message : inspect(cause);
  return `✖ ${data.name ?? "(unnamed test)"}\n${indented(what)}\n`;
}

export default async function* plcvecReporter(source: AsyncIterable<TestEvent>): AsyncGenerator<string> {
  const counts: string[] = [];
  let vectors = 0;
  let failed = false;
  for await (const event of source) {
    const data = event.data;
    if (event.type === "test:fail" && !data.todo && !data.skip) failed = true;
    // A vector that ran: passed, failed, or a known failure (todo); one a filter left out is a skip.
    if ((event.type === "test:pass" || event.type === "test:fail") && !data.skip && isVectorName(data.name)) vectors++;
    switch (event.type) {
      case "test:fail":
        if (!data.todo && !data.skip) {
          const text = failureText(data);
          if (text) yield text;
        }
        break;
      case "test:pass":
        // A vector that passes says nothing, as under plcvec verify; a test of the user's own, and a
        // suite, a line (a vector's test is one of a file's `vectorTests`, under its whole-run test).
        if (data.details?.type === "suite" || (data.nesting ?? 0) === 0) yield `✔ ${data.name ?? ""}\n`;
        break;
      case "test:stdout":
      case "test:stderr":
        if (typeof data.message === "string") yield data.message;
        break;
      case "test:diagnostic":
        // The run's counts (`tests 293`, `pass 173`, ...) are the diagnostics at the top level.
        if ((data.nesting ?? 0) === 0 && typeof data.message === "string") counts.push(data.message);
        break;
      default:
        break;
    }
  }
  if (counts.length > 0) yield `node:test: ${counts.join(", ")}\n`;
  // A run that failed says why itself (a process ended half way reports no vector); one that did not
  // fail but ran no vector is the gate that tested nothing.
  if (vectors === 0 && !failed) {
    yield `plcvec/reporter: ${NOTHING_RAN}\n`;
    process.exitCode = 1;
  }
}
