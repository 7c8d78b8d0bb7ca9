#!/usr/bin/env node
// The `plcvec-reference-adapter` command (package.json `bin`): a file that exists before `prepack`
// builds, so that npm finds the command it publishes; it runs the compiled adapter.
import "../dist/src/bin/reference-adapter.js";
