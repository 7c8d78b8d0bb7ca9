#!/usr/bin/env bash
# The TypeScript verifier: install, type-check, lint, build, test under node:test, the README's
# examples under node:test and Vitest, and the reference adapter through `plcvec verify`.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../gate-rejects.sh"
cd "$(dirname "$0")/../.."
root=$PWD
(
    cd verifiers/typescript
    # The README's own install command: the lock file records every platform's optional packages.
    npm ci --no-audit --no-fund --loglevel=error
    npm run --silent typecheck
    npm run --silent lint
    npm run --silent build
    npm test
    npm run --silent example:node-test
    npm run --silent example:vitest
)
cd "$root"
python3 -m plcvec verify --adapter verifiers/typescript/reference-adapter -q
# A mutant served the same way is rejected (exit 1): the gate is not passing by accident.
gate_rejects typescript "verifiers/typescript/reference-adapter --mutant tadd-hour-not-wrapped" --family fx5-time-add
# The shared table of faults through faults-entry (node --test over vectorTests): the verdict
# `plcvec verify` gives, for every row.
python3 verifiers/parity/run.py --lang typescript
