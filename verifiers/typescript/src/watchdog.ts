/**
 * The guard around an implementation: a bound on each vector's time, and the vector named when
 * the implementation ends the process.
 *
 * An implementation runs in the test's own thread (it is the user's object, closures and all), so
 * a synchronous loop that never returns cannot be interrupted there. A watchdog thread watches
 * instead: the runner stores the number of the vector in progress in shared memory (two atomic
 * stores per vector, nothing else), and when one vector has held it for PLCVEC_TIMEOUT seconds
 * the watchdog writes the vector's id to stderr and ends the process, which fails any test run.
 *
 * An implementation that calls `process.exit` half way, or `process.abort`, is caught at the
 * process's exit (or just before the abort): the vector in progress is named and the exit status
 * is made non-zero, so an early exit is never a green run.
 */
import { writeSync } from "node:fs";
import { Worker } from "node:worker_threads";

import { VerifyError } from "./errors.js";

/** The bound per vector when PLCVEC_TIMEOUT says none. */
export const DEFAULT_TIMEOUT_SECONDS = 10;

/** PLCVEC_TIMEOUT: seconds per vector, a positive number (default 10); anything else is a usage error. */
export function timeoutSeconds(env: NodeJS.ProcessEnv = process.env): number {
  const text = env["PLCVEC_TIMEOUT"];
  if (text === undefined || text === "") return DEFAULT_TIMEOUT_SECONDS;
  const seconds = Number(text.trim());
  if (text.trim() === "" || !Number.isFinite(seconds) || seconds <= 0) {
    throw new VerifyError(`PLCVEC_TIMEOUT=${JSON.stringify(text)}: seconds per vector, a positive number (default ${DEFAULT_TIMEOUT_SECONDS})`);
  }
  return seconds;
}

// The watchdog thread: CommonJS source, run with `eval`, so that it needs no file of its own.
const WATCHDOG = `
const { parentPort, workerData } = require("node:worker_threads");
const { writeSync } = require("node:fs");
const beat = new Int32Array(workerData.buffer);
const ids = [];
parentPort.on("message", (list) => { for (const id of list) ids.push(id); });
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

/** [0]: 1 + the number of the vector in progress, 0 when none; [1]: vectors started so far. */
let beat: Int32Array | undefined;
let watchdog: Worker | undefined;
/** Every vector registered in this process, by number. */
const ids: string[] = [];
/** The number of the vector in progress, or -1. */
let current = -1;

function start(): Int32Array {
  const seconds = timeoutSeconds();
  const shared = new Int32Array(new SharedArrayBuffer(8));
  const milliseconds = seconds * 1000;
  watchdog = new Worker(WATCHDOG, {
    eval: true,
    workerData: { buffer: shared.buffer, seconds, milliseconds, tick: Math.max(10, Math.min(250, milliseconds / 8)) },
    stdout: false,
    stderr: false,
  });
  watchdog.unref();
  process.on("exit", (code) => {
    if (current < 0) return;
    say(`the implementation ended the process (exit status ${code}) while running this vector; the run ends here`);
    process.exitCode = 1;
  });
  const abort = process.abort.bind(process);
  process.abort = (): never => {
    if (current >= 0) say("the implementation aborted the process while running this vector");
    return abort();
  };
  return shared;
}

function say(what: string): void {
  writeSync(2, `plcvec: vector ${ids[current] ?? "?"}: ${what}\n`);
}

/** Number these vectors for the watchdog; returns the number of the first. */
export function register(list: readonly string[]): number {
  beat ??= start();
  const first = ids.length;
  ids.push(...list);
  watchdog!.postMessage(list);
  return first;
}

/**
 * Vector number `n` (from register) starts: the watchdog's clock for it runs from here. Plain
 * stores, not atomic ones: only this thread writes, and the watchdog needs to see them within
 * its tick, not at once (an atomic store is a fence on every vector).
 */
export function enter(n: number): void {
  const b = beat!;
  current = n;
  b[0] = n + 1;
  b[1]! += 1;
}

/** The vector in progress is done. */
export function leave(): void {
  beat![0] = 0;
  current = -1;
}

/** Run `body` as vector number `n` (from register), under the bound and the exit guard. */
export function watched<T>(n: number, body: () => T): T {
  enter(n);
  try {
    return body();
  } finally {
    leave();
  }
}

/** Each of `list` run as `body(index)` under the guard, in order. */
export function guarded<T>(list: readonly string[], body: (index: number) => T): T[] {
  const first = register(list);
  const out: T[] = [];
  for (let i = 0; i < list.length; i++) out.push(watched(first + i, () => body(i)));
  return out;
}
