/** Small vector sets written to a temporary folder, for the loader's and the gate's tests. */
import { mkdtempSync, readFileSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";

import { PACKAGED_VECTORS } from "../src/index.js";

/** The packaged JSON Lines of one family, as lines. */
export function familyLines(family: string): string[] {
  return readFileSync(join(PACKAGED_VECTORS, `${family}.jsonl`), "utf8").trimEnd().split("\n");
}

/** Write `lines` as `<family>.jsonl` in a fresh folder and return the file's path. */
export function writeFamily(family: string, lines: readonly string[]): string {
  const dir = mkdtempSync(join(tmpdir(), "plcvec-ts-"));
  const file = join(dir, `${family}.jsonl`);
  // The header's count follows the vectors kept: a shorter file is a sound file, not a cut one.
  const header = JSON.parse(lines[0] ?? "{}") as Record<string, unknown>;
  const out = typeof header["count"] === "number" ? [JSON.stringify({ ...header, count: lines.length - 1 }), ...lines.slice(1)] : lines;
  writeFileSync(file, out.join("\n") + "\n");
  return file;
}

/** The first `n` vectors of a family with `edit` applied to the vector at `index` (1-based line). */
export function editedFamily(family: string, n: number, index: number, edit: (v: Record<string, unknown>) => void): string {
  const lines = familyLines(family).slice(0, n + 1);
  const vector = JSON.parse(lines[index] as string) as Record<string, unknown>;
  edit(vector);
  lines[index] = JSON.stringify(vector);
  return writeFamily(family, lines);
}
