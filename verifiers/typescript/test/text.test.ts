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

import { loadSuite, runVectors, summaryText, type Implementation, type RunOutcome } from "../src/index.js";

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

test("the shared failure text: every block, the roll-up, the skips and the summary, byte for byte", () => {
  const { hello, answers } = JSON.parse(readFileSync(join(cases, "answers.json"), "utf8")) as Answers;
  const impl: Implementation = {
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
  const report = runVectors(impl, { suite: loadSuite(join(cases, "vectors")) });
  // What depends on the machine goes: the header line, and the time after the totals.
  const text = summaryText(report)
    .split("\n")
    .filter((line) => !line.startsWith("plcvec verify: "))
    .join("\n")
    .replace(/ in \d+\.\d\d s\n$/, "\n");
  assert.equal(text, readFileSync(join(cases, "expected.txt"), "utf8"));
});
