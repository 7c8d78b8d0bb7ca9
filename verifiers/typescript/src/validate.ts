/**
 * What the runner needs of a vector, checked at load with the JSON path of the first bad value
 * (`steps/0/expect/devices/D100: 70000 is not a word (an integer 0..65535) nor a bit`). It follows
 * vectors/schema/vector-file.schema.json for every field a runner reads.
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
  if ("result" in value && typeof value["result"] !== "boolean") return `${path}/result: not true/false`;
  return devices(value["devices"], `${path}/devices`);
};

const outcome: Check = (value, path) => {
  if (!isObject(value)) return `${path}: not an object`;
  const category = value["category"];
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
    () => (isObject(v["assumes"]) && isObject(v["assumes"]["device_sizes"]) ? undefined : "assumes/device_sizes: missing"),
    () => (isObject(initial) ? devices(initial["devices"], "initial/devices") : "initial: missing"),
    () => {
      const operands = (initial as Record<string, Json>)["operands"];
      if (!isObject(operands) || Object.keys(operands).length === 0) return "initial/operands: missing";
      for (const [name, op] of Object.entries(operands)) {
        const ok =
          isObject(op) &&
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
          (step["set"] !== undefined ? devices(step["set"], `steps/${i}/set`) : undefined) ??
          stepExpect(step["expect"], `steps/${i}/expect`);
        if (problem !== undefined) return problem;
      }
      return undefined;
    },
    () => (isObject(final) ? devices(final["devices"], "final/devices") : "final: missing"),
    () => outcome(v["outcome"], "outcome"),
    () => {
      const alts = v["alternatives"];
      if (alts === undefined) return undefined;
      if (!Array.isArray(alts)) return "alternatives: not a list";
      for (const [i, alt] of alts.entries()) {
        const path = `alternatives/${i}`;
        if (!isObject(alt) || !isObject(alt["choices"])) return `${path}/choices: missing`;
        const expect = alt["expect"];
        if (!Array.isArray(expect) || expect.length !== (steps as Json[]).length) {
          return `${path}/expect: not one expectation per step`;
        }
        for (const [j, e] of expect.entries()) {
          const problem = stepExpect(e, `${path}/expect/${j}`);
          if (problem !== undefined) return problem;
        }
        const altFinal = alt["final"];
        const problem = isObject(altFinal) ? devices(altFinal["devices"], `${path}/final/devices`) : `${path}/final: missing`;
        if (problem !== undefined) return problem;
        const o = outcome(alt["outcome"], `${path}/outcome`);
        if (o !== undefined) return o;
      }
      return undefined;
    },
  );
}
