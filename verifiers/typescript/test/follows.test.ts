/**
 * The alternatives a reference machine follows: one frozen record of every interpretation, the
 * declared alternative or the suite's default, with one V8 shape for every declaration (a machine
 * reads it by literal ids, each a load at a fixed offset only while the record is a fast object).
 */
import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import { fileURLToPath } from "node:url";
import { test } from "node:test";

import { INTERPRETATIONS, type InterpretationId } from "../src/index.js";
import { followsOf } from "../src/reference/machine.js";

const IDS = Object.keys(INTERPRETATIONS) as InterpretationId[];

test("every interpretation: the declared alternative, else the default; frozen; a record it made is its own answer", () => {
  const declared = { "FX5-SM709-SCOPE": "all-words", "TADD-OVERLAP": "hour-first" };
  const follows = followsOf(declared);
  assert.deepEqual(Object.keys(follows), IDS);
  for (const id of IDS) {
    const want = (declared as Record<string, string>)[id] ?? INTERPRETATIONS[id].default;
    assert.equal(follows[id], want, id);
  }
  assert.ok(Object.isFrozen(follows));
  assert.equal(followsOf(follows), follows);
  const defaults = followsOf({});
  assert.equal(followsOf(follows), follows, "an earlier record is still its own answer after another was made");
  assert.equal(defaults["FX5-SM709-SCOPE"], INTERPRETATIONS["FX5-SM709-SCOPE"].default);
});

test("a declaration changed after a record was made gives a new record, not the old one", () => {
  const declared: Record<string, string> = { "CP1E-NON-BCD": "error" };
  assert.equal(followsOf(declared)["CP1E-NON-BCD"], "error");
  declared["CP1E-NON-BCD"] = "raw-bytes";
  assert.equal(followsOf(declared)["CP1E-NON-BCD"], "raw-bytes");
});

test("the record is a fast object, of one shape for every declaration (V8's own answer)", () => {
  const machine = fileURLToPath(new URL("../src/reference/machine.js", import.meta.url));
  const names = fileURLToPath(new URL("../src/index.js", import.meta.url));
  const script = `
    const { followsOf } = await import(${JSON.stringify(machine)});
    const { INTERPRETATIONS } = await import(${JSON.stringify(names)});
    const some = {};
    for (const [id, i] of Object.entries(INTERPRETATIONS)) some[id] = i.alternatives.at(-1);
    const a = followsOf({}), b = followsOf(some);
    console.log(JSON.stringify([%HasFastProperties(a), %HasFastProperties(b), %HaveSameMap(a, b)]));`;
  const out = execFileSync(process.execPath, ["--allow-natives-syntax", "--input-type=module", "-e", script], { encoding: "utf8" });
  assert.deepEqual(JSON.parse(out), [true, true, true]);
});
