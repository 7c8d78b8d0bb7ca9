#!/usr/bin/env node
/**
 * How fast this runner judges the golden set with the TypeScript reference, in process, after
 * loading: loading and preparing are timed apart; then warm-up passes let the JIT settle, and the
 * figure is the median of PASSES timed passes. The last line is the JSON object that
 * `plcvec bench-native` reads.
 *
 * The warm-up lasts at least WARMUP_PASSES passes and WARMUP_SECONDS: V8 optimizes the hot path
 * on background threads over the first dozen or two passes (more while other programs hold the
 * cores), and a timed pass before that measures the compiler, not the runner.
 */
import { loadSuite } from "../load.js";
import { reference } from "../reference/index.js";
import { judge, prepare, resolveChoices } from "../run.js";

const WARMUP_PASSES = 30;
const WARMUP_SECONDS = 1;
const PASSES = 25;

let start = performance.now();
const suite = loadSuite();
const loadSeconds = (performance.now() - start) / 1000;
start = performance.now();
const impl = reference();
const { choices, defaults } = resolveChoices(suite, impl.choices);
const prepared = suite.vectors.map((v) => prepare(v, choices, defaults));
const prepareSeconds = (performance.now() - start) / 1000;

/** One pass over every prepared vector: its clock and CPU seconds. Every vector must pass. */
function pass(): { seconds: number; cpu: number } {
  const c0 = process.cpuUsage();
  const t0 = performance.now();
  let failed = 0;
  for (const p of prepared) if (judge(p, impl).status !== "pass") failed++;
  const seconds = (performance.now() - t0) / 1000;
  const c = process.cpuUsage(c0);
  if (failed) {
    process.stderr.write(`the reference failed ${failed} vectors: the benchmark means nothing\n`);
    process.exit(1);
  }
  return { seconds, cpu: (c.user + c.system) / 1e6 };
}

let warm = 0;
const warmStart = performance.now();
while (warm < WARMUP_PASSES || (performance.now() - warmStart) / 1000 < WARMUP_SECONDS) {
  pass();
  warm++;
}
const seconds: number[] = [];
const cpuSeconds: number[] = [];
for (let i = 0; i < PASSES; i++) {
  const t = pass();
  seconds.push(t.seconds);
  cpuSeconds.push(t.cpu);
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
    note: `node ${process.version}, median of ${PASSES} passes after ${warm} warm-up`,
  }),
);
