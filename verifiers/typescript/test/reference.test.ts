/**
 * The reference implementation passes every vector under every combination of the alternatives
 * of its family's interpretations: the evidence that the suite, this runner and the reference agree.
 */
import assert from "node:assert/strict";
import { readdirSync, readFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { describe, test } from "node:test";

import { describe as describeVerdict, type Followed, interpretationsOf, judge, loadSuite, prepare, type Prepared, resolveChoices, runVectors, summaryText, type Vector } from "../src/index.js";
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

/**
 * The vectors prepared once per expectation they give: what a vector expects depends only on the
 * alternatives of the interpretations it names (`outcome.interpretations`), so the 34,560
 * combinations of HOUR's alternatives share a handful of expectations per vector, while the
 * reference runs every vector under every combination. The vectors that name the same
 * interpretations form a group, whose key under a combination (those interpretations' alternatives)
 * is made once per combination, not once per vector; each key's vectors are prepared when it first
 * comes.
 */
class PreparedUnder {
  private readonly groups = new Map<string, { touched: readonly string[]; indexes: number[]; byKey: Map<string, Prepared[]> }>();

  constructor(private readonly vectors: readonly Vector[]) {
    vectors.forEach((vector, index) => {
      const touched = vector.outcome.interpretations ?? [];
      const name = touched.join("\n");
      let group = this.groups.get(name);
      if (group === undefined) this.groups.set(name, (group = { touched, indexes: [], byKey: new Map() }));
      group.indexes.push(index);
    });
  }

  /** Each vector prepared under `choices` (`followed()`, their resolution, asked for only when a key is new), in the vectors' order. */
  all(choices: Readonly<Record<string, string>>, followed: () => Followed): Prepared[] {
    const out = new Array<Prepared>(this.vectors.length);
    for (const { touched, indexes, byKey } of this.groups.values()) {
      const key = touched.map((i) => choices[i]).join("\n");
      let prepared = byKey.get(key);
      if (prepared === undefined) {
        const f = followed();
        byKey.set(key, (prepared = indexes.map((i) => prepare(this.vectors[i]!, f))));
      }
      indexes.forEach((i, j) => (out[i] = prepared[j]!));
    }
    return out;
  }
}

describe("the reference under every combination of alternatives", () => {
  for (const family of suite.headers.keys()) {
    test(family, () => {
      const interps = [...interpretationsOf(suite, [family]).values()].map((i) => [i.id, i.alternatives] as const);
      // The whole gate (selection, watchdog, report) under the defaults; each combination is judged
      // vector by vector as that gate judges it (prepare, then judge), without its per-run set-up.
      const gated = runVectors(reference(), { suite, selection: { families: [family] } });
      assert.ok(gated.passed, summaryText(gated));
      const vectors = suite.vectors.filter((v) => v.family === family);
      assert.equal(gated.verdicts.length, vectors.length);
      const cache = new PreparedUnder(vectors);
      let runs = 0;
      for (const choices of combinations(interps)) {
        const impl = reference(choices);
        let followed: Followed | undefined;
        const prepared = cache.all(choices, () => (followed ??= resolveChoices(suite, choices)));
        for (let i = 0; i < vectors.length; i++) {
          const verdict = judge(prepared[i]!, impl);
          // The message is made only for a failure: 5.5 million verdicts pass.
          if (verdict.status !== "pass") assert.fail(`${JSON.stringify(choices)}\n${describeVerdict(verdict, vectors[i]!)}`);
        }
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
