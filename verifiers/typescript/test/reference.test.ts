/**
 * The reference implementation passes every vector under every combination of the alternatives
 * of its family's interpretations: the evidence that the suite, this runner and the reference agree.
 */
import assert from "node:assert/strict";
import { describe, test } from "node:test";

import { summaryText, interpretationsOf, loadSuite, runVectors } from "../src/index.js";
import { reference } from "../src/reference/index.js";

const suite = loadSuite();

function* combinations(options: readonly (readonly [string, readonly string[]])[]): Generator<Record<string, string>> {
  if (options.length === 0) {
    yield {};
    return;
  }
  const [[id, alternatives], ...rest] = options as [readonly [string, readonly string[]], ...(readonly [string, readonly string[]])[]];
  for (const alt of alternatives) for (const tail of combinations(rest)) yield { [id]: alt, ...tail };
}

describe("the reference under every combination of alternatives", () => {
  for (const family of suite.headers.keys()) {
    test(family, () => {
      const interps = [...interpretationsOf(suite, [family]).values()].map((i) => [i.id, i.alternatives] as const);
      let runs = 0;
      for (const choices of combinations(interps)) {
        const report = runVectors(reference(choices), { suite, selection: { families: [family] } });
        assert.ok(report.passed, `${JSON.stringify(choices)}\n${summaryText(report)}`);
        assert.equal(report.counts.pass, report.verdicts.length);
        runs++;
      }
      assert.equal(runs, interps.reduce((n, [, alts]) => n * alts.length, 1));
    });
  }
});
