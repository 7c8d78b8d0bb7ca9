/** Loading refuses, by file, line and vector id, what the contract cannot run. */
import assert from "node:assert/strict";
import { writeFileSync } from "node:fs";
import { join, dirname } from "node:path";
import { test } from "node:test";
import { fileURLToPath } from "node:url";

import { loadSuite, VerifyError, SUITE } from "../src/index.js";
import { editedFamily, familyLines, writeFamily } from "./helpers.js";

test("the packaged copy holds the whole suite the names were generated with", () => {
  const suite = loadSuite();
  assert.equal(suite.vectors.length, SUITE.total);
  assert.equal(suite.suiteVersion, SUITE.suiteVersion);
  assert.equal(suite.specSha256, SUITE.specSha256);
  assert.equal(new Set(suite.vectors.map((v) => v.id)).size, suite.vectors.length);
});

test("the repository's vectors/ folder (manifest.json + *.json) loads to the same vectors", () => {
  const repoVectors = join(dirname(fileURLToPath(import.meta.url)), "../../../../vectors");
  const fromRepo = loadSuite(repoVectors);
  const packaged = loadSuite();
  assert.deepEqual(fromRepo.vectors.map((v) => v.id), packaged.vectors.map((v) => v.id));
  assert.deepEqual(fromRepo.byId.get(packaged.vectors[0]!.id), packaged.vectors[0]);
});

function refuses(path: string, pattern: RegExp): void {
  assert.throws(() => loadSuite(path), (err: unknown) => err instanceof VerifyError && pattern.test(err.message));
}

test("a word out of range is named with its line, vector id and JSON path", () => {
  const file = editedFamily("fx5-time-add", 3, 2, (v) => {
    ((v["initial"] as { devices: Record<string, number> }).devices)["D100"] = 70000;
  });
  const id = (JSON.parse(familyLines("fx5-time-add")[2]!) as { id: string }).id;
  refuses(file, new RegExp(`${file.replace(/[.*+?^${}()|[\]\\]/g, "\\$&")}:3: vector ${id.replace(/[.*+?^${}()|[\]\\]/g, "\\$&")}: initial/devices/D100: 70000 is not a word`));
});

test("a bit written as 1 in an expectation is refused", () => {
  const file = editedFamily("fx5-time-add", 2, 1, (v) => {
    (v["final"] as { devices: Record<string, unknown> }).devices["SM700"] = 1;
  });
  // 1 is a valid word, but SM700 is a bit everywhere else in the vector: the file's fault, not the implementation's.
  refuses(file, /:2: vector .*: final\/devices\/SM700: 1 is a word, but initial\/devices\/SM700 holds a bit/);
});

test("a vector without steps, a line that is not JSON, a missing header are refused", () => {
  refuses(editedFamily("fx5-time-add", 2, 1, (v) => { v["steps"] = []; }), /:2: vector .*: steps: missing or empty/);
  const lines = familyLines("fx5-time-add").slice(0, 3);
  lines[2] = "{not json";
  refuses(writeFamily("fx5-time-add", lines), /:3: not valid JSON/);
  refuses(writeFamily("fx5-time-add", familyLines("fx5-time-add").slice(1, 3)), /:1: not a plcvec family header/);
  refuses(writeFamily("fx5-time-add", []), /empty file/);
});

test("a vector of another family, and an id twice, are refused", () => {
  refuses(editedFamily("fx5-time-add", 2, 1, (v) => { v["family"] = "fc6a-hour-meter"; }), /family: "fc6a-hour-meter" in a "fx5-time-add" file/);
  const lines = familyLines("fx5-time-add").slice(0, 2);
  refuses(writeFamily("fx5-time-add", [...lines, lines[1]!]), /appears twice/);
});

test("a major schema version this runner does not read is refused", () => {
  const lines = familyLines("fx5-time-add").slice(0, 2);
  lines[0] = JSON.stringify({ ...JSON.parse(lines[0]!), schema_version: "2.0.0" });
  refuses(writeFamily("fx5-time-add", lines), /schema_version 2\.0\.0 is not 1\.x/);
});

test("a damaged copy is caught by its index's sha256", () => {
  const file = writeFamily("fx5-time-add", familyLines("fx5-time-add"));
  writeFileSync(join(dirname(file), "index.json"), JSON.stringify({ families: { "fx5-time-add": { file: "fx5-time-add.jsonl", sha256: "0".repeat(64) } } }));
  refuses(dirname(file), /sha256 .* is not the 0{64} its listing gives/);
});

test("a folder that is not a vector set, and a missing path, are named", () => {
  refuses("/nonexistent/plcvec", /\/nonexistent\/plcvec: no such vector folder or file/);
  const file = writeFamily("x", ["{}"]);
  writeFileSync(join(dirname(file), "index.json"), "{}");
  refuses(dirname(file), /index\.json: no `families`/);
});
