/**
 * Reports: the run's text, in the one text every plcvec runner prints (verifiers/parity/TEXT.md):
 * each failing vector once, the roll-up by reading, the skips by reason, and the summary lines.
 */
import { inference } from "./infer.js";
import type { Report } from "./runner.js";
import { describe, ERROR, FAIL, FAILING, INDENT, SKIP, STATUS_ORDER, XFAIL, type Verdict } from "./verdict.js";

/** Vector ids shown under each group of the roll-up; skip reasons shown. */
const SHOW_IDS = 5;
const SHOW_REASONS = 12;
const byCodePoint = (a: string, b: string): number => (a < b ? -1 : a > b ? 1 : 0);
const pad6 = (n: number): string => String(n).padStart(6);

/** part/whole as a percentage with one decimal, rounded half up in integers. */
export function percent(part: number, whole: number): string {
  const w = Math.max(whole, 1);
  const tenths = Math.floor((2000 * part + w) / (2 * w));
  return `${Math.floor(tenths / 10)}.${tenths % 10}`;
}

/** The failure block of one verdict of this report, with its vector and the reading followed. */
export function block(report: Report, v: Verdict): string {
  return describe(v, report.suite.byId.get(v.id), { followed: report.choices, defaults: report.defaults });
}

/** How an implementer of each runner declares alternatives (TEXT.md, "The declaration in each runner"). */
export type DeclarationSyntax = "typescript" | "verify";

/** The declaration of these alternatives, sorted by interpretation, in a runner's syntax. */
export function declaration(changes: Readonly<Record<string, string>>, syntax: DeclarationSyntax = "typescript"): string {
  const ids = Object.keys(changes).sort(byCodePoint);
  if (syntax === "verify") return ids.map((i) => `--choose ${i}=${changes[i]}`).join(" ");
  return `choices: { ${ids.map((i) => `${JSON.stringify(i)}: ${JSON.stringify(changes[i])}`).join(", ")} }`;
}

type Changes = ReadonlyMap<string, readonly (readonly [string, string])[]>;

const readingOf = (change: readonly (readonly [string, string])[]): string => change.map(([i, a]) => `${i}=${a}`).join(", ");

/**
 * One line per smallest change, largest group first, each marked partial when a vector of `others`
 * (not explained) or of `broken` (passes now, would fail so declared) is of a family one of its
 * vectors is of: the reading does not account for everything the implementation does there.
 */
function groupLines(explained: Changes, others: readonly string[], broken: readonly string[], familyOf: (id: string) => string): string[] {
  const groups = new Map<string, string[]>();
  for (const [id, change] of explained) {
    const text = readingOf(change);
    (groups.get(text) ?? groups.set(text, []).get(text)!).push(id);
  }
  const lines: string[] = [];
  for (const [text, ids] of [...groups].sort(([a, x], [b, y]) => y.length - x.length || byCodePoint(a, b))) {
    const families = new Set(ids.map(familyOf));
    const near = others.filter((id) => families.has(familyOf(id)));
    const lost = broken.filter((id) => families.has(familyOf(id)));
    const named = [...new Set([...near, ...lost].map(familyOf))].sort(byCodePoint).join(", ");
    const mark = near.length || lost.length ? ` (partial: ${near.length} not explained, ${lost.length} would fail, in ${named})` : "";
    lines.push(`${INDENT}${pad6(ids.length)}  ${text}${mark}`);
  }
  return lines;
}

/** The `partial:` line: the vectors of the explained vectors' families that no reading explains or that the declaration would break. */
function partialLines(explained: Changes, others: readonly string[], broken: readonly string[], familyOf: (id: string) => string): string[] {
  const families = new Set([...explained.keys()].map(familyOf));
  const near = others.filter((id) => families.has(familyOf(id)));
  const lost = broken.filter((id) => families.has(familyOf(id)));
  if (near.length === 0 && lost.length === 0) return [];
  return [
    `${INDENT}partial: ${near.length} vectors no reading explains and ${lost.length} vectors that pass now are of the same families; ` +
      "the declaration may hide part of a bug there",
  ];
}

/** The failing vectors no reading explains, grouped by the clauses they cite. */
function unexplainedLines(report: Report, unexplained: readonly string[]): string[] {
  const lines = [`NOT EXPLAINED by any reading: ${unexplained.length} failing vectors, by the clauses they cite:`];
  const groups = new Map<string, string[]>();
  for (const id of unexplained) {
    const key = report.suite.byId.get(id)?.clauses.join(", ") || "(no clauses)";
    (groups.get(key) ?? groups.set(key, []).get(key)!).push(id);
  }
  for (const [key, ids] of [...groups].sort(([a, x], [b, y]) => y.length - x.length || byCodePoint(a, b))) {
    lines.push(`${INDENT}${pad6(ids.length)}  ${key}`);
    for (const id of [...ids].sort(byCodePoint).slice(0, SHOW_IDS)) lines.push(`${INDENT}${" ".repeat(6)}  ${id}`);
    if (ids.length > SHOW_IDS) lines.push(`${INDENT}${" ".repeat(6)}  ... and ${ids.length - SHOW_IDS} more`);
  }
  return lines;
}

/**
 * The failing vectors and the known failures grouped by what would explain them (TEXT.md, "The
 * roll-up by reading"): the readings, each marked partial where failures of its families stay
 * unexplained; the failures no reading explains; the known failures another reading explains.
 */
export function rollupLines(report: Report, syntax: DeclarationSyntax = "typescript"): string[] {
  const failing = report.verdicts.filter((v) => v.status === FAIL || v.status === ERROR);
  const known = report.verdicts.filter((v) => v.status === XFAIL);
  if (failing.length === 0 && known.length === 0) return [];
  const inferred = inference(report.verdicts, report.suite, report.interpretations, report.choices, report.defaults, new Set(report.cpuWrites));
  const familyOf = (id: string): string => report.suite.byId.get(id)?.family ?? "";
  const lines: string[] = [];
  if (inferred.explained.size) {
    lines.push(`READINGS: ${inferred.explained.size} of ${failing.length} failing vectors pass under other alternatives:`);
    lines.push(...groupLines(inferred.explained, inferred.unexplained, inferred.broken, familyOf));
    const changes: Record<string, string> = {};
    for (const i of Object.keys(inferred.choice)) if (inferred.choice[i] !== inferred.followed[i]) changes[i] = inferred.choice[i]!;
    lines.push(`${INDENT}declare: ${declaration(changes, syntax)}`);
    if (inferred.broken.length) lines.push(`${INDENT}(so declared, ${inferred.broken.length} vectors that pass now would fail)`);
    lines.push(...partialLines(inferred.explained, inferred.unexplained, inferred.broken, familyOf));
  }
  if (inferred.unexplained.length) lines.push(...unexplainedLines(report, inferred.unexplained));
  if (inferred.knownExplained.size) {
    lines.push(`KNOWN FAILURES: ${inferred.knownExplained.size} of ${known.length} known failures pass under other alternatives:`);
    const others = [...inferred.unexplained, ...inferred.knownUnexplained];
    lines.push(...groupLines(inferred.knownExplained, others, inferred.broken, familyOf));
    const changes: Record<string, string> = {};
    for (const change of inferred.knownExplained.values()) for (const [i, a] of change) changes[i] = a;
    lines.push(`${INDENT}declare: ${declaration(changes, syntax)}`);
    lines.push(`${INDENT}then remove those ${inferred.knownExplained.size} known failures from ${report.knownFile ?? "the known-failures file"}`);
  }
  return lines;
}

/** How many vectors were skipped and why, most common reason first (ties by reason). */
export function skippedLines(report: Report): string[] {
  const skipped = report.verdicts.filter((v) => v.status === SKIP).map((v) => v.message ?? "");
  if (skipped.length === 0) return [];
  const counts = new Map<string, number>();
  for (const reason of skipped) counts.set(reason, (counts.get(reason) ?? 0) + 1);
  const reasons = [...counts].sort(([a, m], [b, n]) => n - m || byCodePoint(a, b));
  const lines = [`SKIPPED ${skipped.length} of ${report.selected} vectors (${percent(skipped.length, report.selected)}%):`];
  for (const [reason, n] of reasons.slice(0, SHOW_REASONS)) lines.push(`${INDENT}${pad6(n)}  ${reason || "(no reason given)"}`);
  if (reasons.length > SHOW_REASONS) lines.push(`${INDENT}... and ${reasons.length - SHOW_REASONS} more reasons (--jsonl lists each vector)`);
  return lines;
}

/** The summary lines after the empty line: header, interpretations, cpu_writes, totals (without the time). */
export function summaryLines(report: Report): string[] {
  const s = report.suite;
  const lines = [
    `plcvec verify: ${report.implementation} against ${s.source} (suite ${s.suiteVersion || "?"}, schema ${s.schemaVersion}, spec sha256 ${s.specSha256.slice(0, 12) || "?"})`,
  ];
  const items = [...report.interpretations.keys()]
    .sort(byCodePoint)
    .map((i) => `${i}=${report.choices[i]} (${i in report.declared ? "declared" : "default"})`);
  lines.push(`interpretations: ${items.join(", ") || "(none)"}`);
  if (report.cpuWrites.length) lines.push(`cpu_writes: ${report.cpuWrites.join(", ")}`);
  const c = report.counts;
  const parts = STATUS_ORDER.filter((st) => c[st] || st === "pass" || st === "fail" || st === "skip").map((st) => `${c[st]} ${st}`);
  lines.push(`${report.verdicts.length} vectors: ${parts.join(", ")}`);
  return lines;
}

/**
 * The run's text (TEXT.md, "The run's text"): a failure block for each failing vector (`blocks:
 * false` when the test runner has printed each already), the roll-up, the skips, why the run fails
 * as a whole, an empty line and the summary lines, the totals with the run's seconds. The roll-up
 * declares alternatives as a TypeScript implementation does (`choices: { ... }`), or as
 * `plcvec verify` takes them (`declaration: "verify"`, the form of the shared text cases).
 */
export function summaryText(report: Report, options: { readonly blocks?: boolean; readonly declaration?: DeclarationSyntax } = {}): string {
  const lines: string[] = [];
  if (options.blocks !== false) for (const v of report.verdicts) if (FAILING.has(v.status)) lines.push(block(report, v));
  lines.push(...rollupLines(report, options.declaration), ...skippedLines(report));
  if (!report.verdicts.some((v) => FAILING.has(v.status)) && report.runProblems.length) {
    lines.push(`NOT PASSED (exit ${report.exitCode}): ${report.runProblems.join("; ")}`);
  }
  const summary = summaryLines(report);
  summary[summary.length - 1] += ` in ${report.seconds.toFixed(2)} s`;
  lines.push("", ...summary);
  return `${lines.join("\n")}\n`;
}
