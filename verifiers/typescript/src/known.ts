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
import { readFileSync } from "node:fs";

import { parse, TomlError } from "smol-toml";

import { PlcvecError } from "./errors.js";

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
  let text: string;
  try {
    text = readFileSync(path, "utf8");
  } catch (err) {
    throw new PlcvecError(`${path}: cannot read the expectations file: ${(err as NodeJS.ErrnoException).code ?? String(err)}`);
  }
  return parseKnownFailures(text, path);
}

export function parseKnownFailures(text: string, path = "<expectations>"): KnownFailures {
  let data: Record<string, unknown>;
  try {
    data = parse(text) as Record<string, unknown>;
  } catch (err) {
    if (err instanceof TomlError) throw new PlcvecError(`${path}:${err.line}: not valid TOML: ${err.message.split("\n")[0]}`);
    throw err;
  }
  const lines = text.split("\n");
  const lineOf = (pattern: RegExp): number => lines.findIndex((l) => pattern.test(l)) + 1;
  const unknown = Object.keys(data).filter((k) => k !== SECTION);
  if (unknown.length) {
    const key = unknown.sort()[0] as string;
    throw new PlcvecError(
      `${path}:${lineOf(new RegExp(`^\\s*\\[*\\s*"?${key.replace(/[.*+?^${}()|[\]\\]/g, "\\$&")}`))}: unknown key ${JSON.stringify(key)}; ` +
        `an expectations file holds only [[${SECTION}]] entries`,
    );
  }
  const headers = lines.flatMap((l, i) => (l.trim().startsWith(`[[${SECTION}]]`) ? [i + 1] : []));
  const entries = data[SECTION] ?? [];
  if (!Array.isArray(entries)) throw new PlcvecError(`${path}: ${SECTION} must be an array of tables ([[${SECTION}]])`);
  const out = new Map<string, KnownFailure>();
  entries.forEach((entry: unknown, n: number) => {
    const where = `${path}:${headers[n] ?? 0}`;
    if (typeof entry !== "object" || entry === null) throw new PlcvecError(`${where}: [[${SECTION}]] must be a table`);
    const e = entry as Record<string, unknown>;
    const extra = Object.keys(e).filter((k) => k !== "id" && k !== "reason");
    if (extra.length) throw new PlcvecError(`${where}: unknown key ${JSON.stringify(extra[0])} (an entry has \`id\` and \`reason\`)`);
    if (typeof e["id"] !== "string" || e["id"] === "") throw new PlcvecError(`${where}: entry without an \`id\``);
    const id = e["id"];
    if (typeof e["reason"] !== "string" || e["reason"].trim() === "") {
      throw new PlcvecError(`${where}: ${id}: every known failure needs a \`reason\``);
    }
    const first = out.get(id);
    if (first !== undefined) throw new PlcvecError(`${where}: ${id} is listed twice (first at ${first.where})`);
    out.set(id, { id, reason: e["reason"].trim(), where });
  });
  return out;
}
