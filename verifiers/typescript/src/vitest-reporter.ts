/**
 * A Vitest reporter that fails a run in which no plcvec vector ran: Vitest's own `-t` filter that
 * matches no test skips the whole file, `afterAll(checkRun)` included, and Vitest exits 0.
 *
 *     npx vitest run --reporter=default --reporter=plcvec/vitest-reporter
 */
import { writeSync } from "node:fs";

import { isVectorName, NOTHING_RAN } from "./nothing-ran.js";

/** The members of Vitest's tasks this reporter reads (the task tree of `onFinished`, Vitest 1 to 3). */
interface Task {
  readonly type?: string;
  readonly name?: string;
  readonly result?: { readonly state?: string };
  readonly tasks?: readonly Task[];
}

/** The members of a test module this reporter reads (`onTestRunEnd`, Vitest 3 and later). */
interface TestModule {
  readonly children: { allTests(): Iterable<{ readonly name: string; result(): { readonly state: string } }> };
}

function vectorsRan(tasks: readonly Task[]): number {
  let n = 0;
  for (const t of tasks) {
    const state = t.result?.state;
    if (t.type === "test" && (state === "pass" || state === "fail") && isVectorName(t.name)) n++;
    n += vectorsRan(t.tasks ?? []);
  }
  return n;
}

export default class PlcvecVitestReporter {
  #judged = false;

  /** Vitest 3 and later: the run's test modules. */
  onTestRunEnd(modules: readonly TestModule[] = []): void {
    let n = 0;
    for (const m of modules) for (const t of m.children.allTests()) if (["passed", "failed"].includes(t.result().state) && isVectorName(t.name)) n++;
    this.#judge(n);
  }

  /** Vitest 1 and 2 (3 calls both: the first judges). */
  onFinished(files: readonly Task[] = []): void {
    this.#judge(vectorsRan(files));
  }

  #judge(vectors: number): void {
    if (this.#judged) return;
    this.#judged = true;
    if (vectors > 0) return;
    writeSync(2, `plcvec/vitest-reporter: ${NOTHING_RAN}\n`);
    process.exitCode = 1;
  }
}
