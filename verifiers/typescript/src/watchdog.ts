/**
 * The guard around an implementation: a bound on each vector's time, and the vector named when
 * the implementation ends the process.
 *
 * An implementation runs in the test's own thread (it is the user's object, closures and all), so
 * a synchronous loop that never returns cannot be interrupted there. A watchdog thread watches
 * instead: the runner stores the number of the vector in progress in shared memory (on entry the
 * number and a count of vectors started, on leaving a zero: three plain stores per vector, no
 * call, allocation or system call), the watchdog reads it on its tick, and when one vector has
 * held it for PLCVEC_TIMEOUT seconds the watchdog writes the vector's id to stderr and ends the
 * process, which fails any test run.
 *
 * An implementation that calls `process.exit` half way, or `process.abort`, is caught at the
 * process's exit (or just before the abort), which reads the same number: the vector in progress
 * is named and the exit status is made non-zero, so an early exit is never a green run.
 */
import { writeSync } from "node:fs";
import { Worker } from "node:worker_threads";

import { noteDescriptors } from "./leftovers.js";
import { timeoutSeconds } from "./settings.js";

// The watchdog thread: CommonJS source, run with `eval`, so that it needs no file of its own.
const WATCHDOG = `
const { parentPort, workerData } = require("node:worker_threads");
const { writeSync } = require("node:fs");
const beat = new Int32Array(workerData.buffer);
const ids = [];
parentPort.on("message", (list) => {
  for (const id of list) ids.push(id);
  Atomics.add(beat, 2, 1);
  Atomics.notify(beat, 2);
});
let seen = -1;
let since = Date.now();
setInterval(() => {
  const running = Atomics.load(beat, 0);
  const started = Atomics.load(beat, 1);
  const now = Date.now();
  if (running === 0 || started !== seen) { seen = started; since = now; return; }
  if (now - since < workerData.milliseconds) return;
  const id = ids[running - 1] ?? "(vector #" + running + ")";
  writeSync(2, "plcvec: vector " + id + ": no answer within " + workerData.seconds + " s (PLCVEC_TIMEOUT); the run ends here\\n");
  process.kill(process.pid, "SIGKILL");
}, workerData.tick);
`;

/**
 * [0]: 1 + the number of the vector in progress, 0 when none; [1]: vectors started so far; [2]: the
 * lists of ids the watchdog has taken. Made when the module loads (12 bytes; the watchdog that
 * reads it starts at the first register()), so that enter/leave store into a constant, with no
 * check that it exists or what it holds.
 */
const beat = new Int32Array(new SharedArrayBuffer(12));
/** How long register() waits for the watchdog to take a list of ids (it starts a thread the first time). */
const TAKEN_WITHIN_MS = 5000;
let watchdog: Worker | undefined;
/** Every vector registered in this process, by number. */
const ids: string[] = [];

function start(): Worker {
  const seconds = timeoutSeconds();
  const milliseconds = seconds * 1000;
  const worker = new Worker(WATCHDOG, {
    eval: true,
    workerData: { buffer: beat.buffer, seconds, milliseconds, tick: Math.max(10, Math.min(250, milliseconds / 8)) },
    stdout: false,
    stderr: false,
  });
  worker.unref();
  process.on("exit", (code) => {
    if (beat[0] === 0) return;
    say(`the implementation ended the process (exit status ${code}) while running this vector; the run ends here`);
    process.exitCode = 1;
  });
  const abort = process.abort.bind(process);
  process.abort = (): never => {
    if (beat[0] !== 0) say("the implementation aborted the process while running this vector");
    return abort();
  };
  return worker;
}

/** Name the vector in progress (this thread's own last store says which) with `what`. */
function say(what: string): void {
  writeSync(2, `plcvec: vector ${ids[beat[0]! - 1] ?? "?"}: ${what}\n`);
}

/** Number these vectors for the watchdog; returns the number of the first. */
export function register(list: readonly string[]): number {
  watchdog ??= start();
  noteDescriptors();
  const first = ids.length;
  ids.push(...list);
  const taken = Atomics.load(beat, 2);
  watchdog.postMessage(list);
  // Wait (bounded) until the watchdog has started and taken the list, so that it is idle between
  // ticks when the first vector runs. An implementation that closes the process's descriptors
  // (its event loops' own) then leaves the runner a tick to name the failing vector; closed while
  // the watchdog was still starting, they ended the process at once, before anything was said.
  Atomics.wait(beat, 2, taken, TAKEN_WITHIN_MS);
  return first;
}

/**
 * Vector number `n` (from register) starts: the watchdog's clock for it runs from here. Plain
 * stores, not atomic ones: only this thread writes, and the watchdog needs to see them within
 * its tick, not at once (an atomic store is a fence on every vector).
 */
export function enter(n: number): void {
  beat[0] = n + 1;
  beat[1]! += 1;
}

/** The id of the vector in progress (the process ends inside it when this is read at exit), or undefined. */
export function inProgress(): string | undefined {
  return beat[0] === 0 ? undefined : ids[beat[0]! - 1];
}

/** The vector in progress is done. */
export function leave(): void {
  beat[0] = 0;
}

/**
 * Each of `list` run as `body(index)` under the guard, in order. Each vector is bracketed by
 * enter/leave itself, not through a callback made per vector: the guard allocates nothing per vector.
 */
export function guarded<T>(list: readonly string[], body: (index: number) => T): T[] {
  const first = register(list);
  const out: T[] = [];
  for (let i = 0; i < list.length; i++) {
    enter(first + i);
    try {
      out.push(body(i));
    } finally {
      leave();
    }
  }
  return out;
}
