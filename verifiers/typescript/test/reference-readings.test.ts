/**
 * The reference follows the alternative it is given: worked examples of the readings TADD-OVERLAP,
 * FX5-INVALID-S3-DEVICE-RANGE and CP1E-PAST-AREA-END, each value worked by hand from the
 * alternative's text, and, for every interpretation of the suite, a reference that declares an
 * alternative but keeps to the default is caught by the vectors.
 */
import assert from "node:assert/strict";
import { describe, test } from "node:test";

import { type Devices, type Implementation, interpretationsOf, loadSuite, type Operand, runVectors, type StepInputs } from "../src/index.js";
import { reference } from "../src/reference/index.js";

const suite = loadSuite();

/** One step of `instruction` on `devices` through the reference's run, as the runner calls it; its devices and result. */
function runOnce(
  choices: Readonly<Record<string, string>>,
  family: string,
  instruction: string,
  sizes: Readonly<Record<string, number>>,
  devices: Devices,
  operands: Readonly<Record<string, Operand>>,
  step: StepInputs,
): { devices: Devices; result?: boolean } {
  const outcome = reference(choices).run({ id: "worked", family, instruction, assumes: { device_sizes: sizes }, initial: { devices, operands }, steps: [step] });
  assert.ok("steps" in outcome, JSON.stringify(outcome));
  return outcome.steps[0]!;
}

const FX5_SIZES = { D: 8000, SD: 12000 };

describe("TADD-OVERLAP: (d) sharing words with (s1) at another offset", () => {
  // (s1) D10..D12 = 10:30:50, (s2) D20..D22 = 3:40:20; 10:30:50 + 3:40:20 = 14:11:10, no carry.
  const devices = (d: number): Devices => {
    const image: Record<string, number | boolean> = { D10: 10, D11: 30, D12: 50, D20: 3, D21: 40, D22: 20, SD0: 0, SD8067: 0, SM700: false, SM8020: false, SM8022: false };
    for (let k = 0; k < 3; k++) image[`D${d + k}`] ??= 0;
    return image;
  };
  const tadd = (alternative: string, d: number): Devices =>
    runOnce({ "TADD-OVERLAP": alternative }, "fx5-time-add", "TADD", FX5_SIZES, devices(d), { s1: { device: "D10" }, s2: { device: "D20" }, d: { device: `D${d}` } }, { en: true }).devices;
  const words = (image: Devices, from: number, to: number): unknown[] => {
    const out: unknown[] = [];
    for (let n = from; n <= to; n++) out.push(image[`D${n}`]);
    return out;
  };

  test("sources-first: the sum of the times held before the execution, wherever (d) lies", () => {
    // (d) = (s1)-1: D9..D11 = 14:11:10, D12 untouched.
    assert.deepEqual(words(tadd("sources-first", 9), 9, 12), [14, 11, 10, 50]);
    // (d) = (s1)+1: D11..D13 = 14:11:10, D10 untouched.
    assert.deepEqual(words(tadd("sources-first", 11), 10, 13), [10, 14, 11, 10]);
  });

  test("second-first: a source word after (d)'s written second holds it", () => {
    // (d) = (s1)-1 = D9. Seconds: D12 50 + D22 20 = 70 -> D11 := 10, carry 1. Minutes: D11 (now 10)
    // + D21 40 = 50, +1 = 51 -> D10 := 51, carry 0. Hours: D10 (now 51) + D20 3 = 54 -> D9 := 54 mod 24 = 6.
    // Sum as read: 54 h + 50 min + 70 s = 197470 s, past 24:00:00: 197470 - 86400 x 2 = 24670 s = 6:51:10, carry.
    const image = tadd("second-first", 9);
    assert.deepEqual(words(image, 9, 12), [6, 51, 10, 50]);
    assert.deepEqual([image["SM700"], image["SM8022"], image["SM8020"]], [true, true, false]);
    // (d) = (s1)+1 = D11: every source word is read before (d) overwrites it, so 14:11:10 as sources-first.
    assert.deepEqual(words(tadd("second-first", 11), 10, 13), [10, 14, 11, 10]);
  });

  test("hour-first: a source word after (d)'s written plain sums holds them", () => {
    // (d) = (s1)+1 = D11. Hours: D10 10 + D20 3 = 13 -> D11 := 13. Minutes: D11 (now 13) + D21 40 = 53
    // -> D12 := 53. Seconds: D12 (now 53) + D22 20 = 73 -> D13 := 73. Settled: 13 h + 53 min + 73 s =
    // 50053 s = 13:54:13, no carry, not zero.
    const image = tadd("hour-first", 11);
    assert.deepEqual(words(image, 10, 13), [10, 13, 54, 13]);
    assert.deepEqual([image["SM700"], image["SM8022"], image["SM8020"]], [false, false, false]);
    // (d) = (s1)-1 = D9: D9 and D10 are written after D10 was read, D11 after D11: 14:11:10 as sources-first.
    assert.deepEqual(words(tadd("hour-first", 9), 9, 12), [14, 11, 10, 50]);
  });
});

describe("FX5-INVALID-S3-DEVICE-RANGE: a reserved (s3) bit with (s1) past the device range", () => {
  // (s1) D7998: its third word, D8000, is past D0..D7999. (s3) = 0008H: bit 3, reserved.
  const compare = (alternative: string, instruction: string, step: StepInputs): { devices: Devices; result?: boolean } =>
    runOnce(
      { "FX5-INVALID-S3-DEVICE-RANGE": alternative },
      "fx5-time-compare",
      instruction,
      FX5_SIZES,
      { D7998: 11, D7999: 29, D200: 11, D201: 29, D202: 29, SM709: false },
      { s1: { device: "D7998" }, s2: { device: "D200" }, s3: { constant: 0x0008 } },
      step,
    );

  test("device-range-first: SM709 on and non-continuity", () => {
    const out = compare("device-range-first", "LDTM=", {});
    assert.deepEqual([out.result, out.devices["SM709"]], [false, true]);
  });

  test("s3-first: non-continuity, SM709 untouched", () => {
    const out = compare("s3-first", "LDTM=", {});
    assert.deepEqual([out.result, out.devices["SM709"]], [false, false]);
    // In an OR form the non-conductive contact leaves a conducting rung conducting.
    const or = compare("s3-first", "ORTM=", { rlo_in: true });
    assert.deepEqual([or.result, or.devices["SM709"]], [true, false]);
  });

  test("s3-first leaves a selecting (s3) to the device range", () => {
    const out = runOnce(
      { "FX5-INVALID-S3-DEVICE-RANGE": "s3-first" },
      "fx5-time-compare",
      "LDTM=",
      FX5_SIZES,
      { D7998: 11, D7999: 29, D200: 11, D201: 29, D202: 29, SM709: false },
      { s1: { device: "D7998" }, s2: { device: "D200" }, s3: { constant: 0x0007 } },
      {},
    );
    assert.deepEqual([out.result, out.devices["SM709"]], [false, true]);
  });
});

describe("CP1E-PAST-AREA-END: S1 at the last word of D", () => {
  // D0..D8191; S1 = D8191, so S1+1 and S1+2 are past the end. The data would compare equal.
  const flags = { P_ER: false, P_EQ: false, P_NE: true, P_LT: true, P_LE: true, P_GT: false, P_GE: false };
  const compare = (alternative: string, instruction: string, step: StepInputs): { devices: Devices; result?: boolean } =>
    runOnce(
      { "CP1E-PAST-AREA-END": alternative },
      "cp1e-time-compare",
      instruction,
      { D: 8192, A: 754 },
      { D8191: 0, D100: 0, D101: 0, D102: 0, ...flags },
      { S1: { device: "D8191" }, S2: { device: "D100" }, C: { constant: 0 } },
      step,
    );

  test("error: P_ER on, an OFF execution condition, the six flags kept (CP1E-ERROR-FLAGS=kept)", () => {
    const out = compare("error", "LD =DT", {});
    assert.deepEqual(out.result, false);
    assert.deepEqual(out.devices, { D8191: 0, D100: 0, D101: 0, D102: 0, ...flags, P_ER: true });
  });

  test("program-error: not executed, nothing written, an OFF execution condition", () => {
    const out = compare("program-error", "LD =DT", {});
    assert.deepEqual(out.result, false);
    assert.deepEqual(out.devices, { D8191: 0, D100: 0, D101: 0, D102: 0, ...flags });
    // Combined like any OFF condition: OR keeps a conducting rung conducting, AND turns it off.
    assert.equal(compare("program-error", "OR =DT", { rlo_in: true }).result, true);
    assert.equal(compare("program-error", "AND =DT", { rlo_in: true }).result, false);
  });
});

describe("a reference that declares an alternative but keeps to the default is caught", () => {
  // The vectors judge by the declaration: for every alternative, some vector of its families
  // expects what only that alternative does, so ignoring it fails. An alternative under which the
  // page leaves a device undefined (its vectors leave the device unjudged) is the exception: what
  // the default does there is as good as anything.
  const unjudging = new Set(suite.vectors.flatMap((v) => (v.alternatives ?? []).flatMap((a) => Object.keys(a.unjudged ?? {}).map((id) => `${id}=${a.choices[id]}`))));
  for (const info of interpretationsOf(suite).values()) {
    for (const alternative of info.alternatives.filter((a) => a !== info.default && !unjudging.has(`${info.id}=${a}`))) {
      test(`${info.id}=${alternative}`, () => {
        const selection = { families: info.families };
        const follows = reference({ [info.id]: alternative });
        assert.ok(runVectors(follows, { suite, selection }).passed, `the reference following ${info.id}=${alternative} fails`);
        const ignores = reference();
        const declaresOnly: Implementation = { name: `declares ${info.id}=${alternative}`, choices: { [info.id]: alternative }, run: (r) => ignores.run(r) };
        const report = runVectors(declaresOnly, { suite, selection });
        assert.equal(report.passed, false, `${info.id}=${alternative} declared, the default followed, and every vector passed`);
        assert.ok(report.verdicts.some((v) => v.status === "fail"));
      });
    }
  }
});
