/**
 * The reference implementation passes every vector under every combination of the alternatives
 * of its family's interpretations: the evidence that the suite, this runner and the reference agree.
 */
import assert from "node:assert/strict";
import { readdirSync, readFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { describe, test } from "node:test";

import { summaryText, interpretationsOf, loadSuite, runVectors } from "../src/index.js";
import { reference } from "../src/reference/index.js";

const suite = loadSuite();

function* combinations(options: readonly (readonly [string, readonly string[]])[]): Generator<Record<string, string>> {
  if (options.length === 0) {
    yield {};
    return;
  }
  const [[id, alternatives], ...rest] = options as [readonly [string, readonly string[]], ...(readonly [string, readonly string[]])[]];
  for (const alt of alternatives) for (const tail of combinations(rest)) yield { [id]: alt, ...tail };
}

describe("the reference under every combination of alternatives", () => {
  for (const family of suite.headers.keys()) {
    test(family, () => {
      const interps = [...interpretationsOf(suite, [family]).values()].map((i) => [i.id, i.alternatives] as const);
      let runs = 0;
      for (const choices of combinations(interps)) {
        const report = runVectors(reference(choices), { suite, selection: { families: [family] } });
        assert.ok(report.passed, `${JSON.stringify(choices)}\n${summaryText(report)}`);
        assert.equal(report.counts.pass, report.verdicts.length);
        runs++;
      }
      assert.equal(runs, interps.reduce((n, [, alts]) => n * alts.length, 1));
    });
  }
});

describe("the reference is an outside user", () => {
  // What an emulator author can import is what the package's entry point exports (and the README
  // documents); the reference and the mutants import nothing else of the library, so a field the
  // public API gets wrong fails their tests as it would fail the author's.
  const src = join(dirname(fileURLToPath(import.meta.url)), "../../src");
  for (const folder of ["reference", "mutants"]) {
    test(`src/${folder} imports the library only through its entry point`, () => {
      for (const file of readdirSync(join(src, folder)).filter((f) => f.endsWith(".ts"))) {
        const text = readFileSync(join(src, folder, file), "utf8");
        const from = [...text.matchAll(/^import [^;]*? from "([^"]+)";$/gms)].map((m) => m[1] ?? "");
        assert.ok(from.length > 0, `${folder}/${file}: no imports found`);
        for (const source of from) {
          const allowed = source === "../index.js" || source.startsWith("./") || source.startsWith("node:")
            || (folder === "mutants" && source.startsWith("../reference/"));
          assert.ok(allowed, `${folder}/${file} imports ${source}: only "../index.js" (the package's entry point) may be used`);
        }
      }
    });
  }
});
