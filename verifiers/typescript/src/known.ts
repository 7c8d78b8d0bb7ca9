/**
 * The expectations file: vectors an implementation is known to fail, each with a reason.
 *
 *     [[known-failure]]
 *     id = "fx5-date-compare/LDDT</nonexistent/2024-2-30/s1/vs-previous"
 *     reason = "our calendar check rejects 2008/02/31 (tracked as #12)"
 *
 * The same TOML file every plcvec runner reads (CONTRACT.md). A listed vector that fails is
 * `xfail`; a listed vector that passes is `stale` and fails the run, and so does an id the suite
 * does not have: the list can only shrink. Ids are exact, never patterns.
 */
import { renameSync, writeFileSync } from "node:fs";

import { parse, TomlError } from "smol-toml";

import { VerifyError } from "./errors.js";
import { checkRegular, readRegular } from "./files.js";
import type { Suite } from "./suite.js";
import { ERROR, FAIL, FAILING, PASS, STALE, XFAIL, type Verdict } from "./verdict.js";

const SECTION = "known-failure";

export interface KnownFailure {
  readonly id: string;
  readonly reason: string;
  /** Where it is listed: `file:line`. */
  readonly where: string;
}

export type KnownFailures = ReadonlyMap<string, KnownFailure>;

/** Read an expectations file; every mistake in it is named with its file and line. */
export function loadKnownFailures(path: string): KnownFailures {
  // A named pipe nobody writes would hold the run before it starts: refused by name.
  const text = readRegular(path, "cannot read the expectations file").toString("utf8");
  return parseKnownFailures(text, path);
}

export function parseKnownFailures(text: string, path = "<expectations>"): KnownFailures {
  let data: Record<string, unknown>;
  try {
    data = parse(text) as Record<string, unknown>;
  } catch (err) {
    if (err instanceof TomlError) throw new VerifyError(`${path}:${err.line}: not valid TOML: ${err.message.split("\n")[0]}`);
    throw err;
  }
  const lines = text.split("\n");
  const lineOf = (pattern: RegExp): number => lines.findIndex((l) => pattern.test(l)) + 1;
  const unknown = Object.keys(data).filter((k) => k !== SECTION);
  if (unknown.length) {
    const key = unknown.sort()[0] as string;
    throw new VerifyError(
      `${path}:${lineOf(new RegExp(`^\\s*\\[*\\s*"?${key.replace(/[.*+?^${}()|[\]\\]/g, "\\$&")}`))}: unknown key ${JSON.stringify(key)}; ` +
        `an expectations file holds only [[${SECTION}]] entries`,
    );
  }
  const headers = lines.flatMap((l, i) => (l.trim().startsWith(`[[${SECTION}]]`) ? [i + 1] : []));
  const entries = data[SECTION] ?? [];
  if (!Array.isArray(entries)) throw new VerifyError(`${path}: ${SECTION} must be an array of tables ([[${SECTION}]])`);
  const out = new Map<string, KnownFailure>();
  entries.forEach((entry: unknown, n: number) => {
    const where = `${path}:${headers[n] ?? 0}`;
    if (typeof entry !== "object" || entry === null) throw new VerifyError(`${where}: [[${SECTION}]] must be a table`);
    const e = entry as Record<string, unknown>;
    const extra = Object.keys(e).filter((k) => k !== "id" && k !== "reason");
    if (extra.length) throw new VerifyError(`${where}: unknown key ${JSON.stringify(extra[0])} (an entry has \`id\` and \`reason\`)`);
    if (typeof e["id"] !== "string" || e["id"] === "") throw new VerifyError(`${where}: entry without an \`id\``);
    const id = e["id"];
    if (typeof e["reason"] !== "string" || e["reason"].trim() === "") {
      throw new VerifyError(`${where}: ${id}: every known failure needs a \`reason\``);
    }
    const first = out.get(id);
    if (first !== undefined) throw new VerifyError(`${where}: ${id} is listed twice (first at ${first.where})`);
    out.set(id, { id, reason: e["reason"].trim(), where });
  });
  return out;
}

/** Turn a listed failure into xfail and a listed pass into stale (the words `plcvec verify` uses). */
export function applyKnown(verdict: Verdict, known: KnownFailures | undefined): Verdict {
  const entry = known?.get(verdict.id);
  if (entry === undefined) return verdict;
  if (verdict.status === FAIL || verdict.status === ERROR) {
    const message = `known failure (${entry.where}): ${entry.reason}` + (verdict.message !== undefined ? `; ${verdict.message}` : "");
    return { ...verdict, status: XFAIL, message };
  }
  if (verdict.status === PASS) {
    return {
      ...verdict,
      status: STALE,
      message: `listed as a known failure (${entry.where}: ${entry.reason}) but it passes; remove it from the expectations file`,
    };
  }
  return verdict;
}

/** The judgedBy of a verdict for an id the suite does not have. */
const NO_VECTOR: Readonly<Record<string, string>> = Object.freeze({});

/**
 * A stale verdict for each listed id the suite does not have (one merely not selected is not
 * stale), in the file's order; an id the suite merged into another names the vector it is now.
 */
export function unknownIds(known: KnownFailures | undefined, suite: Suite): Verdict[] {
  const out: Verdict[] = [];
  for (const [id, entry] of known ?? []) {
    if (suite.byId.has(id)) continue;
    const now = suite.merged?.get(id);
    const why = now !== undefined ? `: it was merged into ${now}; list that id instead` : "; remove it from the expectations file";
    out.push({
      id,
      status: STALE,
      problems: [],
      message: `listed as a known failure (${entry.where}) but the suite has no such vector${why}`,
      judgedBy: NO_VECTOR,
      clauses: [],
    });
  }
  return out;
}

function tomlString(s: string): string {
  return `"${s.replace(/\\/g, "\\\\").replace(/"/g, '\\"')}"`;
}

/**
 * Write the failing vectors of a run as a new expectations file (for adopting the suite), as
 * `plcvec verify --write-expectations` does: written beside and renamed over, never half-written.
 */
export function writeExpectations(path: string, verdicts: readonly Verdict[], reason = "not yet triaged"): number {
  const lines = ["# Known failures: each passing entry fails the run as stale, so fix and delete.", ""];
  let n = 0;
  for (const v of [...verdicts].sort((a, b) => (a.id < b.id ? -1 : a.id > b.id ? 1 : 0))) {
    const listed = (FAILING.has(v.status) && !(v.status === STALE && v.judgedBy === NO_VECTOR)) || v.status === XFAIL;
    if (!listed) continue;
    lines.push(`[[${SECTION}]]`, `id = ${tomlString(v.id)}`, `reason = ${tomlString(reason)}`, "");
    n++;
  }
  checkRegular(path);
  const temporary = `${path}.${process.pid}.tmp`;
  try {
    writeFileSync(temporary, lines.join("\n"));
    renameSync(temporary, path);
  } catch (err) {
    throw new VerifyError(`${path}: cannot write the expectations file: ${(err as NodeJS.ErrnoException).code ?? String(err)}`);
  }
  return n;
}
