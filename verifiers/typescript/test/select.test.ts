/** Selection: names checked, globs as fnmatch, shards as every plcvec runner splits them. */
import assert from "node:assert/strict";
import { test } from "node:test";

import { crc32, globToRegExp, loadSuite, parseShard, VerifyError, select, shardOf } from "../src/index.js";

const suite = loadSuite();

test("crc32 is zlib's CRC-32 (the standard check value)", () => {
  assert.equal(crc32("123456789"), 0xcbf43926);
  assert.equal(crc32(""), 0);
  // Values from Python's zlib.crc32 over the UTF-8 bytes (the Python runner's shard rule).
  assert.equal(crc32("é"), 0x0e048d3e);
  assert.equal(crc32("fx5-time-add/TADD/manual-example/program"), 0x57d9b78e);
});

test("shards partition the suite: every vector in exactly one, the same one every time", () => {
  const n = 4;
  const shards = [1, 2, 3, 4].map((k) => select(suite, { shard: [k, n] }).map((v) => v.id));
  assert.equal(shards.flat().length, suite.vectors.length);
  assert.equal(new Set(shards.flat()).size, suite.vectors.length);
  for (const [k, ids] of shards.entries()) for (const id of ids.slice(0, 20)) assert.equal(shardOf(id, n), k + 1);
  assert.ok(shards.every((ids) => ids.length > suite.vectors.length / 8), "a CRC spreads the ids about evenly");
});

test("shard text is K/N with 1 <= K <= N", () => {
  assert.deepEqual(parseShard("2/4"), [2, 4]);
  for (const bad of ["0/4", "5/4", "2", "a/b", "2/0"]) assert.throws(() => parseShard(bad), VerifyError);
});

test("filters are OR within one, AND across", () => {
  const tadd = select(suite, { instructions: ["TADD", "TADDP"] });
  assert.ok(tadd.length > 0 && tadd.every((v) => v.family === "fx5-time-add"));
  const boundaryTadd = select(suite, { instructions: ["TADD"], tags: ["boundary"] });
  assert.ok(boundaryTadd.length > 0 && boundaryTadd.every((v) => v.instruction === "TADD" && v.tags.includes("boundary")));
  const byInterp = select(suite, { interpretations: ["TADD-EXACT-24"] });
  assert.ok(byInterp.length > 0 && byInterp.every((v) => v.outcome.interpretations?.includes("TADD-EXACT-24")));
});

test("an unknown name is an error listing the known ones", () => {
  assert.throws(() => select(suite, { instructions: ["TADX"] }), /unknown instruction "TADX" \(known: .*TADDP/);
  assert.throws(() => select(suite, { families: ["nope"] }), /unknown family "nope" \(known: cp1e-time-compare/);
  assert.throws(() => select(suite, { tags: ["nosuchtag"] }), /unknown tag/);
  assert.throws(() => select(suite, { interpretations: ["X"] }), /unknown interpretation/);
});

test("id globs follow fnmatch: * crosses slashes, [..] is a set", () => {
  assert.ok(globToRegExp("fx5-time-add/*").test("fx5-time-add/TADD/a/b"));
  assert.ok(globToRegExp("a?c").test("abc") && !globToRegExp("a?c").test("abbc"));
  assert.ok(globToRegExp("[ab]x").test("bx") && !globToRegExp("[!ab]x").test("bx"));
  assert.ok(globToRegExp("LDTM<=(x)").test("LDTM<=(x)"));
  // A glob that matches no id of the suite is a typo: an error naming it, as plcvec verify's --id.
  assert.throws(() => select(suite, { ids: ["zzz*"] }), /id glob "zzz\*" matches no vector id/);
});
