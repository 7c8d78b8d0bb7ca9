/**
 * Reports: the run as text (suite, choices, every failing vector, the totals line).
 */
import type { Report } from "./runner.js";
import { describe, FAILING } from "./verdict.js";

/** The report as text: suite, choices, every failing vector, and the totals line. */
export function summaryText(report: Report): string {
  const s = report.suite;
  const lines = [
    `plcvec ${s.suiteVersion || "(unknown version)"}, schema ${s.schemaVersion}, spec ${s.specSha256.slice(0, 12)}, vectors from ${s.source}`,
    `implementation: ${report.implementation}`,
    `alternatives: ${Object.entries(report.choices).map(([i, a]) => `${i}=${a}`).join(", ")}`,
  ];
  if (report.cpuWrites.length) lines.push(`cpu writes: ${report.cpuWrites.join(", ")}`);
  for (const r of report.verdicts) if (FAILING.has(r.status)) lines.push(describe(r));
  for (const p of report.runProblems) lines.push(`RUN FAILS: ${p}`);
  const c = report.counts;
  lines.push(`${c.pass} passed, ${c.fail + c.error + c.stale} failed, ${c.skip} skipped` +
    (c.xfail ? `, ${c.xfail} known failures` : "") + (c.error ? ` (${c.error} errors)` : "") + (c.stale ? ` (${c.stale} stale)` : ""));
  return lines.join("\n");
}
