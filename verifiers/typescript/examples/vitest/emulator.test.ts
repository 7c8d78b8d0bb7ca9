// Run with: npx vitest run --root examples/vitest   (one test per vector, named by its id)
import { cases } from "plcvec";
import { expect, test } from "vitest";

import { myEmulator } from "../my-emulator.js";

const suite = cases(myEmulator, { selection: { families: ["fx5-time-add"] } });

test.each(suite)("$id", (c) => {
  expect(c.check().status).toBe("pass");
});
