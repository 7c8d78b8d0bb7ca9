/**
 * The suite as a plain list of test cases, for any test runner: a loop of `test` in Vitest or Jest,
 * or a loop of your own. Each case is named by its vector id; `check()` throws a VectorFailure
 * carrying the field-level diff when the implementation disagrees.
 *
 *     import { cases, checkRun } from "plcvec";
 *     const list = cases(myImplementation);
 *     for (const c of list) test(c.id, () => c.check());
 *     afterAll(() => checkRun(list));
 *
 * Everything a gate reads from the environment is read here (CONTRACT.md): PLCVEC_VECTORS,
 * PLCVEC_ID, PLCVEC_FAMILY, PLCVEC_INSTRUCTION, PLCVEC_TAG, PLCVEC_INTERPRETATION, PLCVEC_SHARD,
 * PLCVEC_KNOWN_FAILURES, PLCVEC_WRITE_EXPECTATIONS and PLCVEC_TIMEOUT.
 */
import { writeSync } from "node:fs";
import { inspect } from "node:util";

import { VerifyError } from "./errors.js";
import type { Implementation } from "./implementation.js";
import { unknownIds, writeExpectations, type KnownFailures } from "./known.js";
import { descriptorsClosed } from "./leftovers.js";
import { summaryText } from "./reports.js";
import { planRun, reportWith, runOne, summarize, type Plan, type Report } from "./runner.js";
import type { Selection } from "./selection.js";
import { setting } from "./settings.js";
import type { Suite } from "./suite.js";
import { describe, FAILING, type Verdict } from "./verdict.js";
import { enter, inProgress, leave, register } from "./watchdog.js";

/** A vector the implementation does not pass; its message is the whole field-level diff, with no stack to read past. */
export class VectorFailure extends Error {
  override readonly name = "VectorFailure";
  constructor(message: string) {
    super(message);
    this.stack = `${this.name}: ${message}`;
  }

  /** Reporters that inspect the error show the text as it is, not in the brackets of an error without frames. */
  [inspect.custom](): string {
    return this.stack ?? this.message;
  }
}

export interface CaseOptions {
  readonly suite?: Suite;
  /** What the test file selects; the PLCVEC_* variables narrow it further. */
  readonly selection?: Selection;
  /** Default: the file PLCVEC_KNOWN_FAILURES names, if any. */
  readonly known?: KnownFailures;
  /** A selection of no vector fails unless this is set. */
  readonly allowEmpty?: boolean;
  /** Fail when more vectors than this are skipped: a count, or a percentage such as "5%". */
  readonly maxSkipped?: number | `${number}%`;
}

export interface Case {
  readonly id: string;
  readonly family: string;
  readonly instruction: string;
  readonly tags: readonly string[];
  /** Run the vector and give its verdict (known failures applied), without throwing. */
  run(): Verdict;
  /** Run the vector and throw a VectorFailure with the diff unless it passes (or is a known failure that still fails). */
  check(): Verdict;
}

/** What a list of cases shares: the run's verdicts so far and what it was made with. */
interface Run {
  readonly impl: Implementation;
  readonly plan: Plan;
  readonly options: CaseOptions;
  readonly started: number;
  readonly verdicts: Verdict[];
}

const runs = new WeakMap<readonly Case[], Run>();

/** One case per selected vector; expectations are worked out lazily, when a case runs. */
export function cases(impl: Implementation, options: CaseOptions = {}): Case[] {
  const plan = planRun(impl, options);
  if (plan.vectors.length === 0 && !options.allowEmpty) {
    throw new VerifyError("the selection holds no vector: a gate that runs nothing would pass by accident (allowEmpty to accept that)");
  }
  const first = register(plan.vectors.map((v) => v.id));
  const verdicts: Verdict[] = [];
  const reading = { followed: plan.followed.choices, defaults: plan.followed.defaults };
  const list = plan.vectors.map((vector, i): Case => {
    const run = (): Verdict => {
      let verdict: Verdict;
      enter(first + i);
      try {
        verdict = runOne(plan, impl, i);
      } finally {
        leave();
      }
      verdicts.push(verdict);
      return verdict;
    };
    return {
      id: vector.id,
      family: vector.family,
      instruction: vector.instruction,
      tags: vector.tags,
      run,
      check(): Verdict {
        const verdict = run();
        if (!FAILING.has(verdict.status)) return verdict;
        const block = describe(verdict, vector, reading);
        // Descriptors the process uses were closed: it may not live to report this; say it now.
        if (descriptorsClosed()) writeSync(2, `${block}\n`);
        throw new VectorFailure(block);
        return verdict;
      },
    };
  });
  runs.set(list, { impl, plan, options, started: performance.now(), verdicts });
  return list;
}

/**
 * The run of these cases as a whole: the verdicts of the cases that ran, the known failures the
 * suite does not have (stale), and why the run fails though no case did. When no case ran at all
 * although the selection held some, and no vector ended the process half way, the test runner's
 * own filter left none: that is a failure too. Writes PLCVEC_WRITE_EXPECTATIONS when it is set.
 */
export function runReport(list: readonly Case[]): Report {
  const run = runs.get(list);
  if (run === undefined) throw new VerifyError("runReport takes the list cases() returned");
  const { plan } = run;
  const verdicts = [...run.verdicts, ...unknownIds(plan.known, plan.suite)];
  const report = summarize(run.impl, verdicts, plan.suite, plan.followed, {
    ...run.options,
    selected: run.verdicts.length,
    seconds: (performance.now() - run.started) / 1000,
    ...(plan.knownFile !== undefined ? { knownFile: plan.knownFile } : {}),
  });
  const write = setting("PLCVEC_WRITE_EXPECTATIONS");
  if (write !== undefined) writeExpectations(write, verdicts);
  const ended = inProgress();
  if (ended !== undefined) {
    // The process is ending inside a vector: the implementation ended it; no filter is to blame.
    return reportWith(report, [`the implementation ended the process while running ${ended}; the vectors after it did not run`], 1);
  }
  if (run.verdicts.length === 0 && plan.vectors.length > 0) {
    const filtered =
      `none of the ${plan.vectors.length} selected vectors ran: the test runner's own filter (--test-name-pattern, ` +
      "vitest -t, jest -t) matched none of them; choose vectors with PLCVEC_ID=<id or glob>[,...] instead";
    return reportWith(report, [filtered], 5);
  }
  return report;
}

/**
 * Throw unless the run of these cases passed as a whole (see runReport): for an `afterAll` hook.
 * The message is the run's text without the failure blocks the test runner has shown already:
 * the stale ids the suite does not have, the roll-up by reading, the skips, the summary.
 */
export function checkRun(list: readonly Case[]): Report {
  const report = runReport(list);
  if (report.passed) return report;
  const stale = report.verdicts.filter((v) => v.status === "stale" && !report.suite.byId.has(v.id)).map((v) => describe(v));
  throw new VectorFailure(
    [...stale, ...report.runProblems.map((p) => `RUN FAILS: ${p}`), summaryText(report, { blocks: false }).trimEnd()].join("\n"),
  );
}
