/**
 * The PLCVEC_* settings (CONTRACT.md, "The environment"): the warnings for an old name and a
 * misspelling, word for word as CONTRACT.md prints them, the old name read as the new one, and
 * PLCVEC_TIMEOUT's one rule.
 */
import assert from "node:assert/strict";
import { spawnSync } from "node:child_process";
import { readFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { test } from "node:test";
import { fileURLToPath } from "node:url";

import { timeoutSeconds, VerifyError } from "../src/index.js";
import { setting, settingWarnings } from "../src/settings.js";

const here = dirname(fileURLToPath(import.meta.url));
const contract = readFileSync(join(here, "..", "..", "..", "CONTRACT.md"), "utf8");
/** The warning lines CONTRACT.md prints, without the `plcvec: ` prefix. */
const printed = contract.split("\n").filter((l) => l.startsWith("plcvec: warning: ")).map((l) => l.slice("plcvec: ".length));

test("the warnings are CONTRACT.md's lines, one per variable, in variable order", () => {
  assert.equal(printed.length, 4, "CONTRACT.md shows four warning lines");
  assert.deepEqual(settingWarnings({ PLCVEC_EXPECTATIONS: "k.toml" }), [printed[0]]);
  assert.deepEqual(settingWarnings({ PLCVEC_EXPECTATIONS: "k.toml", PLCVEC_KNOWN_FAILURES: "k.toml" }), [printed[1]]);
  assert.deepEqual(settingWarnings({ PLCVEC_TAGG: "boundary" }), [printed[2]]);
  const [colour] = settingWarnings({ PLCVEC_COLOUR: "red" });
  assert.ok(colour!.startsWith(printed[3]!.replace(/, \.\.\.$/, ", ")), colour);
  assert.match(colour!, /the settings are PLCVEC_VECTORS, PLCVEC_ID, .*, PLCVEC_TIMEOUT$/);
  // Names plcvec's own tools use, and PLCVEC_TEST_*, are no misspellings; sorted by variable.
  assert.deepEqual(settingWarnings({ PLCVEC_HOSTILE: "x", PLCVEC_TEST_ANYTHING: "1", PLCVEC_FAMILY: "x" }), []);
  assert.deepEqual(
    settingWarnings({ PLCVEC_TAGG: "b", PLCVEC_FAMILLY: "a" }).map((w) => w.split(" ")[1]),
    ["PLCVEC_FAMILLY", "PLCVEC_TAGG"],
  );
  // The nearest by edit distance (at most 3), the old name counting as its replacement.
  assert.deepEqual(settingWarnings({ PLCVEC_EXPECTATION: "k" }), ["warning: PLCVEC_EXPECTATION is not a plcvec setting; did you mean PLCVEC_KNOWN_FAILURES?"]);
});

test("PLCVEC_EXPECTATIONS is read as PLCVEC_KNOWN_FAILURES while that is not set", () => {
  assert.equal(setting("PLCVEC_KNOWN_FAILURES", { PLCVEC_EXPECTATIONS: "old.toml" }), "old.toml");
  assert.equal(setting("PLCVEC_KNOWN_FAILURES", { PLCVEC_EXPECTATIONS: "old.toml", PLCVEC_KNOWN_FAILURES: "new.toml" }), "new.toml");
  assert.equal(setting("PLCVEC_KNOWN_FAILURES", {}), undefined);
});

test("PLCVEC_TIMEOUT: digits with an optional fraction, above 0, at most 86400; anything else CONTRACT.md's message", () => {
  for (const [text, seconds] of [["10", 10], ["2.5", 2.5], ["0.5", 0.5], ["86400", 86400]] as const) {
    assert.equal(timeoutSeconds({ PLCVEC_TIMEOUT: text }), seconds);
  }
  assert.equal(timeoutSeconds({}), 10);
  for (const text of ["1e9", "1e12", "86401", "0", "0.0", "-1", "+2", " 2", "2.", ".5", "soon", "Infinity", "0x10"]) {
    assert.throws(
      () => timeoutSeconds({ PLCVEC_TIMEOUT: text }),
      (err: unknown) =>
        err instanceof VerifyError &&
        err.message === `PLCVEC_TIMEOUT=${text}: the bound must be a number of seconds above 0 and at most 86400, written as digits with an optional fraction (2, 0.5)`,
      text,
    );
  }
  // CONTRACT.md's own example, word for word.
  assert.ok(contract.includes("`PLCVEC_TIMEOUT=1e9: the bound must be a number of seconds above 0 and at most 86400, written as digits with an optional fraction (2, 0.5)`"));
});

test("each warning is printed once per run, through vectorTests and through runVectors alike", () => {
  const { NODE_TEST_CONTEXT: _, ...clean } = process.env;
  const env = { ...clean, PLCVEC_FAMILY: "fx5-time-add", PLCVEC_TAGG: "boundary", PLCVEC_EXPECTATIONS: join(here, "no-such.toml") };
  const line = "plcvec: warning: PLCVEC_TAGG is not a plcvec setting; did you mean PLCVEC_TAG?";
  const fixtures = join(here, "..", "fixtures");
  const underTest = spawnSync(process.execPath, ["--test", "--test-reporter=spec", join(fixtures, "faults.test.js")], { env, encoding: "utf8", timeout: 120_000 });
  const inCode = spawnSync(process.execPath, [join(fixtures, "run-vectors.js")], { env, encoding: "utf8", timeout: 120_000 });
  for (const run of [underTest, inCode]) {
    const out = run.stdout + run.stderr;
    assert.equal(out.split(line).length - 1, 1, out.slice(-2000));
    // The old name is read: the file it names (missing) is the run's set-up mistake.
    assert.match(out, /PLCVEC_EXPECTATIONS is the old name of PLCVEC_KNOWN_FAILURES/);
    assert.match(out, /no-such\.toml: cannot read the expectations file/);
    assert.notEqual(run.status, 0);
  }
});
