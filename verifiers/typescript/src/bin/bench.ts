#!/usr/bin/env node
/**
 * How fast this runner judges the golden set with the TypeScript reference, in process, after
 * loading: loading and preparing are timed apart; then warm-up passes let the JIT settle, and the
 * figure is the median of SAMPLES timed samples, each ROUNDS passes in a row (per pass). The last
 * line is the JSON object that `plcvec bench-native` reads.
 *
 * A pass takes a few milliseconds, less than the slice a busy machine's scheduler gives: a sample
 * of ROUNDS passes (some 40 ms) holds its share of preemption as the Python figure's passes (tens
 * of milliseconds each) and the Java bench's samples do, so the figures compare like with like.
 *
 * The warm-up lasts at least WARMUP_PASSES passes and WARMUP_SECONDS: V8 optimizes the hot path
 * on background threads over the first dozen or two passes (more while other programs hold the
 * cores), and a timed pass before that measures the compiler, not the runner.
 */
import { resolveChoices } from "../choices.js";
import { judge, prepare } from "../compare.js";
import { reference } from "../reference/index.js";
import { loadSuite } from "../suite.js";
import { enter, leave, register } from "../watchdog.js";

const WARMUP_PASSES = 30;
const WARMUP_SECONDS = 1;
const SAMPLES = 25;
const ROUNDS = 10;

let start = performance.now();
const suite = loadSuite();
const loadSeconds = (performance.now() - start) / 1000;
start = performance.now();
const impl = reference();
const followed = resolveChoices(suite, impl.choices);
const prepared = suite.vectors.map((v) => prepare(v, followed));
// Judged under the watchdog and the exit guard, as every test-runner binding judges: the figure includes their cost.
const first = register(suite.vectors.map((v) => v.id));
const prepareSeconds = (performance.now() - start) / 1000;

/** One pass over every prepared vector: its clock and CPU seconds. Every vector must pass. */
function pass(): { seconds: number; cpu: number } {
  const c0 = process.cpuUsage();
  const t0 = performance.now();
  let failed = 0;
  for (let i = 0; i < prepared.length; i++) {
    const p = prepared[i]!;
    enter(first + i);
    if (judge(p, impl).status !== "pass") failed++;
    leave();
  }
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
/** Per pass, clock and CPU seconds of each sample. */
const seconds: number[] = [];
const cpuSeconds: number[] = [];
for (let i = 0; i < SAMPLES; i++) {
  let clock = 0;
  let cpu = 0;
  for (let r = 0; r < ROUNDS; r++) {
    const t = pass();
    clock += t.seconds;
    cpu += t.cpu;
  }
  seconds.push(clock / ROUNDS);
  cpuSeconds.push(cpu / ROUNDS);
}
const medianOf = (xs: number[]): number => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)] as number;
const median = medianOf(seconds);
const n = prepared.length;
// The CPU-time figure beside the clock's: on a busy machine the clock also counts other programs' time.
console.log(
  `typescript: ${n} vectors, load ${loadSeconds.toFixed(3)} s, prepare ${prepareSeconds.toFixed(3)} s, ` +
    `judge ${(median * 1000).toFixed(2)} ms a pass, median sample (${Math.round(n / median)}/s by the clock, ` +
    `${Math.round(n / medianOf(cpuSeconds))}/s by CPU time)`,
);
console.log(
  JSON.stringify({
    lang: "typescript",
    vectors: n,
    passes: SAMPLES * ROUNDS,
    load_seconds: Number(loadSeconds.toFixed(4)),
    seconds: Number(median.toFixed(6)),
    vectors_per_s: Math.round(n / median),
    cpu_vectors_per_s: Math.round(n / medianOf(cpuSeconds)),
    note: `node ${process.version}, median of ${SAMPLES} samples of ${ROUNDS} passes after ${warm} warm-up passes`,
  }),
);
