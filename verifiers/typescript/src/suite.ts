/**
 * Loading a vector set: the copy this package carries, or the folder `PLCVEC_VECTORS` names.
 *
 * A set is a folder with `index.json` and one `<family>.jsonl` per family (what
 * `plcvec export` writes), or the repository's `vectors/` folder (`manifest.json` and one
 * `<family>.json` each), or one such family file. Every vector is checked for what the
 * contract needs before anything runs, so a damaged file is named with its line and vector id
 * instead of failing half-way through a run.
 */
import { createHash } from "node:crypto";
import { existsSync, statSync } from "node:fs";
import { join } from "node:path";
import { fileURLToPath } from "node:url";

import { VerifyError } from "./errors.js";
import { mayRepeatKeys, notRegular, readRegular, repeatedKey } from "./files.js";
import { setting } from "./settings.js";
import { headerProblem, vectorProblem } from "./validate.js";
import type { FamilyHeader, InterpretationHeader, Vector } from "./vector.js";

/** The major schema version this runner reads (CONTRACT.md, "Versioning"): a 2.x file is refused, not misread. */
export const SCHEMA_MAJOR = 1;

/** The folder of vectors inside this package (dist/src/load.js -> ../../vectors). */
export const PACKAGED_VECTORS = fileURLToPath(new URL("../../vectors/", import.meta.url));

export interface Suite {
  readonly vectors: readonly Vector[];
  readonly headers: ReadonlyMap<string, FamilyHeader>;
  readonly byId: ReadonlyMap<string, Vector>;
  readonly source: string;
  readonly suiteVersion: string;
  readonly schemaVersion: string;
  readonly specSha256: string;
  /** Ids the suite merged into another vector (the index's `merged`), each with the id it is now. */
  readonly merged?: ReadonlyMap<string, string>;
}

export interface InterpretationInfo {
  readonly id: string;
  readonly default: string;
  readonly alternatives: readonly string[];
  readonly families: readonly string[];
}

/** Where vectors come from when nothing is said: `PLCVEC_VECTORS`, else the packaged copy. */
export function defaultVectorsPath(): string {
  return setting("PLCVEC_VECTORS") ?? PACKAGED_VECTORS;
}

const cache = new Map<string, Suite>();

/** Load (once per path and process) the vector set at `path` (default: see defaultVectorsPath). */
export function loadSuite(path: string = defaultVectorsPath()): Suite {
  let suite = cache.get(path);
  if (suite === undefined) {
    suite = readSuite(path);
    cache.set(path, suite);
  }
  return suite;
}

/** What a vector folder's index (index.json, else manifest.json) lists, or a lone family file as its own listing. */
interface Listing {
  readonly files: readonly string[];
  readonly sums: ReadonlyMap<string, string>;
  readonly counts: ReadonlyMap<string, number>;
  readonly suiteVersion: string;
  readonly setHash: string;
  readonly merged: ReadonlyMap<string, string>;
}

function listingOf(path: string): Listing {
  if (!isFolder(path)) return { files: [path], sums: new Map(), counts: new Map(), suiteVersion: "", setHash: "", merged: new Map() };
  const index = join(path, "index.json");
  const listing = existsSync(index) || notRegular(index) ? index : join(path, "manifest.json");
  if (!existsSync(listing) && !notRegular(listing)) {
    throw new VerifyError(`${path}: no index.json (a folder written by plcvec export) nor manifest.json (the repository's vectors/)`);
  }
  const data = readIndex(listing) as {
    families?: Record<string, { file?: string; sha256?: string; count?: number }>;
    suite_version?: string;
    generator_version?: string;
    spec_sha256?: string;
    merged?: unknown;
  };
  if (typeof data.families !== "object" || data.families === null) {
    throw new VerifyError(`${listing}: no \`families\`; is this a plcvec vector folder?`);
  }
  const files: string[] = [];
  const sums = new Map<string, string>();
  const counts = new Map<string, number>();
  for (const [family, entry] of Object.entries(data.families)) {
    if (typeof entry?.file !== "string") throw new VerifyError(`${listing}: family ${family} names no \`file\``);
    const file = join(path, entry.file);
    files.push(file);
    if (typeof entry.sha256 === "string") sums.set(file, entry.sha256);
    if (typeof entry.count === "number") counts.set(file, entry.count);
  }
  return {
    files,
    sums,
    counts,
    suiteVersion: String(data.suite_version ?? data.generator_version ?? ""),
    setHash: String(data.spec_sha256 ?? ""),
    merged: mergedIds(data.merged),
  };
}

function readSuite(path: string): Suite {
  if (!existsSync(path) && !notRegular(path)) throw new VerifyError(`${path}: no such vector folder or file`);
  const { files, sums, counts, suiteVersion, setHash, merged } = listingOf(path);
  const headers = new Map<string, FamilyHeader>();
  const vectors: Vector[] = [];
  const byId = new Map<string, Vector>();
  const schemaVersions = new Set<string>();
  for (const file of files) {
    const bytes = readRegular(file);
    const actual = createHash("sha256").update(bytes).digest("hex");
    // The bytes of a file this package ships were checked for repeated keys and against the schema
    // by its tests (test/load.test.ts): not again. Any other bytes (an edited copy) are checked in full.
    const shipped = packagedSums().has(actual);
    const { header, entries } = file.endsWith(".jsonl") ? readJsonl(file, bytes, !shipped) : readFamilyJson(file, bytes, !shipped);
    const version = String(header.schema_version ?? "");
    if (version.split(".")[0] !== String(SCHEMA_MAJOR)) {
      throw new VerifyError(
        `${file}: schema_version ${version || "(none)"} is not ${SCHEMA_MAJOR}.x; this runner reads ${SCHEMA_MAJOR}.x ` +
          "files only (see CONTRACT.md, Versioning)",
      );
    }
    schemaVersions.add(version);
    headers.set(header.family, header);
    for (const { value, where } of entries) {
      const problem = shipped ? undefined : vectorProblem(value, header.family);
      if (problem !== undefined) {
        const id = typeof (value as { id?: unknown })?.id === "string" ? (value as { id: string }).id : "(no id)";
        throw new VerifyError(`${where}: vector ${id}: ${problem}`);
      }
      const vector = value as Vector;
      if (byId.has(vector.id)) throw new VerifyError(`${where}: vector id ${vector.id} appears twice`);
      byId.set(vector.id, vector);
      vectors.push(vector);
    }
    // After the content, so that a damaged line is named by its line: an edit or a cut that
    // leaves every line sound is still caught by the count and the sha256 the listing records.
    const listed = counts.get(file);
    if (typeof header.count === "number" && header.count !== entries.length) {
      throw new VerifyError(`${file}: holds ${entries.length} vectors, its header says ${header.count} (a cut or edited copy)`);
    }
    if (listed !== undefined && listed !== entries.length) {
      throw new VerifyError(`${file}: holds ${entries.length} vectors, the listing says ${listed} (a cut or edited copy)`);
    }
    const sha256 = sums.get(file);
    if (sha256 !== undefined) {
      if (actual !== sha256) {
        throw new VerifyError(`${file}: sha256 ${actual} is not the ${sha256} its listing gives (a damaged or edited copy)`);
      }
    }
  }
  const hashes = [...headers.values()].map((h) => h.spec_sha256);
  return {
    vectors,
    headers,
    byId,
    source: path,
    suiteVersion,
    schemaVersion: [...schemaVersions].sort().join(", "),
    specSha256: setHash || [...new Set(hashes)].sort().join(", "),
    merged,
  };
}

let packaged: ReadonlySet<string> | undefined;

/**
 * The sha256 of each family file this package ships (its index.json): such bytes were checked for
 * repeated keys and every vector against the schema when the package was tested (test/load.test.ts),
 * so loading them again skips both. Any other bytes, a damaged or edited copy
 * or another set, are checked in full.
 */
export function packagedSums(): ReadonlySet<string> {
  if (packaged === undefined) {
    let sums: string[] = [];
    try {
      const index = JSON.parse(readRegular(join(PACKAGED_VECTORS, "index.json")).toString("utf8")) as { families?: Record<string, { sha256?: unknown }> };
      sums = Object.values(index.families ?? {}).flatMap((f) => (typeof f.sha256 === "string" ? [f.sha256] : []));
    } catch {
      // no packaged copy to trust: every file is scanned
    }
    packaged = new Set(sums);
  }
  return packaged;
}

/** Whether a folder is at `path` (a loop of symbolic links is no folder: reading it names the loop). */
function isFolder(path: string): boolean {
  try {
    return statSync(path).isDirectory();
  } catch {
    return false;
  }
}

/**
 * {old id: the id it is now} from an index's {family: {old id: the id it went to}}, each chain of
 * merges followed to its end (a vector merged into one that was merged again).
 */
function mergedIds(merged: unknown): Map<string, string> {
  const flat = new Map<string, string>();
  if (typeof merged === "object" && merged !== null) {
    for (const ids of Object.values(merged as Record<string, unknown>)) {
      if (typeof ids !== "object" || ids === null) continue;
      for (const [old, now] of Object.entries(ids as Record<string, unknown>)) if (typeof now === "string") flat.set(old, now);
    }
  }
  const out = new Map<string, string>();
  for (const [old, first] of flat) {
    const seen = new Set([old]);
    let now = first;
    while (flat.has(now) && !seen.has(now)) {
      seen.add(now);
      now = flat.get(now)!;
    }
    out.set(old, now);
  }
  return out;
}

interface Entry {
  readonly value: unknown;
  readonly where: string;
}

const UTF8 = new TextDecoder("utf-8", { fatal: true });

/** The bytes as text; a byte that is not UTF-8 is named by its line, never replaced. */
function decode(file: string, bytes: Buffer): string {
  try {
    return UTF8.decode(bytes);
  } catch {
    let start = 0;
    for (let line = 1; ; line++) {
      const end = bytes.indexOf(0x0a, start);
      try {
        UTF8.decode(bytes.subarray(start, end < 0 ? bytes.length : end));
      } catch {
        throw new VerifyError(`${file}:${line}: not UTF-8 text`);
      }
      if (end < 0) throw new VerifyError(`${file}: not UTF-8 text`);
      start = end + 1;
    }
  }
}

function readJson(file: string, bytes: Buffer = readRegular(file)): { text: string; value: unknown } {
  const text = decode(file, bytes);
  try {
    return { text, value: JSON.parse(text) };
  } catch (err) {
    throw new VerifyError(`${file}: not valid JSON (${(err as Error).message})`);
  }
}

/** An index (index.json or manifest.json): small, so checked for a repeated key at every load. */
function readIndex(file: string): unknown {
  const { text, value } = readJson(file);
  refuseRepeatedKey(file, text, value, 0, () => undefined);
  return value;
}

/**
 * Refuse a repeated key in `text` (parsed as `value`), naming `file`, the line (counted from
 * `firstLine`) and, where `vectorAt` finds one for the key's path, the vector it is in.
 */
function refuseRepeatedKey(file: string, text: string, value: unknown, firstLine: number, vectorAt: (path: readonly (string | number)[]) => string | undefined): void {
  if (!mayRepeatKeys(text, value)) return;
  const found = repeatedKey(text);
  if (found === undefined) return;
  const vector = vectorAt(found.path);
  throw new VerifyError(`${file}:${found.line + firstLine}: ${vector !== undefined ? `vector ${vector}: ` : ""}repeated key ${JSON.stringify(found.key)}`);
}

const idOf = (value: unknown): string | undefined => {
  const id = (value as { id?: unknown } | null)?.id;
  return typeof id === "string" ? id : undefined;
};

function checkHeader(value: unknown, where: string): FamilyHeader {
  const problem = headerProblem(value);
  if (problem !== undefined) throw new VerifyError(`${where}: not a plcvec family header: ${problem}`);
  return value as FamilyHeader;
}

function readJsonl(file: string, bytes: Buffer, keys: boolean): { header: FamilyHeader; entries: Entry[] } {
  const text = decode(file, bytes);
  if (text.trim() === "") throw new VerifyError(`${file}: empty file (no header line)`);
  const lines = text.split("\n");
  if (lines[lines.length - 1] === "") lines.pop();
  else throw new VerifyError(`${file}:${lines.length}: the last line has no end (a cut copy)`);
  const entries: Entry[] = [];
  let header: FamilyHeader | undefined;
  lines.forEach((line, i) => {
    const where = `${file}:${i + 1}`;
    let value: unknown;
    try {
      value = JSON.parse(line);
    } catch (err) {
      throw new VerifyError(`${where}: not valid JSON (${(err as Error).message})`);
    }
    if (keys) refuseRepeatedKey(file, line, value, i, () => (i === 0 ? undefined : idOf(value)));
    if (i === 0) header = checkHeader(value, where);
    else entries.push({ value, where });
  });
  if (header === undefined) throw new VerifyError(`${file}: empty file (no header line)`);
  return { header, entries };
}

function readFamilyJson(file: string, bytes: Buffer, keys: boolean): { header: FamilyHeader; entries: Entry[] } {
  const { text, value } = readJson(file, bytes);
  const data = value as Record<string, unknown> | null;
  if (keys) refuseRepeatedKey(file, text, value, 0, (path) =>
    path[0] === "vectors" && typeof path[1] === "number" ? idOf((data?.["vectors"] as unknown[] | undefined)?.[path[1]]) : undefined,
  );
  if (typeof data !== "object" || data === null || !Array.isArray(data["vectors"])) {
    throw new VerifyError(`${file}: not a plcvec vector file (no \`family\` and \`vectors\`)`);
  }
  const { vectors, ...rest } = data;
  const header = checkHeader(rest, file);
  return { header, entries: (vectors as unknown[]).map((value, i) => ({ value, where: `${file} (vector #${i})` })) };
}

/**
 * The interpretations of the given families (all by default), each once: the FX5 time and date
 * comparisons share theirs, and an implementation declares it once for both.
 */
export function interpretationsOf(suite: Suite, families?: Iterable<string>): Map<string, InterpretationInfo> {
  const wanted = families === undefined ? undefined : new Set(families);
  const out = new Map<string, { id: string; default: string; alternatives: string[]; families: string[] }>();
  for (const [family, header] of [...suite.headers.entries()].sort(([a], [b]) => (a < b ? -1 : a > b ? 1 : 0))) {
    if (wanted !== undefined && !wanted.has(family)) continue;
    for (const interp of header.interpretations as readonly InterpretationHeader[]) {
      const alternatives = interp.alternatives.map((a) => a.id);
      const seen = out.get(interp.id);
      if (seen === undefined) {
        out.set(interp.id, { id: interp.id, default: interp.default, alternatives, families: [family] });
      } else if (seen.default !== interp.default || seen.alternatives.join() !== alternatives.join()) {
        throw new VerifyError(
          `${suite.source}: interpretation ${interp.id} has other alternatives or another default in ${family} than in ${seen.families[0]}`,
        );
      } else {
        seen.families.push(family);
      }
    }
  }
  return out;
}
