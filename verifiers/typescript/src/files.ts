/**
 * Reading the files a run trusts: only regular files, and JSON with no key given twice
 * (CONTRACT.md, "Loading").
 *
 * A named pipe nobody writes, a device that never ends (/dev/zero) or a loop of symbolic links
 * where a vector file belongs would hang a loader that opens it without looking, so a path is
 * looked at first and refused by name. A JSON object holding one key twice is refused too:
 * parsers in other languages disagree on which value wins (JSON.parse keeps the last), so the
 * runners could judge one file several ways.
 */
import { closeSync, constants, fstatSync, openSync, readFileSync, statSync, type Stats } from "node:fs";

import { VerifyError } from "./errors.js";

/** What is at `path` when it is not a regular file ("" for a regular file or nothing at all). */
export function notRegular(path: string): string {
  let stats: Stats;
  try {
    stats = statSync(path);
  } catch (err) {
    const code = (err as NodeJS.ErrnoException).code;
    return code === "ELOOP" ? "a loop of symbolic links" : ""; // nothing there: the open says so
  }
  return kindOf(stats);
}

function kindOf(stats: Stats): string {
  if (stats.isFile()) return "";
  if (stats.isFIFO()) return "not a regular file (a named pipe)";
  if (stats.isCharacterDevice()) return "not a regular file (a character device)";
  if (stats.isBlockDevice()) return "not a regular file (a block device)";
  if (stats.isSocket()) return "not a regular file (a socket)";
  if (stats.isDirectory()) return "not a regular file (a folder)";
  return "not a regular file";
}

/** Refuse `path` by name when something other than a regular file is there. */
export function checkRegular(path: string): void {
  const why = notRegular(path);
  if (why) throw new VerifyError(`${path}: ${why}`);
}

/**
 * The bytes of a regular file, refused by name when it is anything else or cannot be read. The
 * file is opened without blocking (a pipe put there after the look cannot hold the open) and
 * looked at again through its descriptor.
 */
export function readRegular(path: string, what = "cannot read"): Buffer {
  checkRegular(path);
  let fd: number;
  try {
    fd = openSync(path, constants.O_RDONLY | constants.O_NONBLOCK);
  } catch (err) {
    const code = (err as NodeJS.ErrnoException).code;
    if (code === "ELOOP") throw new VerifyError(`${path}: a loop of symbolic links`);
    throw new VerifyError(`${path}: ${what}${code === "ENOENT" ? " (no such file)" : ""}: ${code ?? String(err)}`);
  }
  try {
    const why = kindOf(fstatSync(fd));
    if (why) throw new VerifyError(`${path}: ${why}`);
    return readFileSync(fd);
  } finally {
    closeSync(fd);
  }
}

/**
 * Whether a JSON text (already parsed as `value`) holds a repeated key: the keys the text spells
 * (each `"` that ends a string and is followed by `:`) against the keys the parsed value holds.
 * Counting is a scan of the text with indexOf and a walk of the value, a small share of the
 * parse; the exact place is looked for only when the counts differ (repeatedKey).
 */
export function mayRepeatKeys(text: string, value: unknown): boolean {
  let spelt = 0;
  for (let i = text.indexOf('":'); i >= 0; i = text.indexOf('":', i + 2)) {
    let backslashes = 0;
    while (text.charCodeAt(i - 1 - backslashes) === 0x5c) backslashes++;
    if (backslashes % 2 === 0) spelt++; // an escaped quote is inside a string, not the end of a key
  }
  return spelt !== keysOf(value);
}

function keysOf(value: unknown): number {
  if (typeof value !== "object" || value === null) return 0;
  let n = 0;
  if (Array.isArray(value)) {
    for (const v of value) n += keysOf(v);
    return n;
  }
  const record = value as Record<string, unknown>;
  for (const k in record) n += 1 + keysOf(record[k]);
  return n;
}

/** Where the first repeated key is: its line (1-based), the key, and the keys and indexes leading to its object. */
export interface RepeatedKey {
  readonly line: number;
  readonly key: string;
  readonly path: readonly (string | number)[];
}

interface Frame {
  readonly keys: Set<string> | undefined; // undefined: an array
  at: string | number;
}

/**
 * The first key that repeats one of its object's earlier keys in a valid JSON `text`, in text
 * order, or undefined. A small scanner (JSON.parse gives no positions), run only on a text that
 * mayRepeatKeys has found suspect.
 */
export function repeatedKey(text: string): RepeatedKey | undefined {
  const stack: Frame[] = [];
  let line = 1;
  let wantKey = false;
  for (let i = 0; i < text.length; i++) {
    const c = text[i];
    if (c === "\n") line++;
    else if (c === "{") {
      stack.push({ keys: new Set(), at: "" });
      wantKey = true;
    } else if (c === "[") stack.push({ keys: undefined, at: 0 });
    else if (c === "}" || c === "]") {
      stack.pop();
      wantKey = false;
    } else if (c === "," && stack.length) {
      const top = stack[stack.length - 1]!;
      if (top.keys === undefined) top.at = (top.at as number) + 1;
      else wantKey = true;
    } else if (c === '"') {
      let j = i + 1;
      while (text[j] !== '"') j += text[j] === "\\" ? 2 : 1;
      const top = stack[stack.length - 1];
      if (wantKey && top?.keys !== undefined) {
        const key = JSON.parse(text.slice(i, j + 1)) as string;
        if (top.keys.has(key)) return { line, key, path: stack.slice(0, -1).map((f) => f.at) };
        top.keys.add(key);
        top.at = key;
        wantKey = false;
      }
      i = j;
    }
  }
  return undefined;
}
