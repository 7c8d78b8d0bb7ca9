/**
 * The test-runner integration and the stdio adapter, driven as a user drives them: node --test
 * on a test file of theirs, and the adapter process fed protocol lines.
 */
import assert from "node:assert/strict";
import { spawnSync } from "node:child_process";
import { mkdtempSync, readFileSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { dirname, join } from "node:path";
import { test } from "node:test";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const fixture = join(here, "..", "fixtures", "mutant-node-test.js");
const adapter = join(here, "..", "src", "bin", "reference-adapter.js");
const reporter = join(here, "..", "src", "reporter.js");
const BOUND = { timeout: 120_000, encoding: "utf8" as const, maxBuffer: 64 * 1024 * 1024 };

function nodeTest(args: string[], env: Record<string, string> = {}) {
  // Without NODE_TEST_CONTEXT: set by the runner running this file, it would make the child
  // report to us in the runner's own format instead of running as a user's `node --test` does.
  const { NODE_TEST_CONTEXT: _, ...clean } = process.env;
  return spawnSync(process.execPath, ["--test", "--test-reporter=spec", ...args, fixture], { ...BOUND, env: { ...clean, ...env } });
}

let plainRun: ReturnType<typeof nodeTest> | undefined;
/** `node --test` over the fixture as it stands, run once for the three tests that read it. */
function plainNodeTest() {
  return (plainRun ??= nodeTest([]));
}

test("node --test: a broken emulator fails, one test per vector named by its id, with the diff", () => {
  const run = plainNodeTest();
  assert.equal(run.status, 1, run.stdout);
  assert.match(run.stdout, /✖ fx5-time-add\/TADD\/[^\n]+/);
  assert.match(run.stdout, /step 0 D\d+: expected \d+, got \d+/);
  assert.match(run.stdout, /✔ fx5-time-add\/TADD\/manual-example\/program/);
});

test("node --test --test-reporter=plcvec/reporter: each failing vector's block once, then the run's text", () => {
  const { NODE_TEST_CONTEXT: _, ...clean } = process.env;
  const run = spawnSync(process.execPath, ["--test", `--test-reporter=${reporter}`, fixture], { ...BOUND, env: clean });
  assert.equal(run.status, 1, run.stdout + run.stderr);
  const failed = [...run.stdout.matchAll(/^FAIL (\S.*)$/gm)].map((m) => m[1]);
  assert.ok(failed.length > 0, run.stdout);
  assert.equal(new Set(failed).size, failed.length, "a failing vector's block printed twice");
  // The run's text, which the dot reporter drops (vectorTests writes it on stderr as the file ends).
  assert.match(run.stdout, /^(READINGS|NOT EXPLAINED by any reading): /m);
  const totals = /^(\d+) vectors: \d+ pass, (\d+) fail/m.exec(run.stdout);
  assert.ok(totals, run.stdout);
  assert.equal(Number(totals[2]), failed.length);
  assert.match(run.stdout, /^node:test: tests \d+, /m);
  // Under the spec reporter the same run shows each failing test in two places.
  const spec = plainNodeTest();
  const once = failed[0]!;
  assert.equal(spec.stdout.split(`FAIL ${once}\n`).length - 1, 2, "the spec reporter no longer repeats: update the README");
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
    return Number(/ℹ tests (\d+)/.exec(run.stdout)?.[1]);
  });
  const all = Number(/ℹ tests (\d+)/.exec(plainNodeTest().stdout)?.[1]);
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
    { id: "no-steps", family: "fx5-time-add", instruction: "TADD", initial: { devices: {}, operands: {} } },
    {
      id: "word-70000",
      family: "fx5-time-add",
      instruction: "TADD",
      initial: { devices: { D10: 70000 }, operands: { d: { device: "D30" }, s1: { device: "D10" }, s2: { device: "D20" } } },
      steps: [{ en: true }],
    },
  ],
});

test("the adapter answers hello, run and bye as PROTOCOL.md shows", () => {
  const run = adapterRun([HELLO, RUN, '{"type":"bye"}'].join("\n") + "\n", ["--choose", "TADD-EXACT-24=carry-above-24"]);
  assert.equal(run.status, 0, run.stderr);
  const [hello, result, broken, noSteps, word] = run.stdout.trim().split("\n").map((l) => JSON.parse(l) as Record<string, unknown>);
  assert.deepEqual(hello!["instructions"], ["TADD", "TADDP"]);
  assert.deepEqual(hello!["interpretations"], { "TADD-EXACT-24": "carry-above-24" });
  const devices = (result!["steps"] as { devices: Record<string, unknown> }[])[0]!.devices;
  assert.deepEqual([devices["D30"], devices["D31"], devices["D32"]], [13, 40, 15]);
  // A request of the wrong shape is answered as an error naming it and where, never run nor echoed.
  assert.deepEqual(broken, { type: "result", id: "broken", error: "the request for broken is not a vector the protocol sends: at initial/devices: not an object of devices" });
  assert.deepEqual(noSteps, { type: "result", id: "no-steps", error: "the request for no-steps is not a vector the protocol sends: at steps: missing or empty" });
  assert.deepEqual(word, {
    type: "result",
    id: "word-70000",
    error: "the request for word-70000 is not a vector the protocol sends: at initial/devices/D10: 70000 is not a word (an integer 0..65535) nor a bit",
  });
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

const faults = join(here, "..", "fixtures", "faults.test.js");
const TADD_EXAMPLE = "fx5-time-add/TADD/manual-example/program";

/** node --test over the faults fixture: a hostile implementation under vectorTests, as faults-entry runs it. */
function hostileRun(env: Record<string, string>, args: string[] = []) {
  const { NODE_TEST_CONTEXT: _, ...clean } = process.env;
  const run = spawnSync(process.execPath, ["--test", "--test-reporter=spec", ...args, faults], {
    ...BOUND,
    env: { ...clean, PLCVEC_FAMILY: "fx5-time-add", PLCVEC_HOSTILE_ON: TADD_EXAMPLE, ...env },
  });
  return { status: run.status, out: run.stdout + run.stderr };
}

test("no way out of the gate: an early exit, an abort, a loop, a filter of nothing, all skipped each fail naming why", () => {
  const cases: [Record<string, string>, string[], RegExp][] = [
    [{ PLCVEC_HOSTILE: "exit-zero" }, [], /plcvec: vector fx5-time-add\/TADD\/manual-example\/program: the implementation ended the process \(exit status 0\)/],
    [{ PLCVEC_HOSTILE: "crash" }, [], /plcvec: vector fx5-time-add\/TADD\/manual-example\/program: the implementation aborted the process/],
    [{ PLCVEC_HOSTILE: "loop-forever", PLCVEC_TIMEOUT: "0.5" }, [], /plcvec: vector fx5-time-add\/TADD\/manual-example\/program: no answer within 0.5 s \(PLCVEC_TIMEOUT\)/],
    [{}, ["--test-name-pattern=^nothing is called this$"], /none of the \d+ selected vectors ran: .*PLCVEC_ID=/],
    // The README's own pattern, with an implementation that skips everything: 0 passed is no pass.
    [{ PLCVEC_HOSTILE: "skips-everything" }, ["--test-name-pattern=fx5-time-add/TADDP/"], /RUN FAILS: nothing passed \(\d+ skipped\): the run proves nothing/],
    [{ PLCVEC_HOSTILE: "bad-choice" }, [], /plcvec: error: declared interpretation "NO-SUCH-INTERPRETATION" is not in the suite \(known: CP1E-/],
    [{ PLCVEC_FAMILY: "," }, [], /plcvec: error: PLCVEC_FAMILY=",": an empty name/],
    [{ PLCVEC_TIMEOUT: "0" }, [], /plcvec: error: PLCVEC_TIMEOUT=0: the bound must be a number of seconds above 0 and at most 86400/],
  ];
  for (const [env, args, pattern] of cases) {
    const run = hostileRun(env, args);
    assert.notEqual(run.status, 0, JSON.stringify(env) + run.out);
    assert.match(run.out, pattern, JSON.stringify(env));
    assert.doesNotMatch(run.out, /^\s+at .*\.js:\d+/m, `${JSON.stringify(env)}: no stack trace`);
  }
  assert.equal(hostileRun({}, ["--test-name-pattern=fx5-time-add/TADDP/"]).status, 0);
});

test("runVectors' guard names the vector an early exit, an abort or a loop happened on, and the run fails", () => {
  const fixture = join(here, "..", "fixtures", "run-vectors.js");
  const { NODE_TEST_CONTEXT: _, ...clean } = process.env;
  const run = (env: Record<string, string>) => {
    const r = spawnSync(process.execPath, [fixture], {
      ...BOUND,
      env: { ...clean, PLCVEC_FAMILY: "fx5-time-add", PLCVEC_HOSTILE_ON: TADD_EXAMPLE, ...env },
    });
    return { status: r.status, signal: r.signal, out: r.stdout + r.stderr };
  };
  const cases: [Record<string, string>, RegExp][] = [
    [{ PLCVEC_HOSTILE: "exit-zero" }, /plcvec: vector fx5-time-add\/TADD\/manual-example\/program: the implementation ended the process \(exit status 0\)/],
    [{ PLCVEC_HOSTILE: "crash" }, /plcvec: vector fx5-time-add\/TADD\/manual-example\/program: the implementation aborted the process/],
    [{ PLCVEC_HOSTILE: "loop-forever", PLCVEC_TIMEOUT: "0.5" }, /plcvec: vector fx5-time-add\/TADD\/manual-example\/program: no answer within 0.5 s \(PLCVEC_TIMEOUT\)/],
  ];
  for (const [env, pattern] of cases) {
    const r = run(env);
    assert.ok(r.status !== 0, `${JSON.stringify(env)}: the run must fail (status ${r.status}, signal ${r.signal})\n${r.out}`);
    assert.match(r.out, pattern, JSON.stringify(env));
  }
  // The same fixture with the reference passes: what fails above is the hostile implementation.
  const plain = run({});
  assert.equal(plain.status, 0, plain.out);
});

test("known failures under node:test: an id the suite does not have is stale; a listed failure passes; the file is written", () => {
  const dir = mkdtempSync(join(tmpdir(), "plcvec-known-"));
  const known = join(dir, "known.toml");
  writeFileSync(known, '[[known-failure]]\nid = "fx5-time-add/TADD/no-such-vector"\nreason = "listed by mistake"\n');
  const stale = hostileRun({ PLCVEC_KNOWN_FAILURES: known });
  assert.notEqual(stale.status, 0);
  assert.match(stale.out, /STALE fx5-time-add\/TADD\/no-such-vector\n.*the suite has no such vector/);
  const written = join(dir, "written.toml");
  const failing = hostileRun({ PLCVEC_HOSTILE: "wrong-result", PLCVEC_WRITE_EXPECTATIONS: written });
  assert.equal(failing.status, 1);
  assert.equal(readFileSync(written, "utf8").match(/^id = .*$/gm)?.join(), `id = "${TADD_EXAMPLE}"`);
  assert.equal(hostileRun({ PLCVEC_HOSTILE: "wrong-result", PLCVEC_KNOWN_FAILURES: written }).status, 0);
});

test("plcvec/reporter fails a run in which no vector ran: no test file (TypeScript not compiled), or none calling vectorTests", () => {
  const { NODE_TEST_CONTEXT: _, ...clean } = process.env;
  const empty = mkdtempSync(join(tmpdir(), "plcvec-ts-empty-"));
  // What a newcomer has before compiling: a TypeScript test file, which node --test on Node 20 does not run.
  writeFileSync(join(empty, "emulator.test.ts"), 'import { vectorTests } from "plcvec/node-test";\n');
  const nothing = spawnSync(process.execPath, ["--test", `--test-reporter=${reporter}`], { ...BOUND, cwd: empty, env: clean });
  assert.equal(nothing.status, 1, nothing.stdout + nothing.stderr);
  assert.match(nothing.stdout, /^plcvec\/reporter: no plcvec vector ran, so nothing was tested/m);
  // A test file of the user's own that runs no vector: green under node:test, not under plcvec/reporter.
  writeFileSync(join(empty, "other.test.mjs"), 'import { test } from "node:test";\ntest("not a vector", () => {});\n');
  const other = spawnSync(process.execPath, ["--test", `--test-reporter=${reporter}`], { ...BOUND, cwd: empty, env: clean });
  assert.equal(other.status, 1, other.stdout + other.stderr);
  assert.match(other.stdout, /✔ not a vector/);
});
