/** Every mutant is rejected by this runner, by name: a verifier that cannot fail proves nothing. */
import assert from "node:assert/strict";
import { describe, test } from "node:test";

import { FAMILIES, loadSuite, runVectors, type Implementation, type Report } from "../src/index.js";
import { MUTANTS, mutant, type Aspect } from "../src/mutants/index.js";
import { reference } from "../src/reference/index.js";
import { rollupLines } from "../src/reports.js";

const suite = loadSuite();

/** Each mutant judged over the whole suite once, its report read by the two tests that need it. */
const reports = new Map<string, Report>();
function wholeSuiteReport(name: string): Report {
  let report = reports.get(name);
  if (report === undefined) reports.set(name, (report = runVectors(mutant(name), { suite })));
  return report;
}

describe("each mutant is rejected", () => {
  for (const [name, m] of Object.entries(MUTANTS)) {
    test(name, () => {
      const report = wholeSuiteReport(name);
      assert.equal(report.passed, false, `${name} (${m.bug}) passed the whole suite`);
      const failing = report.verdicts.filter((r) => r.status === "fail");
      assert.ok(failing.length > 0, `${name} failed without a failing vector`);
      // A single-bug mutant of one family is caught by that family's vectors, and only fails there.
      const families = new Set(failing.map((r) => r.id.split("/")[0]));
      assert.ok(families.has(m.family), `${name} is not caught by any ${m.family} vector (caught in ${[...families].join(", ")})`);
      // A bug is never explained away: every reading the roll-up proposes for it is marked partial.
      const proposals = rollupLines(report).filter((l) => /^ {4} {0,5}\d+ {2}[A-Z0-9-]+=/.test(l) && !l.includes("(partial: "));
      assert.deepEqual(proposals, [], `${name}: a reading explains all of a bug of its families`);
    });
  }
});

test("the mutants cover every family and every comparison aspect", () => {
  const aspects: readonly Aspect[] = [
    "contact result",
    "changed word",
    "flag",
    "device that must stay unchanged",
    "write outside the vector",
    "interpretation alternative",
  ];
  const all = Object.values(MUTANTS);
  assert.ok(all.length >= 10);
  for (const family of FAMILIES) assert.ok(all.some((m) => m.family === family), `no mutant of ${family}`);
  for (const aspect of aspects) assert.ok(all.some((m) => m.aspect === aspect), `no mutant breaks the ${aspect}`);
});

test("an implementation that follows a reading passes once it declares it", () => {
  // The reference following CP1E-ER-FLAG=held: undeclared, it fails the CP1E vectors (the roll-up
  // proposes the reading, whole); declared, it passes them. The runner judges by the declaration.
  const selection = { families: ["cp1e-time-compare"] };
  const held = reference({ "CP1E-ER-FLAG": "held" });
  const undeclared = runVectors({ name: "follows held", run: (r) => held.run(r) }, { suite, selection });
  assert.equal(undeclared.passed, false);
  assert.ok(rollupLines(undeclared).includes("    declare: choices: { \"CP1E-ER-FLAG\": \"held\" }"), rollupLines(undeclared).join("\n"));
  assert.equal(runVectors(held, { suite, selection }).passed, true);
});

test("a write outside the vector is reported as such", () => {
  const report = runVectors(mutant("tadd-writes-past-range"), { suite, selection: { families: ["fx5-time-add"] } });
  const problems = report.verdicts.flatMap((r) => r.problems);
  assert.ok(problems.some((p) => p.expected === "<not in the vector>"), JSON.stringify(problems.slice(0, 3)));
});

/** The same implementation, its steps copied into plain objects: what a runner gets from an implementation of its own. */
function asPlainObjects(impl: Implementation): Implementation {
  return {
    name: impl.name,
    run(request) {
      const answer = impl.run(request);
      return "steps" in answer ? { steps: answer.steps.map((s) => ({ ...s, devices: { ...s.devices } })) } : answer;
    },
  };
}

test("every mutant is judged alike whether its steps are compared by slot or as plain objects", () => {
  for (const name of Object.keys(MUTANTS)) {
    const bySlot = wholeSuiteReport(name).verdicts;
    const byObject = runVectors(asPlainObjects(mutant(name)), { suite }).verdicts;
    assert.deepEqual(
      byObject.map((r) => [r.id, r.status, r.problems]),
      bySlot.map((r) => [r.id, r.status, r.problems]),
      name,
    );
  }
});
