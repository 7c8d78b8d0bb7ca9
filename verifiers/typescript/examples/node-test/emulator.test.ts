// Run with: node --test dist/examples/node-test/   (one test per vector, named by its id)
import { vectorTests } from "plcvec/node-test";

import { myEmulator } from "../my-emulator.js";

vectorTests(myEmulator, { selection: { families: ["fx5-time-add"] } });
