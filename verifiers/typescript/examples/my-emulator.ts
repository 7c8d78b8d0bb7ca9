/**
 * "My emulator": the part of an emulator that executes TADD and TADDP on its own device memory,
 * written the way an implementer adapts plcvec with the thin `executeOnMemory` helper. The two
 * example tests beside this file run the suite's fx5-time-add vectors against it.
 */
import { executeOnMemory, type Execution } from "plcvec";

const DAY = 86_400;
const signed = (w: number): number => (w & 0x8000 ? w - 0x10000 : w);

function tadd({ instruction, operands, memory, step, state }: Execution): undefined {
  // TADDP runs on the rising edge of EN only; TADD on every scan while EN is on.
  const rising = step.en === true && state["en"] !== true;
  state["en"] = step.en;
  if (!(instruction === "TADD" ? step.en : rising)) return undefined;
  const [s1, s2, d] = (["s1", "s2", "d"] as const).map((k) => {
    const op = operands[k];
    if (op === undefined || !("device" in op)) throw new Error(`${k} must be a device`);
    return op.device;
  }) as [string, string, string];
  const error = (code: number): undefined => {
    memory.write("SD0", code);
    memory.write("SD8067", code);
    return undefined;
  };
  if (![s1, s2, d].every((dev) => memory.inRange(dev, 3))) return error(0x2820);
  const a = memory.words(s1, 3).map(signed);
  const b = memory.words(s2, 3).map(signed);
  const valid = (t: number[]): boolean => t[0]! >= 0 && t[0]! <= 23 && t.slice(1).every((x) => x >= 0 && x <= 59);
  if (!valid(a) || !valid(b)) return error(0x3405);
  const sum = (a[0]! + b[0]!) * 3600 + (a[1]! + b[1]!) * 60 + a[2]! + b[2]!;
  const t = sum % DAY;
  memory.writeWords(d, [Math.floor(t / 3600), Math.floor(t / 60) % 60, t % 60]);
  memory.write("SM700", sum >= DAY);
  memory.write("SM8022", sum >= DAY);
  memory.write("SM8020", t === 0);
  return undefined;
}

export const myEmulator = executeOnMemory({ name: "my-emulator", instructions: ["TADD", "TADDP"], execute: tadd });
