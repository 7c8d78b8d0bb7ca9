/**
 * The PLCVEC_* settings, read as every plcvec runner reads them (CONTRACT.md, "The environment"),
 * from the one table `plcvec export` writes into src/generated/settings.ts.
 *
 * A renamed setting is still read under its old name, with a warning naming the new one; a
 * PLCVEC_* variable that is no setting, no old name and no name plcvec's own tools use is taken for
 * a misspelling and named with the nearest setting. Neither stops the run: each is one line on
 * stderr, once per process, whatever the entry point (vectorTests, cases, runVectors).
 */
import { writeSync } from "node:fs";

import { VerifyError } from "./errors.js";
import {
  DEPRECATED_SETTINGS,
  NEAREST_DISTANCE,
  RESERVED_SETTING_PREFIXES,
  RESERVED_SETTINGS,
  SETTINGS,
  TIMEOUT_DEFAULT_S,
  TIMEOUT_MAX_S,
} from "./generated/settings.js";

const PREFIX = "PLCVEC_";

/** Levenshtein distance: insert, delete or replace one character, each 1. */
export function editDistance(a: string, b: string): number {
  let previous = Array.from({ length: b.length + 1 }, (_, j) => j);
  for (let i = 1; i <= a.length; i++) {
    const current = [i];
    for (let j = 1; j <= b.length; j++) {
      current.push(Math.min(previous[j]! + 1, current[j - 1]! + 1, previous[j - 1]! + (a[i - 1] === b[j - 1] ? 0 : 1)));
    }
    previous = current;
  }
  return previous[b.length]!;
}

const byCodePoint = (a: string, b: string): number => (a < b ? -1 : a > b ? 1 : 0);

/** The setting `name` is most likely a misspelling of (the first by name among the closest); an old name counts as its replacement. */
export function nearestSetting(name: string): string | undefined {
  const candidates = [...new Set([...SETTINGS.map((s) => s.name), ...DEPRECATED_SETTINGS.map((d) => d.name)])].sort(byCodePoint);
  const upper = name.toUpperCase();
  let best = candidates[0]!;
  let bestDistance = editDistance(upper, best);
  for (const c of candidates.slice(1)) {
    const d = editDistance(upper, c);
    if (d < bestDistance) [best, bestDistance] = [c, d];
  }
  if (bestDistance > NEAREST_DISTANCE) return undefined;
  return DEPRECATED_SETTINGS.find((d) => d.name === best)?.replacement ?? best;
}

/** The warnings the environment gives, in variable order, each without the `plcvec: ` prefix. */
export function settingWarnings(env: NodeJS.ProcessEnv = process.env): string[] {
  const known = new Set([...SETTINGS.map((s) => s.name), ...RESERVED_SETTINGS]);
  const out: string[] = [];
  for (const name of Object.keys(env).filter((n) => n.startsWith(PREFIX)).sort(byCodePoint)) {
    if (known.has(name) || RESERVED_SETTING_PREFIXES.some((p) => name.startsWith(p))) continue;
    const old = DEPRECATED_SETTINGS.find((d) => d.name === name);
    if (old !== undefined) {
      out.push(
        old.replacement in env
          ? `warning: ${name} is ignored: it is the old name of ${old.replacement}, which is set too`
          : `warning: ${name} is the old name of ${old.replacement}, read as it until plcvec ${old.until}; set ${old.replacement} instead`,
      );
      continue;
    }
    const guess = nearestSetting(name);
    out.push(
      `warning: ${name} is not a plcvec setting` +
        (guess !== undefined ? `; did you mean ${guess}?` : `; the settings are ${SETTINGS.map((s) => s.name).join(", ")}`),
    );
  }
  return out;
}

let warned = false;

/** Write the environment's warnings to stderr, once per process (the first entry point that reads a setting does). */
export function warnSettingsOnce(env: NodeJS.ProcessEnv = process.env): void {
  if (warned) return;
  warned = true;
  const lines = settingWarnings(env);
  if (lines.length) writeSync(2, lines.map((l) => `plcvec: ${l}\n`).join(""));
}

/**
 * The value of a setting: its own variable, else an old name of it while the setting is unset
 * (PLCVEC_EXPECTATIONS is read as PLCVEC_KNOWN_FAILURES). Undefined when neither is set or the
 * value is empty.
 */
export function setting(name: string, env: NodeJS.ProcessEnv = process.env): string | undefined {
  if (!SETTINGS.some((s) => s.name === name)) throw new Error(`${name} is not a setting of the generated table`);
  warnSettingsOnce(env);
  let value = env[name];
  if (!(name in env)) value = env[DEPRECATED_SETTINGS.find((d) => d.replacement === name && d.name in env)?.name ?? name];
  return value === undefined || value === "" ? undefined : value;
}

/** The bound on an answer (CONTRACT.md): one rule in every runner, so that no value one takes another refuses. */
const TIMEOUT = /^[0-9]+(\.[0-9]+)?$/;
/** The bound per vector when PLCVEC_TIMEOUT says none. */
export const DEFAULT_TIMEOUT_SECONDS = TIMEOUT_DEFAULT_S;

/** PLCVEC_TIMEOUT: seconds per vector, digits with an optional fraction, above 0 and at most a day (default 10). */
export function timeoutSeconds(env: NodeJS.ProcessEnv = process.env): number {
  const text = setting("PLCVEC_TIMEOUT", env);
  if (text === undefined) return DEFAULT_TIMEOUT_SECONDS;
  const seconds = TIMEOUT.test(text) ? Number(text) : NaN;
  if (!(seconds > 0 && seconds <= TIMEOUT_MAX_S)) {
    throw new VerifyError(
      `PLCVEC_TIMEOUT=${text}: the bound must be a number of seconds above 0 and at most ${TIMEOUT_MAX_S}, ` +
        "written as digits with an optional fraction (2, 0.5)",
    );
  }
  return seconds;
}
