/**
 * The reference machines' names before 0.3.0 (`plcvec/reference`'s `Fx5CompareMachine`,
 * `TaddMachine`, `HourMeter`): still the same classes under the old names, as a value and as a
 * type, and marked deprecated in the declarations an editor shows a user.
 */
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";
import { test } from "node:test";
import ts from "typescript";

import { Memory } from "../src/index.js";
import { Fc6aHourMeter, Fx5Compare, Fx5CompareMachine, Fx5TimeAdd, HourMeter, TaddMachine } from "../src/reference/index.js";

const RENAMED = [
  ["Fx5CompareMachine", "Fx5Compare"],
  ["TaddMachine", "Fx5TimeAdd"],
  ["HourMeter", "Fc6aHourMeter"],
] as const;

test("each old name is its machine's class", () => {
  assert.equal(Fx5CompareMachine, Fx5Compare);
  assert.equal(TaddMachine, Fx5TimeAdd);
  assert.equal(HourMeter, Fc6aHourMeter);
});

test("code written against the old names still compiles and runs", () => {
  // A mutant of 0.2.0's kind: a subclass of the old name, typed by the old name.
  class Extended extends TaddMachine {}
  const mem = new Memory({});
  const tadd: TaddMachine = new Extended(mem, {});
  const hour: HourMeter = new Fc6aHourMeter(mem, {});
  const compare: Fx5CompareMachine = new Fx5CompareMachine(mem, {}).forDates();
  assert.ok(tadd instanceof Fx5TimeAdd);
  assert.ok(hour instanceof HourMeter);
  assert.ok(compare instanceof Fx5Compare);
});

test("each old name is deprecated, as value and as type, naming the new name and 0.4.0", () => {
  const file = fileURLToPath(new URL("../src/reference/index.d.ts", import.meta.url));
  const source = ts.createSourceFile(file, readFileSync(file, "utf8"), ts.ScriptTarget.Latest, true);
  const deprecations = new Map<string, string[]>();
  const note = (name: string, node: ts.Node): void => {
    for (const tag of ts.getJSDocTags(node)) {
      if (tag.tagName.text !== "deprecated") continue;
      deprecations.set(name, [...(deprecations.get(name) ?? []), ts.getTextOfJSDocComment(tag.comment) ?? ""]);
    }
  };
  for (const statement of source.statements) {
    if (ts.isTypeAliasDeclaration(statement)) note(`type ${statement.name.text}`, statement);
    if (ts.isVariableStatement(statement)) for (const d of statement.declarationList.declarations) note(`const ${d.name.getText(source)}`, d);
  }
  for (const [old, now] of RENAMED) {
    for (const kind of ["const", "type"]) {
      const texts = deprecations.get(`${kind} ${old}`);
      assert.ok(texts !== undefined, `${kind} ${old} is not marked @deprecated in ${file}`);
      assert.match(texts.join(" "), new RegExp(`\\b${now}\\b.*0\\.4\\.0`), `${kind} ${old}`);
    }
  }
  // The new names are not deprecated.
  for (const [, now] of RENAMED) assert.equal([...deprecations.keys()].some((k) => k.endsWith(` ${now}`)), false, now);
});
