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
 *
 * `vectors_per_s` judges each vector under the guard, as every test-runner binding judges (cases()
 * and runVectors): the watchdog's bound (PLCVEC_TIMEOUT) and the exit guard, watchdog.ts's
 * enter/leave around the judging with leave in a `finally`. What the guard costs is measured
 * apart, paired in this process, because two runs of a shared machine a minute apart differ by
 * more than the guard could: PAIRS iterations each time one unguarded pass (the same loop without
 * enter/leave) and one guarded pass, back to back, the first of the two alternating.
 *   guarded_ratio          the median over iterations of unguarded seconds / guarded seconds of
 *                          the same iteration: the share of the unguarded speed the guard leaves;
 *   guarded_ratio_fastest  the fastest unguarded pass / the fastest guarded pass;
 *   guarded_vectors_per_s, unguarded_loop_vectors_per_s  vectors / the median pass of each kind;
 *   guard_fixed_seconds    what the guard costs once per run, before any pass: the first
 *                          register(), which starts the watchdog thread (whose own start-up
 *                          then runs on that thread, during the warm-up), sets the exit hooks and
 *                          posts the ids. A pass has no cost of the guard's but enter/leave per
 *                          vector, so the ratios are the per-vector cost with nothing taken out
                          (what another bench calls guarded_ratio_per_vector is guarded_ratio here).
 * The two passes are two functions, the same loop but for enter/leave, and the warm-up runs them
 * in turn, so that each is optimized before the first timed pass (node --trace-opt --trace-deopt:
 * both are compiled during the warm-up, nothing is compiled or deoptimized after it, and both call
 * judge, inlined in neither). One function with a flag would not compare fairly: its unguarded
 * pass would test the flag and carry the guard's code in its compiled body, so the difference
 * measured would be less than the guard's, and a branch the warm-up left cold deoptimizes when
 * first taken.
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
const PAIRS = 300;

let start = performance.now();
const suite = loadSuite();
const loadSeconds = (performance.now() - start) / 1000;
start = performance.now();
const impl = reference();
const followed = resolveChoices(suite, impl.choices);
const prepared = suite.vectors.map((v) => prepare(v, followed));
const guardStart = performance.now();
const first = register(suite.vectors.map((v) => v.id));
const guardFixedSeconds = (performance.now() - guardStart) / 1000;
const prepareSeconds = (performance.now() - start) / 1000;

/** A pass in which the reference failed a vector measures nothing: the benchmark stops. */
function allPassed(failed: number): void {
  if (failed === 0) return;
  process.stderr.write(`the reference failed ${failed} vectors: the benchmark means nothing\n`);
  process.exit(1);
}

/** One pass over every prepared vector, each under the guard as a test run judges it: its clock seconds. */
function guardedPass(): number {
  const t0 = performance.now();
  let failed = 0;
  for (let i = 0; i < prepared.length; i++) {
    const p = prepared[i]!;
    enter(first + i);
    try {
      if (judge(p, impl).status !== "pass") failed++;
    } finally {
      leave();
    }
  }
  const seconds = (performance.now() - t0) / 1000;
  allPassed(failed);
  return seconds;
}

/** guardedPass without the guard: the same judging, no enter/leave. */
function unguardedPass(): number {
  const t0 = performance.now();
  let failed = 0;
  for (let i = 0; i < prepared.length; i++) {
    const p = prepared[i]!;
    if (judge(p, impl).status !== "pass") failed++;
  }
  const seconds = (performance.now() - t0) / 1000;
  allPassed(failed);
  return seconds;
}

/** One guarded pass: its clock and CPU seconds. */
function pass(): { seconds: number; cpu: number } {
  const c0 = process.cpuUsage();
  const seconds = guardedPass();
  const c = process.cpuUsage(c0);
  return { seconds, cpu: (c.user + c.system) / 1e6 };
}

let warm = 0;
const warmStart = performance.now();
while (warm < WARMUP_PASSES || (performance.now() - warmStart) / 1000 < WARMUP_SECONDS) {
  pass();
  unguardedPass();
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
/** The paired passes: seconds of each kind and their ratio, iteration by iteration. */
const unguarded: number[] = [];
const guarded: number[] = [];
const ratios: number[] = [];
for (let i = 0; i < PAIRS; i++) {
  let u: number;
  let g: number;
  if (i % 2 === 0) {
    u = unguardedPass();
    g = guardedPass();
  } else {
    g = guardedPass();
    u = unguardedPass();
  }
  unguarded.push(u);
  guarded.push(g);
  ratios.push(u / g);
}
const medianOf = (xs: number[]): number => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)] as number;
const median = medianOf(seconds);
const n = prepared.length;
const guardedRatio = medianOf(ratios);
const guardedRatioFastest = Math.min(...unguarded) / Math.min(...guarded);
// The CPU-time figure beside the clock's: on a busy machine the clock also counts other programs' time.
console.log(
  `typescript: ${n} vectors, load ${loadSeconds.toFixed(3)} s, prepare ${prepareSeconds.toFixed(3)} s, ` +
    `judge ${(median * 1000).toFixed(2)} ms a pass, median sample (${Math.round(n / median)}/s by the clock, ` +
    `${Math.round(n / medianOf(cpuSeconds))}/s by CPU time)`,
);
console.log(
  `typescript: the guard, ${PAIRS} paired passes: ${Math.round(n / medianOf(guarded))}/s guarded, ` +
    `${Math.round(n / medianOf(unguarded))}/s unguarded, median ratio ${guardedRatio.toFixed(3)}, ` +
    `fastest ${guardedRatioFastest.toFixed(3)}; once per run ${(guardFixedSeconds * 1000).toFixed(1)} ms`,
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
    guarded_vectors_per_s: Math.round(n / medianOf(guarded)),
    unguarded_loop_vectors_per_s: Math.round(n / medianOf(unguarded)),
    guarded_ratio: Number(guardedRatio.toFixed(3)),
    guarded_ratio_fastest: Number(guardedRatioFastest.toFixed(3)),
    guard_fixed_seconds: Number(guardFixedSeconds.toFixed(4)),
    note: `node ${process.version}, median of ${SAMPLES} samples of ${ROUNDS} passes after ${warm} warm-up passes of each kind; guard: ${PAIRS} paired passes`,
  }),
);
