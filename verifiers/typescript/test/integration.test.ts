/**
 * The test-runner integration and the stdio adapter, driven as a user drives them: node --test
 * on a test file of theirs, and the adapter process fed protocol lines.
 */
import assert from "node:assert/strict";
import { spawnSync } from "node:child_process";
import { dirname, join } from "node:path";
import { test } from "node:test";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const fixture = join(here, "..", "fixtures", "mutant-node-test.js");
const adapter = join(here, "..", "src", "bin", "reference-adapter.js");
const BOUND = { timeout: 120_000, encoding: "utf8" as const, maxBuffer: 64 * 1024 * 1024 };

function nodeTest(args: string[], env: Record<string, string> = {}) {
  // Without NODE_TEST_CONTEXT: set by the runner running this file, it would make the child
  // report to us in the runner's own format instead of running as a user's `node --test` does.
  const { NODE_TEST_CONTEXT: _, ...clean } = process.env;
  return spawnSync(process.execPath, ["--test", "--test-reporter=spec", ...args, fixture], { ...BOUND, env: { ...clean, ...env } });
}

test("node --test: a broken emulator fails, one test per vector named by its id, with the diff", () => {
  const run = nodeTest([]);
  assert.equal(run.status, 1, run.stdout);
  assert.match(run.stdout, /✖ fx5-time-add\/TADD\/[^\n]+/);
  assert.match(run.stdout, /step 0 D\d+: expected \d+, got \d+/);
  assert.match(run.stdout, /✔ fx5-time-add\/TADD\/manual-example\/program/);
});

test("node --test --test-name-pattern selects vectors by id", () => {
  const run = nodeTest(["--test-name-pattern=manual-example/program$"]);
  assert.equal(run.status, 0, run.stdout + run.stderr);
  assert.match(run.stdout, /✔ fx5-time-add\/TADD\/manual-example\/program/);
  assert.doesNotMatch(run.stdout, /✔ fx5-time-add\/TADD\/carry/);
});

test("PLCVEC_SHARD=K/N runs one shard of the selection, as every plcvec runner splits it", () => {
  const counts = [1, 2].map((k) => {
    const run = nodeTest([], { PLCVEC_SHARD: `${k}/2` });
    return Number(/ℹ tests (\d+)/.exec(run.stdout)?.[1]) - 1; // less the closing test of the run
  });
  const all = Number(/ℹ tests (\d+)/.exec(nodeTest([]).stdout)?.[1]) - 1;
  assert.ok(counts[0]! > 0 && counts[1]! > 0, JSON.stringify(counts));
  assert.equal(counts[0]! + counts[1]!, all);
  const bad = nodeTest([], { PLCVEC_SHARD: "3/2" });
  assert.notEqual(bad.status, 0);
  assert.match(bad.stdout + bad.stderr, /shard takes K\/N/);
});

test("node --test: an empty selection fails the file instead of passing it", () => {
  const run = nodeTest([], { PLCVEC_TEST_FAMILY: "no-such-family" });
  assert.notEqual(run.status, 0);
  assert.match(run.stdout + run.stderr, /unknown family "no-such-family"/);
});

function adapterRun(input: string, args: string[] = []) {
  return spawnSync(process.execPath, [adapter, ...args], { ...BOUND, input });
}

const HELLO = JSON.stringify({
  type: "hello",
  protocol: 1,
  families: { "fx5-time-add": { instructions: ["TADD", "TADDP"], interpretations: { "TADD-EXACT-24": { default: "carry-at-24", alternatives: ["carry-at-24", "carry-above-24"] } } } },
});
// The manual's example program: 10:30:10 + 3:10:05 = 13:40:15 in D30..D32 (PROTOCOL.md's transcript).
const RUN = JSON.stringify({
  type: "run",
  batch: 0,
  vectors: [
    {
      id: "fx5-time-add/TADD/manual-example/program",
      family: "fx5-time-add",
      instruction: "TADD",
      assumes: { device_sizes: { D: 8000, R: 32768, SD: 12000 } },
      initial: {
        devices: { D10: 10, D11: 30, D12: 10, D20: 3, D21: 10, D22: 5, D30: 65535, D31: 65535, D32: 65535, SD0: 0, SD8067: 0, SM700: false, SM8020: false, SM8022: false },
        operands: { d: { device: "D30" }, s1: { device: "D10" }, s2: { device: "D20" } },
      },
      steps: [{ en: true }],
    },
    { id: "broken", family: "fx5-time-add", instruction: "TADD", initial: {}, steps: [{ en: true }] },
  ],
});

test("the adapter answers hello, run and bye as PROTOCOL.md shows", () => {
  const run = adapterRun([HELLO, RUN, '{"type":"bye"}'].join("\n") + "\n", ["--choose", "TADD-EXACT-24=carry-above-24"]);
  assert.equal(run.status, 0, run.stderr);
  const [hello, result, broken] = run.stdout.trim().split("\n").map((l) => JSON.parse(l) as Record<string, unknown>);
  assert.deepEqual(hello!["instructions"], ["TADD", "TADDP"]);
  assert.deepEqual(hello!["interpretations"], { "TADD-EXACT-24": "carry-above-24" });
  const devices = (result!["steps"] as { devices: Record<string, unknown> }[])[0]!.devices;
  assert.deepEqual([devices["D30"], devices["D31"], devices["D32"]], [13, 40, 15]);
  assert.equal(broken!["id"], "broken");
  assert.match(String(broken!["error"]), /TypeError|Error/);
});

test("the adapter survives malformed input with a fatal answer and a non-zero exit, never a crash", () => {
  for (const input of ["not json\n", "[1,2]\n", '{"type":"dance"}\n', '{"type":"run","vectors":7}\n', '{"type":"hello","protocol":99}\n']) {
    const run = adapterRun(input);
    assert.equal(run.status, 1, `${input}: ${run.stderr}`);
    const answer = JSON.parse(run.stdout.trim()) as Record<string, unknown>;
    assert.equal(answer["type"], "fatal", input);
    assert.doesNotMatch(run.stderr, /at .*\.js:\d+/, "no stack trace");
  }
  const bad = adapterRun("", ["--mutant", "nope"]);
  assert.equal(bad.status, 2);
  assert.match(bad.stderr, /no mutant "nope"; known: cp1e-er-held/);
});
