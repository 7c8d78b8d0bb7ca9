/** Loading refuses, by file, line and vector id, what the contract cannot run. */
import assert from "node:assert/strict";
import { spawnSync } from "node:child_process";
import { cpSync, mkdtempSync, readFileSync, rmSync, symlinkSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, dirname } from "node:path";
import { after, test } from "node:test";
import { fileURLToPath } from "node:url";

import { loadKnownFailures, loadSuite, PACKAGED_VECTORS, parseKnownFailures, runVectors, summaryText, VerifyError, SUITE } from "../src/index.js";
import { reference } from "../src/reference/index.js";
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

const escaped = (s: string): string => s.replace(/[.*+?^${}()|[\]\\]/g, "\\$&");

/** The copies of the packaged set the tests below make (6 MB each), removed when the file's tests end. */
const copies: string[] = [];
after(() => {
  for (const c of copies) rmSync(c, { recursive: true, force: true });
});

/** A copy of the packaged vector folder, with `edit` applied to its index.json text. */
function copiedSet(edit: (index: string) => string = (i) => i): string {
  const top = mkdtempSync(join(tmpdir(), "plcvec-ts-set-"));
  copies.push(top);
  const dir = join(top, "vectors");
  cpSync(PACKAGED_VECTORS, dir, { recursive: true });
  writeFileSync(join(dir, "index.json"), edit(readFileSync(join(dir, "index.json"), "utf8")));
  return dir;
}

test("what is not a regular file is refused by name before it is opened: a named pipe, a folder, a loop of links", () => {
  const dir = mkdtempSync(join(tmpdir(), "plcvec-ts-odd-"));
  const fifo = join(dir, "fx5-time-add.jsonl");
  assert.equal(spawnSync("mkfifo", [fifo]).status, 0);
  refuses(fifo, new RegExp(`^${escaped(fifo)}: not a regular file \\(a named pipe\\)$`));
  const loop = join(dir, "loop.jsonl");
  symlinkSync(join(dir, "loop2.jsonl"), loop);
  symlinkSync(loop, join(dir, "loop2.jsonl"));
  refuses(loop, new RegExp(`^${escaped(loop)}: a loop of symbolic links$`));
  // A family file the index names that is a folder, and an index that is a named pipe.
  const set = copiedSet();
  const family = join(set, "fx5-time-add.jsonl");
  spawnSync("rm", [family]);
  spawnSync("mkdir", [family]);
  refuses(set, new RegExp(`^${escaped(family)}: not a regular file \\(a folder\\)$`));
  const pipeIndex = copiedSet();
  spawnSync("rm", [join(pipeIndex, "index.json")]);
  assert.equal(spawnSync("mkfifo", [join(pipeIndex, "index.json")]).status, 0);
  refuses(pipeIndex, new RegExp(`^${escaped(join(pipeIndex, "index.json"))}: not a regular file \\(a named pipe\\)$`));
  // The known-failures file too.
  const knownPipe = join(dir, "known.toml");
  assert.equal(spawnSync("mkfifo", [knownPipe]).status, 0);
  assert.throws(() => loadKnownFailures(knownPipe), (err: unknown) => err instanceof VerifyError && err.message === `${knownPipe}: not a regular file (a named pipe)`);
});

test("the files this package ships hold no repeated key (so loading them again may skip that scan)", async () => {
  const { mayRepeatKeys, repeatedKey } = await import("../src/files.js");
  const { packagedSums } = await import("../src/suite.js");
  const index = JSON.parse(readFileSync(join(PACKAGED_VECTORS, "index.json"), "utf8")) as { families: Record<string, { file: string; sha256: string }> };
  assert.deepEqual([...packagedSums()].sort(), Object.values(index.families).map((f) => f.sha256).sort());
  let lines = 0;
  for (const { file } of Object.values(index.families)) {
    for (const line of readFileSync(join(PACKAGED_VECTORS, file), "utf8").trimEnd().split("\n")) {
      lines++;
      if (mayRepeatKeys(line, JSON.parse(line))) assert.equal(repeatedKey(line), undefined, `${file}: ${line.slice(0, 80)}`);
    }
  }
  assert.equal(lines, SUITE.total + Object.keys(index.families).length);
});

test("every vector of the files this package ships passes the schema check (so loading them again may skip it)", async () => {
  const { vectorProblem } = await import("../src/validate.js");
  const index = JSON.parse(readFileSync(join(PACKAGED_VECTORS, "index.json"), "utf8")) as { families: Record<string, { file: string }> };
  let vectors = 0;
  for (const [family, { file }] of Object.entries(index.families)) {
    for (const line of readFileSync(join(PACKAGED_VECTORS, file), "utf8").trimEnd().split("\n").slice(1)) {
      vectors++;
      assert.equal(vectorProblem(JSON.parse(line), family), undefined, `${file}: ${line.slice(0, 80)}`);
    }
  }
  assert.equal(vectors, SUITE.total);
});

test("an edited file in a copy of the packaged folder is checked in full: refused by line, vector id and JSON path, as any file", () => {
  const set = copiedSet();
  const file = join(set, "fx5-time-add.jsonl");
  const lines = readFileSync(file, "utf8").split("\n");
  const vector = JSON.parse(lines[2]!) as { id: string; initial: { devices: Record<string, number> } };
  vector.initial.devices["D100"] = 70000;
  lines[2] = JSON.stringify(vector);
  writeFileSync(file, lines.join("\n"));
  // The content is named before the sha256 the index gives (CONTRACT.md, Loading): its line, not the hash.
  assert.throws(
    () => loadSuite(set),
    (err: unknown) =>
      err instanceof VerifyError &&
      err.message === `${file}:3: vector ${vector.id}: initial/devices/D100: 70000 is not a word (an integer 0..65535) nor a bit`,
  );
});

test("a repeated key is refused by file, line and vector id, in a vector and in the index", () => {
  const lines = familyLines("fx5-time-add").slice(0, 4);
  const id = (JSON.parse(lines[2]!) as { id: string }).id;
  // The second "description" of the vector on line 3, with another value (JSON.parse keeps the last).
  lines[2] = lines[2]!.replace(/^\{/, '{"description": "first", ');
  const file = writeFamily("fx5-time-add", lines);
  refuses(file, new RegExp(`^${escaped(file)}:3: vector ${escaped(id)}: repeated key "description"$`));
  // A repeat in a nested object (a step's devices) is found as well.
  const nested = familyLines("fx5-time-add").slice(0, 3);
  assert.ok(nested[1]!.includes('"devices":{'));
  nested[1] = nested[1]!.replace('"devices":{', '"devices":{"D7":1,"D7":2,');
  const nestedFile = writeFamily("fx5-time-add", nested);
  refuses(nestedFile, new RegExp(`^${escaped(nestedFile)}:2: vector .*: repeated key "D7"$`));
  const set = copiedSet((index) => index.replace('"families": {', '"families": {\n  "fx5-time-add": {},'));
  refuses(set, new RegExp(`^${escaped(join(set, "index.json"))}:\\d+: repeated key "fx5-time-add"$`));
  // An escaped quote before a colon inside a string is no key: such a file loads.
  const quoted = familyLines("fx5-time-add").slice(0, 2);
  assert.match(quoted[1]!, /"description":"[^"]*"/);
  quoted[1] = quoted[1]!.replace(/"description":"[^"]*"/, '"description":"say \\"x\\": y"');
  assert.equal(loadSuite(writeFamily("fx5-time-add", quoted)).vectors[0]!.description, 'say "x": y');
});

test("a known failure whose id was merged names the vector it became, the index's map followed to its end", () => {
  const target = "fx5-time-add/TADD/manual-example/program";
  const set = copiedSet((index) => {
    const data = JSON.parse(index) as Record<string, unknown>;
    data["merged"] = { "fx5-time-add": { "fx5-time-add/TADD/old": "fx5-time-add/TADD/older", "fx5-time-add/TADD/older": target } };
    return JSON.stringify(data, null, 1) + "\n";
  });
  const known = parseKnownFailures('[[known-failure]]\nid = "fx5-time-add/TADD/old"\nreason = "listed before the merge"\n', "k.toml");
  const report = runVectors(reference(), { suite: loadSuite(set), selection: { ids: [target] }, known });
  assert.equal(report.counts.stale, 1);
  assert.match(
    summaryText(report),
    new RegExp(`^STALE fx5-time-add/TADD/old\\n {4}listed as a known failure \\(k\\.toml:1\\) but the suite has no such vector: it was merged into ${escaped(target)}; list that id instead$`, "m"),
  );
});
