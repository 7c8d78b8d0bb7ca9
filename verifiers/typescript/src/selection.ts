/**
 * Choosing vectors: by family, instruction, tag, id glob, interpretation, and shard K/N.
 * Each list is OR within itself; the filters are AND together. Names the suite does not have are
 * errors that list the known ones: a typo in a CI file must not quietly turn the gate off.
 */
import { VerifyError } from "./errors.js";
import { setting } from "./settings.js";
import { interpretationsOf, type Suite } from "./suite.js";
import type { Vector } from "./vector.js";

export interface Selection {
  readonly families?: readonly string[];
  readonly instructions?: readonly string[];
  readonly tags?: readonly string[];
  /** Globs on the id: `*` any run of characters (slashes too), `?` one, `[...]` a set (fnmatch). */
  readonly ids?: readonly string[];
  /** Vectors whose outcome depends on one of these interpretations. */
  readonly interpretations?: readonly string[];
  /** [k, n]: the k-th of n shards (1 <= k <= n), by CRC-32 of the id, as every plcvec runner does. */
  readonly shard?: readonly [number, number];
}

const CRC_TABLE = (() => {
  const table = new Uint32Array(256);
  for (let n = 0; n < 256; n++) {
    let c = n;
    for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    table[n] = c >>> 0;
  }
  return table;
})();

/** CRC-32 (IEEE 802.3, the one zlib computes) of the UTF-8 bytes of `text`. */
export function crc32(text: string): number {
  let c = 0xffffffff;
  for (const byte of Buffer.from(text, "utf8")) c = (CRC_TABLE[(c ^ byte) & 0xff] as number) ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

/**
 * The shard (1..n) a vector belongs to: a hash of its id, not its position, so adding vectors moves
 * no other vector to another shard, and every language's runner splits the suite the same way.
 */
export function shardOf(id: string, n: number): number {
  return (crc32(id) % n) + 1;
}

/** "2/4" -> [2, 4]. */
export function parseShard(text: string): [number, number] {
  const m = /^(\d+)\/(\d+)$/.exec(text.trim());
  const k = m ? Number(m[1]) : NaN;
  const n = m ? Number(m[2]) : NaN;
  if (!m || !(k >= 1 && k <= n)) throw new VerifyError(`shard takes K/N with 1 <= K <= N (e.g. 2/4), got ${JSON.stringify(text)}`);
  return [k, n];
}

/** fnmatch's translation of a glob into an anchored regular expression. */
export function globToRegExp(glob: string): RegExp {
  let out = "";
  for (let i = 0; i < glob.length; i++) {
    const ch = glob[i] as string;
    if (ch === "*") out += ".*";
    else if (ch === "?") out += ".";
    else if (ch === "[") {
      const end = glob.indexOf("]", i + 2);
      if (end < 0) out += "\\[";
      else {
        let set = glob.slice(i + 1, end).replace(/\\/g, "\\\\");
        if (set.startsWith("!")) set = "^" + set.slice(1);
        out += `[${set}]`;
        i = end;
      }
    } else out += ch.replace(/[.+^${}()|\\\]]/g, "\\$&");
  }
  return new RegExp(`^${out}$`, "s");
}

function checkNames(what: string, asked: readonly string[] | undefined, known: Iterable<string>): void {
  if (!asked?.length) return;
  const have = new Set(known);
  const unknown = asked.filter((a) => !have.has(a));
  if (unknown.length) {
    throw new VerifyError(`unknown ${what} ${unknown.map((u) => JSON.stringify(u)).join(", ")} (known: ${[...have].sort().join(", ")})`);
  }
}

/** The vectors of `suite` that `selection` picks, in the suite's order; unknown names are errors. */
export function select(suite: Suite, selection: Selection = {}): Vector[] {
  const headers = [...suite.headers.values()];
  checkNames("family", selection.families, suite.headers.keys());
  checkNames("instruction", selection.instructions, headers.flatMap((h) => h.instructions));
  checkNames("tag", selection.tags, headers.flatMap((h) => Object.keys(h.tags)));
  checkNames("interpretation", selection.interpretations, interpretationsOf(suite).keys());
  const families = selection.families?.length ? new Set(selection.families) : undefined;
  const instructions = selection.instructions?.length ? new Set(selection.instructions) : undefined;
  const tags = selection.tags?.length ? new Set(selection.tags) : undefined;
  const interps = selection.interpretations?.length ? new Set(selection.interpretations) : undefined;
  const globs = selection.ids?.length ? selection.ids.map(globToRegExp) : undefined;
  // A glob that matches no id of the suite is a typo, not a narrow selection.
  for (const [i, g] of (globs ?? []).entries()) {
    if (!suite.vectors.some((v) => g.test(v.id))) {
      throw new VerifyError(`id glob ${JSON.stringify(selection.ids![i])} matches no vector id of the suite`);
    }
  }
  const shard = selection.shard;
  if (shard !== undefined) parseShard(`${shard[0]}/${shard[1]}`);
  return suite.vectors.filter(
    (v) =>
      (families === undefined || families.has(v.family)) &&
      (instructions === undefined || instructions.has(v.instruction)) &&
      (tags === undefined || v.tags.some((t) => tags.has(t))) &&
      (interps === undefined || (v.outcome.interpretations ?? []).some((i) => interps.has(i))) &&
      (globs === undefined || globs.some((g) => g.test(v.id))) &&
      (shard === undefined || shardOf(v.id, shard[1]) === shard[0]),
  );
}

/** The environment variables of a selection, each a comma-separated list (CONTRACT.md). */
const VARIABLES = [
  ["PLCVEC_ID", "ids"],
  ["PLCVEC_FAMILY", "families"],
  ["PLCVEC_INSTRUCTION", "instructions"],
  ["PLCVEC_TAG", "tags"],
  ["PLCVEC_INTERPRETATION", "interpretations"],
] as const;

/**
 * The selection the environment asks for: PLCVEC_ID (exact ids or globs), PLCVEC_FAMILY,
 * PLCVEC_INSTRUCTION, PLCVEC_TAG, PLCVEC_INTERPRETATION (comma-separated) and PLCVEC_SHARD (K/N).
 * An empty item (`PLCVEC_FAMILY=,`) is an error, never "no filter".
 */
export function environmentSelection(env: NodeJS.ProcessEnv = process.env): Selection {
  const out: { -readonly [K in keyof Selection]: Selection[K] } = {};
  for (const [variable, key] of VARIABLES) {
    const text = setting(variable, env);
    if (text === undefined) continue;
    const items = text.split(",").map((s) => s.trim());
    if (items.some((s) => s === "")) {
      throw new VerifyError(`${variable}=${JSON.stringify(text)}: an empty name in the list (names are separated by commas)`);
    }
    out[key] = items;
  }
  const shard = setting("PLCVEC_SHARD", env);
  if (shard !== undefined) {
    try {
      out.shard = parseShard(shard);
    } catch (err) {
      throw new VerifyError(`PLCVEC_SHARD=${JSON.stringify(shard)}: ${(err as Error).message}`);
    }
  }
  return out;
}

/**
 * The vectors both the code's selection and the environment's pick: the environment narrows what a
 * test file selects (PLCVEC_ID=one-id runs that one), and an unknown name in either is an error
 * that names its variable.
 */
export function selectWithEnvironment(suite: Suite, selection: Selection = {}, env: NodeJS.ProcessEnv = process.env): Vector[] {
  const fromCode = select(suite, selection);
  const fromEnv = environmentSelection(env);
  if (Object.keys(fromEnv).length === 0) return fromCode;
  let picked: ReadonlySet<Vector>;
  try {
    picked = new Set(select(suite, fromEnv));
  } catch (err) {
    if (!(err instanceof VerifyError)) throw err;
    const names = VARIABLES.filter(([v]) => env[v]).map(([v]) => `${v}=${JSON.stringify(env[v])}`).join(" ");
    throw new VerifyError(`${names}: ${err.message}`);
  }
  return fromCode.filter((v) => picked.has(v));
}
