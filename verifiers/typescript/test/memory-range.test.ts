/**
 * Memory.inRange, which keeps what it finds per frozen table of device sizes: the same answers as
 * the rule read afresh ("three points for each of three devices": base .. base+count-1 exist when
 * the device type's size says so), and a table that is not frozen read afresh at every check.
 */
import assert from "node:assert/strict";
import { test } from "node:test";

import { loadSuite, Memory, requestOf } from "../src/index.js";

/** The rule, worked out here from the address and the table: a type of unstated size is taken to be large enough. */
function ruleSays(sizes: Readonly<Record<string, number>>, address: string, count: number): boolean {
  const m = /^([A-Za-z_]+?)(\d+)$/.exec(address);
  if (m === null) return false;
  const size = Object.hasOwn(sizes, m[1]!) ? sizes[m[1]!] : undefined;
  return size === undefined || Number(m[2]) + count <= size;
}

test("every operand device of every vector: inRange answers as the rule does, the first time and again", () => {
  let checked = 0;
  for (const vector of loadSuite().vectors) {
    const request = requestOf(vector);
    assert.ok(Object.isFrozen(request.assumes.device_sizes), `${vector.id}: a prepared request's sizes are frozen (the kept answers' key)`);
    for (const op of Object.values(vector.initial.operands)) {
      if (!("device" in op)) continue;
      for (const count of [1, 3, 4]) {
        const want = ruleSays(vector.assumes.device_sizes, op.device, count);
        for (let again = 0; again < 2; again++) {
          assert.equal(Memory.forRequest(request).inRange(op.device, count), want, `${vector.id}: ${op.device} +${count}`);
        }
        checked++;
      }
    }
  }
  assert.ok(checked > 1000, `only ${checked} checks`);
});

test("inRange at the edges of a frozen table, worked out by hand", () => {
  const sizes = Object.freeze({ D: 8000, SD: 12000 });
  const mem = new Memory({}, sizes);
  assert.equal(mem.inRange("D7997", 3), true); // D7997, D7998, D7999
  assert.equal(mem.inRange("D7998", 3), false); // D8000 does not exist
  assert.equal(mem.inRange("D7998", 2), true); // the same base, a shorter run: asked afresh of the count
  assert.equal(mem.inRange("SD11999", 1), true);
  assert.equal(mem.inRange("W5", 3), true); // W's size is not stated
  assert.equal(mem.inRange("P_EQ", 1), false); // no number: not a run of points
  // Another image of the same table answers alike.
  assert.equal(new Memory({}, sizes).inRange("D7998", 3), false);
});

test("a table that is not frozen is read afresh at every check", () => {
  const sizes: Record<string, number> = { D: 100 };
  const mem = new Memory({}, sizes);
  assert.equal(mem.inRange("D98", 3), false);
  sizes["D"] = 200;
  assert.equal(mem.inRange("D98", 3), true);
  delete sizes["D"];
  sizes["W"] = 10;
  assert.equal(mem.inRange("D1000", 3), true);
  assert.equal(mem.inRange("W9", 2), false);
});
