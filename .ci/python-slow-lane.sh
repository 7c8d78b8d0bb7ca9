#!/usr/bin/env bash
# CI's lane for the slow end-to-end tests the README's test command leaves out (`-m slow`: a
# process per pytest session, every combination of alternatives, the long property draws). The
# default run keeps a fast test over the same code; here they run whole, so nothing leaves CI.
set -euo pipefail
cd "$(dirname "$0")/.."
python3 -m pytest -q -n auto -m slow -p no:cacheprovider
