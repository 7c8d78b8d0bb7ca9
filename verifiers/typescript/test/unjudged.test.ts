/**
 * Devices left unjudged (schema 1.1, verifiers/parity/TEXT.md and CONTRACT.md): an alternatives
 * entry's `unjudged` map, on a hand-made vector until the golden set has some. The vector is the
 * golden `flags-on-before` TADD vector whose `set-only` entry is made to expect what the default
 * expects, except that it leaves D300 and D301 unjudged.
 */
import assert from "node:assert/strict";
import { test } from "node:test";

import { expectedOf, loadSuite, runVectors, summaryText, VerifyError, type Implementation, type Vector } from "../src/index.js";
import { sameExpectation } from "../src/infer.js";
import { reference } from "../src/reference/index.js";
import { familyLines, writeFamily } from "./helpers.js";

const ID = "fx5-time-add/TADD/carry/below-wrap/flags-on-before";
const SET_ONLY = { "TADD-FLAGS-OFF": "set-only" } as const;

/** The family file holding the hand-made vector alone (and a 1.1 header); `edit` changes its `set-only` entry. */
function handMade(edit: (entry: Record<string, unknown>) => void = () => undefined): string {
  const lines = familyLines("fx5-time-add");
  const header = { ...(JSON.parse(lines[0]!) as Record<string, unknown>), schema_version: "1.1.0" };
  const vector = JSON.parse(lines.find((l) => l.includes(`"id":"${ID}"`))!) as Vector & Record<string, unknown>;
  const drop = (devices: Record<string, unknown>) => Object.fromEntries(Object.entries(devices).filter(([d]) => d !== "D300" && d !== "D301"));
  const entry: Record<string, unknown> = {
    choices: SET_ONLY,
    expect: vector.steps.map((s) => ({ ...s.expect, devices: drop(s.expect.devices) })),
    final: { devices: drop(vector.final.devices) },
    outcome: { category: "value" },
    unjudged: { "TADD-FLAGS-OFF": ["D300", "D301"] },
  };
  edit(entry);
  return writeFamily("fx5-time-add", [JSON.stringify(header), JSON.stringify({ ...vector, alternatives: [entry] })]);
}

/** The reference's answer (written-each-execution, which the entry expects too) with `devices` written over step 0. */
function answering(devices: Record<string, number | boolean>, choices: Readonly<Record<string, string>> = {}): Implementation {
  const ref = reference();
  return {
    name: "hand-made",
    choices,
    run(request) {
      const answer = ref.run(request);
      if (!("steps" in answer)) return answer;
      return { steps: answer.steps.map((s, i) => ({ ...s, devices: i === 0 ? { ...s.devices, ...devices } : { ...s.devices } })) };
    },
  };
}

test("a 1.1 file with an unjudged map loads; a malformed map is refused by vector id and path", () => {
  assert.equal(loadSuite(handMade()).vectors.length, 1);
  const refused = (edit: (entry: Record<string, unknown>) => void, message: string) =>
    assert.throws(() => loadSuite(handMade(edit)), (err: unknown) => err instanceof VerifyError && err.message.endsWith(`vector ${ID}: ${message}`));
  refused((e) => (e["unjudged"] = { "TADD-FLAGS-OFF": [] }), "alternatives/0/unjudged/TADD-FLAGS-OFF: not a non-empty list of devices");
  refused((e) => (e["unjudged"] = { "TADD-FLAGS-OFF": ["D300", "D300"] }), 'alternatives/0/unjudged/TADD-FLAGS-OFF/1: "D300" is listed twice');
  refused((e) => (e["unjudged"] = { "TADD-FLAGS-OFF": ["D 300"] }), 'alternatives/0/unjudged/TADD-FLAGS-OFF/0: "D 300" is not a device name');
  refused((e) => (e["unjudged"] = {}), "alternatives/0/unjudged: not a non-empty object of interpretation ids");
});

test("under the alternative that leaves them unjudged, those devices are never compared; the others are", () => {
  const suite = loadSuite(handMade());
  const anything = runVectors(answering({ D300: 7, D301: true }, SET_ONLY), { suite });
  assert.equal(anything.counts.pass, 1, summaryText(anything));
  const wrong = runVectors(answering({ D302: 5 }, SET_ONLY), { suite });
  assert.equal(wrong.counts.fail, 1);
  // The block says what is not judged, after `judged by:` (none here) and before the first step line.
  const lines = summaryText(wrong).split("\n");
  const at = lines.indexOf("    not judged under TADD-FLAGS-OFF=set-only: D300, D301");
  assert.ok(at > 0, summaryText(wrong));
  assert.equal(lines[at - 1], "    TADD: 23:00:00 + 00:00:00, flags on before the execution.");
  assert.equal(lines[at + 1], "    step 0 inputs: en=true");
  assert.match(lines[at + 2]!, /^ {4}step 0 operands: d D300=65535 65535 65535, s1 D100=23 0 0, s2 D200=0 0 0$/);
  assert.equal(lines[at + 3], "    step 0 D302: expected 0, got 5 (before the step: 65535)");
  // Under the default, D300 is judged as always, and the line does not appear.
  const byDefault = runVectors(answering({ D300: 7 }), { suite });
  assert.equal(byDefault.counts.fail, 1);
  assert.doesNotMatch(summaryText(byDefault), /not judged under/);
});

test("judged by: an interpretation whose other alternative leaves the differing field unjudged decides it", () => {
  // D300 is expected 23 under both alternatives; set-only leaves it unjudged, so it decides the line.
  const report = runVectors(answering({ D300: 7 }), { suite: loadSuite(handMade()) });
  assert.match(summaryText(report), /^ {4}judged by: TADD-FLAGS-OFF=written-each-execution\n {4}step 0 inputs: en=true\n/m);
});

test("the inference: a passing vector passes under another combination only where that one judges what the followed one judges alike", () => {
  const vector = loadSuite(handMade()).byId.get(ID)!;
  const defaults = { "TADD-FLAGS-OFF": "written-each-execution" };
  const byDefault = expectedOf(vector, defaults, defaults);
  const setOnly = expectedOf(vector, SET_ONLY, defaults);
  assert.deepEqual(setOnly.unjudged, { "TADD-FLAGS-OFF": ["D300", "D301"] });
  // Followed the default: under set-only D300 and D301 are not judged, the rest is alike.
  assert.equal(sameExpectation(setOnly, byDefault), true);
  // Followed set-only: the default judges D300, whose answer the set-only expectation does not know.
  assert.equal(sameExpectation(byDefault, setOnly), false);
});
