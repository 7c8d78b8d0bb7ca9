/**
 * An implementation served over the plcvec stdio protocol (verifiers/PROTOCOL.md): hello, run and
 * bye on stdin and stdout, so that `plcvec verify --adapter` judges it like any other.
 *
 * Malformed input never crashes it: a line that is not a protocol message is answered with
 * `fatal` and a non-zero exit; a vector it cannot run is answered with `error` for that vector.
 */
import { createInterface } from "node:readline";

import type { Implementation, RunOutcome } from "./implementation.js";
import { requestProblem } from "./validate.js";
import type { VectorRequest } from "./vector.js";

const PROTOCOL = 1;

/** A request as the implementation interface gives it: `assumes` may be left out on the wire. */
function withDefaults(request: VectorRequest): VectorRequest {
  return request.assumes === undefined ? { ...request, assumes: { device_sizes: {} } } : request;
}

type Families = Record<string, { instructions?: unknown; interpretations?: Record<string, { default?: unknown }> }>;

/** The answer to a hello: every instruction of the families offered, each interpretation declared or at its default. */
function helloAnswer(impl: Implementation, version: string, msg: Record<string, unknown>): object {
  const families = (typeof msg["families"] === "object" && msg["families"] !== null ? msg["families"] : {}) as Families;
  const instructions = new Set<string>();
  const interpretations: Record<string, string> = {};
  for (const family of Object.values(families)) {
    if (Array.isArray(family.instructions)) for (const i of family.instructions) if (typeof i === "string") instructions.add(i);
    for (const [id, interp] of Object.entries(family.interpretations ?? {})) interpretations[id] = impl.choices?.[id] ?? String(interp.default);
  }
  return {
    type: "hello",
    protocol: PROTOCOL,
    adapter: { name: impl.name, version },
    instructions: [...instructions].sort(),
    interpretations,
    ...(impl.cpuWrites?.length ? { cpu_writes: [...impl.cpuWrites] } : {}),
  };
}

/** Serve `impl` on this process's stdin and stdout until `bye` or the end of input. */
export function serve(impl: Implementation, version = "1.0"): void {
  const out: string[] = [];
  const flush = (): void => {
    if (out.length) process.stdout.write(out.join(""));
    out.length = 0;
  };
  const send = (message: object): void => {
    out.push(JSON.stringify(message) + "\n");
  };
  const fatal = (message: string): never => {
    send({ type: "fatal", message });
    flush();
    process.exitCode = 1;
    process.stdout.end();
    process.exit(1);
  };

  function runOne(request: unknown): void {
    const id = typeof (request as { id?: unknown })?.id === "string" ? (request as { id: string }).id : undefined;
    if (id === undefined) fatal("a vector in a run request has no id");
    // A request of the wrong shape is answered as an error naming it, never run (PROTOCOL.md).
    const problem = requestProblem(request);
    if (problem !== undefined) {
      send({ type: "result", id, error: `the request for ${id} is not a vector the protocol sends: at ${problem}` });
      return;
    }
    let answer: RunOutcome;
    try {
      answer = impl.run(withDefaults(request as VectorRequest));
    } catch (err) {
      answer = { error: err instanceof Error ? `${err.name}: ${err.message}` : String(err) };
    }
    send({ type: "result", id, ...answer });
  }

  const lines = createInterface({ input: process.stdin, crlfDelay: Infinity });
  lines.on("line", (line) => {
    if (line.trim() === "") return;
    let msg: unknown;
    try {
      msg = JSON.parse(line);
    } catch {
      fatal(`not a JSON line: ${line.slice(0, 120)}`);
    }
    if (typeof msg !== "object" || msg === null || Array.isArray(msg)) fatal("a protocol message is a JSON object");
    const m = msg as Record<string, unknown>;
    switch (m["type"]) {
      case "hello":
        if (m["protocol"] !== PROTOCOL) fatal(`this adapter speaks protocol ${PROTOCOL}, not ${JSON.stringify(m["protocol"])}`);
        send(helloAnswer(impl, version, m));
        break;
      case "run":
        if (!Array.isArray(m["vectors"])) fatal("a run request needs `vectors`");
        for (const request of m["vectors"] as unknown[]) runOne(request);
        break;
      case "bye":
        flush();
        lines.close();
        return;
      default:
        fatal(`unknown message type ${JSON.stringify(m["type"])}`);
    }
    flush(); // one write per batch
  });
  lines.on("close", () => {
    flush();
  });
}
