/**
 * node:test integration: one test per vector, named by its id, so `node --test
 * --test-name-pattern` selects vectors and every reporter (spec, TAP, JUnit) lists them.
 *
 *     // my-emulator.test.ts
 *     import { vectorTests } from "plcvec/node-test";
 *     vectorTests(myImplementation, { selection: { families: ["fx5-time-add"] } });
 *
 * A skipped vector is reported as skipped; a known failure as a todo. The run as a whole is
 * judged when the process exits, not by a test a filter could leave out: an empty selection,
 * a filter that matched no vector, nothing passed, more skipped than `maxSkipped` allows, a
 * stale known failure, or an implementation that ended the process half way each make the exit
 * status non-zero, with a line on stderr that says why. A gate never passes by accident.
 *
 * A mistake in the set-up (a vector file, a PLCVEC_* variable, a known-failures file, a declared
 * interpretation) is one line on stderr and a non-zero exit, not a stack trace.
 */
import { writeSync } from "node:fs";
import { describe, test } from "node:test";

import { cases, runReport, type Case, type CaseOptions } from "./cases.js";
import { summaryText } from "./reports.js";
import { VerifyError } from "./errors.js";
import type { Implementation } from "./implementation.js";
import { endChildrenHoldingOutput } from "./leftovers.js";
import { describe as describeVerdict } from "./verdict.js";

export interface VectorTestOptions extends CaseOptions {
  /** The name of the suite of tests (default: "plcvec: " and the implementation's name). */
  readonly name?: string;
}

/** The exit status of a mistake in the set-up (as `plcvec verify`'s); a run's own is its report's exitCode. */
const USAGE = 2;

function complain(lines: readonly string[], status: number): void {
  writeSync(2, lines.map((l) => `plcvec: ${l}\n`).join(""));
  if (!process.exitCode || process.exitCode === 0) process.exitCode = status;
}

export function vectorTests(impl: Implementation, options: VectorTestOptions = {}): void {
  let list: Case[];
  try {
    list = cases(impl, options);
  } catch (err) {
    if (!(err instanceof VerifyError)) throw err;
    complain([`error: ${err.message}`], USAGE);
    // Kept at exit too: the test runner sets the status it found when the file ends.
    process.on("exit", () => {
      if (!process.exitCode) process.exitCode = USAGE;
    });
    return;
  }
  describe(options.name ?? `plcvec: ${impl.name}`, () => {
    for (const c of list) {
      test(c.id, (t) => {
        const verdict = c.check();
        if (verdict.status === "skip") t.skip(verdict.message);
        else if (verdict.status === "xfail") t.todo(verdict.message);
      });
    }
  });
  process.on("exit", () => {
    // Under node --test, which reads this process's output until every holder has closed it.
    if (process.env["NODE_TEST_CONTEXT"] !== undefined) endChildrenHoldingOutput();
    let report;
    try {
      report = runReport(list);
    } catch (err) {
      if (!(err instanceof VerifyError)) throw err;
      complain([`error: ${err.message}`], USAGE);
      return;
    }
    // The rest of the run's text: each failure block was printed by its test, once.
    writeSync(2, summaryText(report, { blocks: false }));
    if (report.passed) return;
    const stale = report.verdicts.filter((v) => v.status === "stale" && !report.suite.byId.has(v.id)).map((v) => describeVerdict(v));
    if (stale.length || report.runProblems.length) {
      complain([...stale, ...report.runProblems.map((p) => `RUN FAILS: ${p}`)], report.exitCode);
    } else if (!process.exitCode) {
      process.exitCode = report.exitCode; // a failing vector: its test says so already
    }
  });
}
