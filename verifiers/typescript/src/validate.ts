/**
 * What the runner needs of a vector, checked at load with the JSON path of the first bad value
 * (`steps/0/expect/devices/D100: 70000 is not a word (an integer 0..65535) nor a bit`). It follows
 * vectors/schema/vector-file.schema.json for every field a runner reads, and refuses a key the schema
 * does not have at any level (CONTRACT.md, Loading): a key this runner does not know may carry a
 * meaning it would silently ignore.
 */

type Json = unknown;
type Check = (value: Json, path: string) => string | undefined;

const isObject = (v: Json): v is Record<string, Json> => typeof v === "object" && v !== null && !Array.isArray(v);
const DEVICE_NAME = /^[A-Za-z_]+[0-9]*$/;
const OPERAND_DEVICE = /^[A-Za-z_]+[0-9]+$/;

function isWordOrBit(v: Json): boolean {
  return typeof v === "boolean" || (typeof v === "number" && Number.isInteger(v) && v >= 0 && v <= 65535);
}

const devices: Check = (value, path) => {
  if (!isObject(value)) return `${path}: not an object of devices`;
  for (const [name, v] of Object.entries(value)) {
    if (!DEVICE_NAME.test(name)) return `${path}: ${JSON.stringify(name)} is not a device name`;
    if (!isWordOrBit(v)) return `${path}/${name}: ${JSON.stringify(v)} is not a word (an integer 0..65535) nor a bit`;
  }
  return undefined;
};

const stepExpect: Check = (value, path) => {
  if (!isObject(value)) return `${path}: not an object`;
  const unknown = unknownKey(value, EXPECT_KEYS, path);
  if (unknown !== undefined) return unknown;
  if ("result" in value && typeof value["result"] !== "boolean") return `${path}/result: not true/false`;
  return devices(value["devices"], `${path}/devices`);
};

const outcome: Check = (value, path) => {
  if (!isObject(value)) return `${path}: not an object`;
  const category = value["category"];
  const unknown = unknownKey(value, category === "implementation-defined" ? DEFINED_KEYS : OUTCOME_KEYS, path);
  if (unknown !== undefined) return unknown;
  if (Array.isArray(value["errors"])) {
    for (const [i, e] of value["errors"].entries()) {
      const p = isObject(e) ? unknownKey(e, ERROR_KEYS, `${path}/errors/${i}`) : `${path}/errors/${i}: not an object`;
      if (p !== undefined) return p;
    }
  }
  if (category !== "value" && category !== "error" && category !== "implementation-defined") {
    return `${path}/category: ${JSON.stringify(category)} is not value, error or implementation-defined`;
  }
  if (category === "implementation-defined") {
    const interps = value["interpretations"];
    if (!Array.isArray(interps) || interps.length === 0 || !interps.every((i) => typeof i === "string")) {
      return `${path}/interpretations: an implementation-defined outcome names the interpretations it depends on`;
    }
  }
  return undefined;
};

/** The first key of `value` not in `allowed`, as a problem at `path`. */
function unknownKey(value: Record<string, Json>, allowed: ReadonlySet<string>, path: string): string | undefined {
  for (const key in value) if (!allowed.has(key)) return `${path}${path ? "/" : ""}${key}: a key the schema does not have`;
  return undefined;
}

const VECTOR_KEYS = new Set(["id", "family", "instruction", "st", "printed", "description", "tags", "clauses", "assumes", "initial", "steps", "final", "outcome", "alternatives"]);
const INITIAL_KEYS = new Set(["devices", "operands", "scratch"]);
const STEP_KEYS = new Set(["set", "rlo_in", "clock", "en", "input", "elapsed_ms", "expect"]);
const EXPECT_KEYS = new Set(["devices", "result"]);
const FINAL_KEYS = new Set(["devices"]);
const ASSUMES_KEYS = new Set(["device_sizes"]);
const OUTCOME_KEYS = new Set(["category", "errors"]);
const DEFINED_KEYS = new Set(["category", "interpretations", "default", "reason"]);
const ERROR_KEYS = new Set(["step", "code", "device"]);
const ALTERNATIVE_KEYS = new Set(["choices", "expect", "final", "outcome", "unjudged"]);
const INTERPRETATION_ID = /^[A-Za-z0-9][A-Za-z0-9_.<>=-]*$/;

/** An alternatives entry's `unjudged` map (schema 1.1): interpretation id -> a non-empty list of distinct device names. */
function unjudged(value: Json, path: string): string | undefined {
  if (value === undefined) return undefined;
  if (!isObject(value) || Object.keys(value).length === 0) return `${path}: not a non-empty object of interpretation ids`;
  for (const [id, list] of Object.entries(value)) {
    if (!INTERPRETATION_ID.test(id)) return `${path}: ${JSON.stringify(id)} is not an interpretation id`;
    if (!Array.isArray(list) || list.length === 0) return `${path}/${id}: not a non-empty list of devices`;
    for (const [k, d] of list.entries()) {
      if (typeof d !== "string" || !DEVICE_NAME.test(d)) return `${path}/${id}/${k}: ${JSON.stringify(d)} is not a device name`;
      if (list.indexOf(d) !== k) return `${path}/${id}/${k}: ${JSON.stringify(d)} is listed twice`;
    }
  }
  return undefined;
}
const HEADER_KEYS = new Set(["count", "family", "generated", "instructions", "interpretations", "kind", "schema_version", "spec_file", "spec_sha256", "tags", "title"]);
const INTERPRETATION_KEYS = new Set(["id", "question", "default", "alternatives"]);
const ALTERNATIVE_HEADER_KEYS = new Set(["id", "says"]);

/** The first thing wrong with a family header (a JSON Lines file's first line, or a JSON file without `vectors`). */
export function headerProblem(h: Json): string | undefined {
  if (!isObject(h) || typeof h["family"] !== "string") return "no `family`";
  const unknown = unknownKey(h, HEADER_KEYS, "");
  if (unknown !== undefined) return unknown;
  if (!Array.isArray(h["interpretations"]) || !Array.isArray(h["instructions"]) || !isObject(h["tags"])) {
    return `the header of ${h["family"]} needs \`instructions\`, \`tags\` and \`interpretations\``;
  }
  for (const [i, interp] of h["interpretations"].entries()) {
    const path = `interpretations/${i}`;
    if (!isObject(interp) || !Array.isArray(interp["alternatives"])) return `${path}: not an interpretation`;
    const problem = unknownKey(interp, INTERPRETATION_KEYS, path);
    if (problem !== undefined) return problem;
    for (const [j, alt] of interp["alternatives"].entries()) {
      if (!isObject(alt)) return `${path}/alternatives/${j}: not an object`;
      const p = unknownKey(alt, ALTERNATIVE_HEADER_KEYS, `${path}/alternatives/${j}`);
      if (p !== undefined) return p;
    }
  }
  return undefined;
}

/**
 * A device whose JSON type (word or bit) differs between the places one vector names it
 * (`initial`, `set`, `expect`, `final`, the alternatives): a bit holding 2 is the file's fault,
 * and must not be blamed on the implementation.
 */
function mixedTypes(v: Record<string, Json>): string | undefined {
  // Name -> true for a bit, false for a word, and where it was first seen: objects without a
  // prototype and for..in, since this runs over every device of every vector at load.
  const isBit: Record<string, boolean> = Object.create(null) as Record<string, boolean>;
  const firstSeen: Record<string, string> = Object.create(null) as Record<string, string>;
  const visit = (devices: Json, path: string): string | undefined => {
    if (!isObject(devices)) return undefined;
    for (const name in devices) {
      const value = devices[name];
      const bit = typeof value === "boolean";
      const seen = isBit[name];
      if (seen === undefined) {
        isBit[name] = bit;
        firstSeen[name] = path;
      } else if (seen !== bit) {
        return `${path}/${name}: ${JSON.stringify(value)} is a ${bit ? "bit" : "word"}, but ${firstSeen[name]}/${name} holds a ${seen ? "bit" : "word"}`;
      }
    }
    return undefined;
  };
  const initial = v["initial"] as Record<string, Json>;
  let problem = visit(initial["devices"], "initial/devices");
  const steps = v["steps"] as Record<string, Json>[];
  for (let i = 0; i < steps.length && problem === undefined; i++) {
    const step = steps[i]!;
    problem = visit(step["set"], `steps/${i}/set`) ?? visit((step["expect"] as Record<string, Json>)["devices"], `steps/${i}/expect/devices`);
  }
  problem ??= visit((v["final"] as Record<string, Json>)["devices"], "final/devices");
  const alternatives = (v["alternatives"] as Record<string, Json>[] | undefined) ?? [];
  for (let i = 0; i < alternatives.length && problem === undefined; i++) {
    const alt = alternatives[i]!;
    const expect = alt["expect"] as Record<string, Json>[];
    for (let j = 0; j < expect.length && problem === undefined; j++) problem = visit(expect[j]!["devices"], `alternatives/${i}/expect/${j}/devices`);
    problem ??= visit((alt["final"] as Record<string, Json>)["devices"], `alternatives/${i}/final/devices`);
  }
  return problem;
}

function first(...checks: (() => string | undefined)[]): string | undefined {
  for (const check of checks) {
    const problem = check();
    if (problem !== undefined) return problem;
  }
  return undefined;
}

/** The first thing wrong with `v` as a vector of `family`, or undefined. */
export function vectorProblem(v: Json, family: string): string | undefined {
  if (!isObject(v)) return "not a JSON object";
  const unknown = unknownKey(v, VECTOR_KEYS, "");
  if (unknown !== undefined) return unknown;
  for (const key of ["id", "family", "instruction"]) {
    if (typeof v[key] !== "string" || v[key] === "") return `${key}: missing or not a string`;
  }
  if (v["family"] !== family) return `family: ${JSON.stringify(v["family"])} in a ${JSON.stringify(family)} file`;
  const initial = v["initial"];
  const steps = v["steps"];
  const final = v["final"];
  return first(
    () => (Array.isArray(v["tags"]) ? undefined : "tags: not a list"),
    () => (Array.isArray(v["clauses"]) ? undefined : "clauses: not a list"),
    () => (isObject(v["assumes"]) && isObject(v["assumes"]["device_sizes"]) ? unknownKey(v["assumes"], ASSUMES_KEYS, "assumes") : "assumes/device_sizes: missing"),
    () => (isObject(initial) ? (unknownKey(initial, INITIAL_KEYS, "initial") ?? devices(initial["devices"], "initial/devices")) : "initial: missing"),
    () => {
      const operands = (initial as Record<string, Json>)["operands"];
      if (!isObject(operands) || Object.keys(operands).length === 0) return "initial/operands: missing";
      for (const [name, op] of Object.entries(operands)) {
        const ok =
          isObject(op) &&
          Object.keys(op).length === 1 &&
          ((typeof op["device"] === "string" && OPERAND_DEVICE.test(op["device"])) ||
            (typeof op["constant"] === "number" && Number.isInteger(op["constant"])));
        if (!ok) return `initial/operands/${name}: neither {"device": "D100"} nor {"constant": 7}`;
      }
      const scratch = (initial as Record<string, Json>)["scratch"];
      if (scratch !== undefined && !(Array.isArray(scratch) && scratch.every((s) => typeof s === "string"))) {
        return "initial/scratch: not a list of device names";
      }
      return undefined;
    },
    () => {
      if (!Array.isArray(steps) || steps.length === 0) return "steps: missing or empty";
      for (const [i, step] of steps.entries()) {
        if (!isObject(step)) return `steps/${i}: not an object`;
        const problem =
          unknownKey(step, STEP_KEYS, `steps/${i}`) ??
          (step["set"] !== undefined ? devices(step["set"], `steps/${i}/set`) : undefined) ??
          stepExpect(step["expect"], `steps/${i}/expect`);
        if (problem !== undefined) return problem;
      }
      return undefined;
    },
    () => (isObject(final) ? (unknownKey(final, FINAL_KEYS, "final") ?? devices(final["devices"], "final/devices")) : "final: missing"),
    () => outcome(v["outcome"], "outcome"),
    () => {
      const alts = v["alternatives"];
      if (alts === undefined) return undefined;
      if (!Array.isArray(alts)) return "alternatives: not a list";
      for (const [i, alt] of alts.entries()) {
        const path = `alternatives/${i}`;
        if (!isObject(alt) || !isObject(alt["choices"])) return `${path}/choices: missing`;
        const extra = unknownKey(alt, ALTERNATIVE_KEYS, path);
        if (extra !== undefined) return extra;
        const expect = alt["expect"];
        if (!Array.isArray(expect) || expect.length !== (steps as Json[]).length) {
          return `${path}/expect: not one expectation per step`;
        }
        for (const [j, e] of expect.entries()) {
          const problem = stepExpect(e, `${path}/expect/${j}`);
          if (problem !== undefined) return problem;
        }
        const altFinal = alt["final"];
        const problem = isObject(altFinal)
          ? (unknownKey(altFinal, FINAL_KEYS, `${path}/final`) ?? devices(altFinal["devices"], `${path}/final/devices`))
          : `${path}/final: missing`;
        if (problem !== undefined) return problem;
        const o = outcome(alt["outcome"], `${path}/outcome`) ?? unjudged(alt["unjudged"], `${path}/unjudged`);
        if (o !== undefined) return o;
      }
      return undefined;
    },
    () => mixedTypes(v),
  );
}

const REQUEST_STEP_KEYS = new Set(["set", "rlo_in", "clock", "en", "input", "elapsed_ms"]);

/**
 * The first thing wrong with `r` as a vector of a protocol run request (PROTOCOL.md: a vector without
 * its expectations), or undefined: what an adapter must refuse rather than run (a word of 70000
 * would be echoed back, a request without steps would fail inside the implementation).
 */
export function requestProblem(r: Json): string | undefined {
  if (!isObject(r)) return "not a JSON object";
  for (const key of ["id", "family", "instruction"]) {
    if (typeof r[key] !== "string" || r[key] === "") return `${key}: missing or not a string`;
  }
  const initial = r["initial"];
  if (!isObject(initial)) return "initial: missing";
  const problem = devices(initial["devices"], "initial/devices");
  if (problem !== undefined) return problem;
  if (!isObject(initial["operands"])) return "initial/operands: missing";
  if (r["assumes"] !== undefined && !(isObject(r["assumes"]) && isObject(r["assumes"]["device_sizes"]))) return "assumes/device_sizes: not an object";
  const steps = r["steps"];
  if (!Array.isArray(steps) || steps.length === 0) return "steps: missing or empty";
  for (const [i, step] of steps.entries()) {
    if (!isObject(step)) return `steps/${i}: not an object`;
    const p = unknownKey(step, REQUEST_STEP_KEYS, `steps/${i}`) ?? (step["set"] !== undefined ? devices(step["set"], `steps/${i}/set`) : undefined);
    if (p !== undefined) return p;
  }
  return undefined;
}
