/**
 * The one failure text (verifiers/parity/TEXT.md): the shared cases of verifiers/parity/text/,
 * loaded by this runner's loader, answered as answers.json says, judged and described by this
 * runner's own code, must give expected.txt byte for byte.
 */
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { test } from "node:test";
import { fileURLToPath } from "node:url";

import { declaration, loadKnownFailures, loadSuite, runVectors, summaryText, type Implementation, type RunOutcome } from "../src/index.js";

const cases = join(dirname(fileURLToPath(import.meta.url)), "..", "..", "..", "parity", "text");

interface Answers {
  readonly hello: {
    readonly adapter: { readonly name: string; readonly version?: string };
    readonly instructions: readonly string[];
    readonly interpretations: Readonly<Record<string, string>>;
    readonly cpu_writes?: readonly string[];
  };
  readonly answers: Readonly<Record<string, RunOutcome>>;
}

/** The implementation the shared cases describe: it declares `hello` and answers from `answers`. */
function replay(): Implementation {
  const { hello, answers } = JSON.parse(readFileSync(join(cases, "answers.json"), "utf8")) as Answers;
  return {
    name: hello.adapter.name,
    ...(hello.adapter.version !== undefined ? { version: hello.adapter.version } : {}),
    instructions: hello.instructions,
    choices: hello.interpretations,
    ...(hello.cpu_writes !== undefined ? { cpuWrites: hello.cpu_writes } : {}),
    run: (request) => {
      const answer = answers[request.id];
      if (answer === undefined) throw new Error(`answers.json has no answer for ${request.id}`);
      return answer;
    },
  };
}

/** The run's text without what depends on the machine: the header line, and the time after the totals. */
function machineFree(text: string): string {
  return text
    .split("\n")
    .filter((line) => !line.startsWith("plcvec verify: "))
    .join("\n")
    .replace(/ in \d+\.\d\d s\n$/, "\n");
}

test("the shared failure text: every block, the roll-up, the skips and the summary, byte for byte", () => {
  const report = runVectors(replay(), { suite: loadSuite(join(cases, "vectors")) });
  // The shared cases hold the declaration as plcvec verify writes it.
  assert.equal(machineFree(summaryText(report, { declaration: "verify" })), readFileSync(join(cases, "expected.txt"), "utf8"));
});

test("the shared failure text with its known failures: the KNOWN FAILURES part names the file as given", () => {
  const here = process.cwd();
  process.chdir(cases); // the file is given as the shared cases name it: `known.toml`, from its own folder
  try {
    const report = runVectors(replay(), { suite: loadSuite(join(cases, "vectors")), known: loadKnownFailures("known.toml") });
    assert.equal(machineFree(summaryText(report, { declaration: "verify" })), readFileSync(join(cases, "expected-known.txt"), "utf8"));
  } finally {
    process.chdir(here);
  }
});

test("the declaration in this runner's syntax is TEXT.md's TypeScript row, and the roll-up uses it by default", () => {
  const table = readFileSync(join(cases, "..", "TEXT.md"), "utf8");
  const row = /^\| TypeScript \| `([^`]+)` \|$/m.exec(table);
  assert.ok(row !== null, "TEXT.md has no TypeScript row in its table of declarations");
  assert.equal(declaration({ "TADD-FLAGS-OFF": "set-only", "FX5-SM709-SCOPE": "all-words" }), row[1]);
  const report = runVectors(replay(), { suite: loadSuite(join(cases, "vectors")) });
  assert.match(summaryText(report), /^ {4}declare: choices: \{ "FX5-SM709-SCOPE": "all-words", "TADD-FLAGS-OFF": "set-only" \}$/m);
});
