/**
 * One shared, frozen copy of each equal part of the prepared vectors.
 *
 * Judging the golden set is bound by memory traffic, not arithmetic: thousands of vectors each
 * reading their own copy of `{"rlo_in": true}`, of the operands `{"S1": {"device": "D100"}, ...}`
 * or of the string "cp1e-time-compare" miss the cache on every one. Most such parts are equal
 * across hundreds of vectors, so preparing keeps the first of each and hands out that one. Shared
 * parts are frozen: an implementation that wrote into its request could otherwise reach into
 * another vector's.
 */
const strings = new Map<string, string>();
const values = new Map<string, unknown>();

/** The one copy of this string. */
export function internString(s: string): string {
  const seen = strings.get(s);
  if (seen !== undefined) return seen;
  strings.set(s, s);
  return s;
}

/** The one frozen copy of a JSON value equal to `value` (objects with the same keys in the same order). */
export function interned<T extends object>(value: T): T {
  const key = JSON.stringify(value);
  const seen = values.get(key);
  if (seen !== undefined) return seen as T;
  const copy = deepFreeze(JSON.parse(key, (_k, v: unknown) => (typeof v === "string" ? internString(v) : v)) as T);
  values.set(key, copy);
  return copy;
}

/** The one copy of a list of contact results per step (undefined for a step without one: JSON cannot say it). */
export function internedResults(results: readonly (boolean | undefined)[]): readonly (boolean | undefined)[] {
  const key = `results:${results.map((r) => (r === undefined ? "-" : r ? "1" : "0")).join("")}`;
  const seen = values.get(key);
  if (seen !== undefined) return seen as readonly (boolean | undefined)[];
  const copy = Object.freeze([...results]);
  values.set(key, copy);
  return copy;
}

function deepFreeze<T>(value: T): T {
  if (typeof value === "object" && value !== null) {
    for (const v of Object.values(value)) deepFreeze(v);
    Object.freeze(value);
  }
  return value;
}
