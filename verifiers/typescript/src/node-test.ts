/**
 * node:test integration: one test per vector, named by its id, so `node --test
 * --test-name-pattern` selects vectors and every reporter (spec, TAP, JUnit) lists them.
 *
 *     // my-emulator.test.ts
 *     import { vectorTests } from "plcvec/node-test";
 *     vectorTests(myImplementation, { selection: { families: ["fx5-time-add"] } });
 *
 * A skipped vector is reported as skipped; a known failure as a todo; and a closing test fails
 * the run when the selection was empty, when nothing passed, or when more were skipped than
 * `maxSkipped` allows: a gate never passes by accident.
 */
import { describe, test } from "node:test";

import { cases, type CaseOptions } from "./cases.js";
import type { Implementation } from "./run.js";
import { summarize } from "./run.js";
import type { VectorResult } from "./run.js";
import { loadSuite } from "./load.js";

export interface VectorTestOptions extends CaseOptions {
  /** The name of the suite of tests (default: "plcvec: " and the implementation's name). */
  readonly name?: string;
  readonly maxSkipped?: number | `${number}%`;
}

export function vectorTests(impl: Implementation, options: VectorTestOptions = {}): void {
  const suite = options.suite ?? loadSuite();
  const list = cases(impl, { ...options, suite });
  const results: VectorResult[] = [];
  describe(options.name ?? `plcvec: ${impl.name}`, () => {
    for (const c of list) {
      test(c.id, (t) => {
        const result = c.check();
        results.push(result);
        if (result.status === "skip") t.skip(result.message);
        else if (result.status === "xfail") t.todo(result.message);
      });
    }
    test("plcvec: the selection ran and passed as a whole", () => {
      const report = summarize(impl.name, results, suite, {}, options);
      if (report.runProblems.length) throw new Error(report.runProblems.join("; "));
    });
  });
}
