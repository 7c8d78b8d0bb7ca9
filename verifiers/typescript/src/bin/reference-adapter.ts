#!/usr/bin/env node
/**
 * The TypeScript reference implementation served over the plcvec stdio protocol
 * (verifiers/PROTOCOL.md), so `plcvec verify --adapter verifiers/typescript/reference-adapter`
 * judges it like any implementation.
 *
 *     plcvec-reference-adapter [--mutant NAME] [--choose ID=ALT ...]
 */
import { MUTANTS, mutant } from "../mutants/index.js";
import { reference } from "../reference/index.js";
import type { Implementation } from "../implementation.js";
import { serve } from "../serve.js";

function usage(message: string): never {
  process.stderr.write(`plcvec-reference-adapter: ${message}\n`);
  process.exit(2);
}

function parseArgs(argv: readonly string[]): Implementation {
  const choices: Record<string, string> = {};
  let mutantName: string | undefined;
  for (let i = 0; i < argv.length; i++) {
    const arg = argv[i];
    const value = argv[i + 1];
    if (arg === "--choose" && value !== undefined && value.includes("=")) {
      const [id, alt] = [value.slice(0, value.indexOf("=")), value.slice(value.indexOf("=") + 1)];
      choices[id] = alt;
      i++;
    } else if (arg === "--mutant" && value !== undefined) {
      if (MUTANTS[value] === undefined) usage(`no mutant ${JSON.stringify(value)}; known: ${Object.keys(MUTANTS).sort().join(", ")}`);
      mutantName = value;
      i++;
    } else {
      usage(`unknown argument ${JSON.stringify(arg)} (usage: [--mutant NAME] [--choose ID=ALT ...])`);
    }
  }
  return mutantName === undefined ? reference(choices) : mutant(mutantName, choices);
}

serve(parseArgs(process.argv.slice(2)));
