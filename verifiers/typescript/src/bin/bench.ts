#!/usr/bin/env node
/**
 * How fast this runner judges the golden set with the TypeScript reference, in process, after
 * loading: loading and preparing are timed apart; then WARMUP passes let the JIT settle, and the
 * figure is the median of PASSES timed passes. The last line is the JSON object that
 * `plcvec bench-native` reads.
 */
import { loadSuite } from "../load.js";
import { reference } from "../reference/index.js";
import { judge, prepare, resolveChoices } from "../run.js";

const WARMUP = 5;
const PASSES = 25;

let start = performance.now();
const suite = loadSuite();
const loadSeconds = (performance.now() - start) / 1000;
start = performance.now();
const impl = reference();
const { choices, defaults } = resolveChoices(suite, impl.choices);
const prepared = suite.vectors.map((v) => prepare(v, choices, defaults));
const prepareSeconds = (performance.now() - start) / 1000;

const seconds: number[] = [];
const cpuSeconds: number[] = [];
for (let pass = 0; pass < WARMUP + PASSES; pass++) {
  const c0 = process.cpuUsage();
  const t0 = performance.now();
  let failed = 0;
  for (const p of prepared) if (judge(p, impl).status !== "pass") failed++;
  const t = (performance.now() - t0) / 1000;
  const c = process.cpuUsage(c0);
  if (failed) {
    process.stderr.write(`the reference failed ${failed} vectors: the benchmark means nothing\n`);
    process.exit(1);
  }
  if (pass >= WARMUP) {
    seconds.push(t);
    cpuSeconds.push((c.user + c.system) / 1e6);
  }
}
const medianOf = (xs: number[]): number => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)] as number;
const median = medianOf(seconds);
const n = prepared.length;
// The CPU-time figure beside the clock's: on a busy machine the clock also counts other programs' time.
console.log(
  `typescript: ${n} vectors, load ${loadSeconds.toFixed(3)} s, prepare ${prepareSeconds.toFixed(3)} s, ` +
    `judge ${(median * 1000).toFixed(2)} ms a pass (${Math.round(n / median)}/s by the clock, ` +
    `${Math.round(n / medianOf(cpuSeconds))}/s by CPU time)`,
);
console.log(
  JSON.stringify({
    lang: "typescript",
    vectors: n,
    passes: PASSES,
    load_seconds: Number(loadSeconds.toFixed(4)),
    seconds: Number(median.toFixed(6)),
    vectors_per_s: Math.round(n / median),
    cpu_vectors_per_s: Math.round(n / medianOf(cpuSeconds)),
    note: `node ${process.version}, median of ${PASSES} passes after ${WARMUP} warm-up`,
  }),
);
