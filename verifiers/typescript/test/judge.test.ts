/** Judging: exact values and JSON types, listed devices unchanged, no writes outside, known failures, the gate. */
import assert from "node:assert/strict";
import { writeFileSync, mkdtempSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { test } from "node:test";

import {
  describe,
  summaryText,
  loadKnownFailures,
  loadSuite,
  parseKnownFailures,
  VerifyError,
  requestOf,
  runVectors,
  type StepResult,
  type Implementation,
  type VectorRequest,
} from "../src/index.js";
import { reference } from "../src/reference/index.js";

const suite = loadSuite();
const ref = reference();
const MANUAL_TADD = "fx5-time-add/TADD/manual-example/program";

/** The reference with its answer to one vector edited. */
function edited(id: string, edit: (steps: { result?: boolean; devices: Record<string, unknown> }[]) => void): Implementation {
  return {
    name: "edited reference",
    run(request: VectorRequest) {
      const answer = ref.run(request);
      if (request.id !== id || !("steps" in answer)) return answer;
      const steps = answer.steps.map((s) => ({ ...s, devices: { ...s.devices } })) as { result?: boolean; devices: Record<string, unknown> }[];
      edit(steps);
      return { steps } as ReturnType<Implementation["run"]>;
    },
  };
}

const only = (id: string) => ({ suite, selection: { ids: [id] } });

test("the manual's TADD example passes: 10:30:10 + 3:10:05 = 13:40:15", () => {
  const report = runVectors(ref, only(MANUAL_TADD));
  assert.equal(report.counts.pass, 1);
  const v = suite.byId.get(MANUAL_TADD)!;
  assert.deepEqual([v.final.devices["D30"], v.final.devices["D31"], v.final.devices["D32"]], [13, 40, 15]);
});

test("a changed word is a field-level diff naming step, device, expected and actual", () => {
  const report = runVectors(edited(MANUAL_TADD, (s) => { s[0]!.devices["D31"] = 41; }), only(MANUAL_TADD));
  assert.equal(report.passed, false);
  const text = describe(report.verdicts[0]!);
  assert.match(text, /^FAIL fx5-time-add\/TADD\/manual-example\/program/);
  assert.match(text, /step 0 D31: expected 40, got 41 \(before the step: 65535\)/);
  assert.match(text, /clauses: fx5-time-add#/);
});

test("a bit reported as 1 fails, though 1 == true", () => {
  const report = runVectors(edited(MANUAL_TADD, (s) => { s[0]!.devices["SM700"] = 0; }), only(MANUAL_TADD));
  assert.match(describe(report.verdicts[0]!), /SM700: expected false, got 0/);
});

test("a device left out, and a device written outside the vector, are failures", () => {
  const missing = runVectors(edited(MANUAL_TADD, (s) => { delete s[0]!.devices["SD0"]; }), only(MANUAL_TADD));
  assert.match(describe(missing.verdicts[0]!), /SD0: expected 0, got <not reported>/);
  const outside = runVectors(edited(MANUAL_TADD, (s) => { s[0]!.devices["D33"] = 0; }), only(MANUAL_TADD));
  assert.match(describe(outside.verdicts[0]!), /D33: expected <not in the vector>, got 0/);
});

test("a device that must stay unchanged is said so", () => {
  const report = runVectors(edited(MANUAL_TADD, (s) => { s[0]!.devices["D10"] = 11; }), only(MANUAL_TADD));
  assert.match(describe(report.verdicts[0]!), /D10: expected 10, got 11 \(the step must leave it unchanged\)/);
});

test("a contact result is compared after every step, and the number of steps", () => {
  const id = suite.vectors.find((v) => v.family === "cp1e-time-compare" && v.instruction.startsWith("LD"))!.id;
  const flipped = runVectors(edited(id, (s) => { s[0]!.result = !s[0]!.result; }), only(id));
  assert.match(describe(flipped.verdicts[0]!), /step 0 result: expected (true|false), got (true|false)/);
  const short = runVectors(edited(id, (s) => { s.pop(); }), only(id));
  assert.match(describe(short.verdicts[0]!), /steps: expected 1 steps, got 0 steps/);
});

test("a reported step whose devices were read and then changed is judged by what they now hold", () => {
  const inPlace: Implementation = {
    name: "changed in place",
    run(request: VectorRequest) {
      const answer = ref.run(request);
      if ("steps" in answer) (answer.steps[0]!.devices as Record<string, unknown>)["D31"] = 41;
      return answer;
    },
  };
  assert.match(describe(runVectors(inPlace, only(MANUAL_TADD)).verdicts[0]!), /step 0 D31: expected 40, got 41/);
});

test("a step of the memory helper reads and serializes with its devices; a spread copy has none and fails", () => {
  const answer = ref.run(requestOf(suite.byId.get(MANUAL_TADD)!));
  assert.ok("steps" in answer);
  const step = answer.steps[0]!;
  assert.deepEqual([step.devices["D30"], step.devices["D31"], step.devices["D32"]], [13, 40, 15]);
  assert.deepEqual((JSON.parse(JSON.stringify(step)) as { devices: unknown }).devices, { ...step.devices });
  const spread: Implementation = {
    name: "spread",
    run(request: VectorRequest) {
      const a = ref.run(request);
      return "steps" in a ? { steps: a.steps.map((s) => ({ ...s }) as StepResult) } : a;
    },
  };
  assert.match(describe(runVectors(spread, only(MANUAL_TADD)).verdicts[0]!), /step 0 D31: expected 40, got <not reported>/);
});

test("the parts a request shares with other vectors cannot be written", () => {
  const writer: Implementation = {
    name: "writer",
    run(request: VectorRequest) {
      (request.initial.operands as Record<string, unknown>)["s1"] = { device: "D0" };
      return ref.run(request);
    },
  };
  const report = runVectors(writer, only(MANUAL_TADD));
  assert.equal(report.counts.error, 1);
  assert.match(describe(report.verdicts[0]!), /writer threw TypeError/);
  assert.equal(runVectors(ref, only(MANUAL_TADD)).passed, true);
});

test("an implementation that throws errors that vector; one that skips is skipped", () => {
  const thrower: Implementation = { name: "thrower", run: () => { throw new RangeError("no R devices"); } };
  const report = runVectors(thrower, only(MANUAL_TADD));
  assert.equal(report.counts.error, 1);
  // Located at the implementation's own line (this file), not at a frame of Node or a package.
  assert.match(describe(report.verdicts[0]!), /thrower threw RangeError: no R devices \(judge\.test\.js:\d+\)/);
});

test("the gate never passes by accident: empty selection, all skipped, too many skipped", () => {
  // Each filter matches, together they select nothing.
  const nothing = { families: ["fx5-time-add"], ids: ["fx5-time-compare/*"] };
  const empty = runVectors(ref, { suite, selection: nothing });
  assert.equal(empty.passed, false);
  assert.match(summaryText(empty), /NOT PASSED \(exit 5\): no vector selected: the selection matches nothing/);
  assert.equal(empty.exitCode, 5);
  assert.equal(runVectors(ref, { suite, selection: nothing, allowEmpty: true }).passed, true);

  const skipper: Implementation = { name: "skipper", run: () => ({ skip: "not yet" }) };
  const skipped = runVectors(skipper, { suite, selection: { families: ["fx5-time-add"] } });
  assert.equal(skipped.passed, false);
  assert.match(summaryText(skipped), /nothing passed \(\d+ skipped\): the run proves nothing/);

  const tadOnly: Implementation = { ...ref, name: "TADD only", instructions: ["TADD"] };
  const some = runVectors(tadOnly, { suite, selection: { families: ["fx5-time-add"] } });
  assert.equal(some.passed, true);
  assert.ok(some.counts.skip > 0);
  assert.equal(runVectors(tadOnly, { suite, selection: { families: ["fx5-time-add"] }, maxSkipped: 0 }).passed, false);
  assert.equal(runVectors(tadOnly, { suite, selection: { families: ["fx5-time-add"] }, maxSkipped: "100%" }).passed, true);
});

test("known failures: a listed failure is xfail, a listed pass is stale, an unknown id is stale", () => {
  const broken = edited(MANUAL_TADD, (s) => { s[0]!.devices["D31"] = 41; });
  const known = parseKnownFailures(`[[known-failure]]\nid = "${MANUAL_TADD}"\nreason = "minutes off by one (#7)"\n`, "known.toml");
  const xfail = runVectors(broken, { suite, selection: { families: ["fx5-time-add"] }, known });
  assert.equal(xfail.counts.xfail, 1);
  assert.equal(xfail.passed, true);
  const stale = runVectors(ref, { ...only(MANUAL_TADD), known });
  assert.equal(stale.counts.stale, 1);
  assert.equal(stale.passed, false);
  const ghost = parseKnownFailures(`[[known-failure]]\nid = "fx5-time-add/no/such"\nreason = "x"\n`, "k.toml");
  const r = runVectors(ref, { ...only(MANUAL_TADD), known: ghost });
  assert.equal(r.passed, false);
  assert.match(summaryText(r), /STALE fx5-time-add\/no\/such\n {4}listed as a known failure \(k\.toml:1\) but the suite has no such vector; remove it/);
});

test("a run of known failures alone proves nothing: not green, exit 5, 'nothing passed' (CONTRACT.md)", () => {
  const broken = edited(MANUAL_TADD, (s) => { s[0]!.devices["D31"] = 41; });
  const known = parseKnownFailures(`[[known-failure]]\nid = "${MANUAL_TADD}"\nreason = "minutes off by one"\n`, "known.toml");
  const report = runVectors(broken, { ...only(MANUAL_TADD), known });
  assert.deepEqual([report.counts.xfail, report.passed, report.exitCode], [1, false, 5]);
  assert.match(summaryText(report), /^NOT PASSED \(exit 5\): nothing passed \(1 known failures\): the run proves nothing/m);
  // Deprecated since 0.2.0: the 0.1.0 name of verdicts, not shown by a spread or JSON.
  assert.equal(report.results, report.verdicts);
  assert.equal(JSON.stringify(Object.keys(report)).includes('"results"'), false);
});

test("a value that is not a finite number is shown by its name, never as null (TEXT.md's values)", () => {
  for (const [value, shown] of [[NaN, "NaN"], [Infinity, "Infinity"], [-Infinity, "-Infinity"]] as const) {
    const r = runVectors(edited(MANUAL_TADD, (s) => { s[0]!.devices["D30"] = value; }), only(MANUAL_TADD));
    assert.match(summaryText(r), new RegExp(`step 0 D30: expected 13, got ${shown.replace("-", "\\-")} \\(before the step: 65535\\)`));
  }
});

test("a bad expectations file is named with its line", () => {
  const dir = mkdtempSync(join(tmpdir(), "plcvec-ts-known-"));
  const cases: [string, RegExp][] = [
    ['[[known-failure]]\nid = "a"\n', /k\.toml:1: a: every known failure needs a `reason`/],
    ['[[known-failure]]\nid = "a"\nreason = "r"\n[[known-failure]]\nid = "a"\nreason = "r"\n', /k\.toml:4: a is listed twice \(first at .*k\.toml:1\)/],
    ['[[known-failure]]\nid = "a"\nreason = "r"\npattern = "x"\n', /unknown key "pattern"/],
    ['skip = ["a"]\n', /k\.toml:1: unknown key "skip"/],
    ['[[known-failure]\n', /k\.toml:1: not valid TOML/],
  ];
  for (const [text, pattern] of cases) {
    const file = join(dir, "k.toml");
    writeFileSync(file, text);
    assert.throws(() => loadKnownFailures(file), (err: unknown) => err instanceof VerifyError && pattern.test(err.message), text);
  }
  assert.throws(() => loadKnownFailures(join(dir, "missing.toml")), /missing\.toml: cannot read the expectations file \(no such file\): ENOENT/);
});

test("declared alternatives are checked against the suite", () => {
  assert.throws(() => runVectors(reference({ "NO-SUCH": "x" }), only(MANUAL_TADD)), /declared interpretation "NO-SUCH" is not in the suite/);
  assert.throws(() => runVectors(reference({ "TADD-EXACT-24": "maybe" }), only(MANUAL_TADD)), /TADD-EXACT-24=maybe: no such alternative \(known: carry-at-24, carry-above-24\)/);
});
