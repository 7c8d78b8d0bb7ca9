#!/usr/bin/env bash
# CI's Python lane (run by .ci/run beside the other lanes, once it installed this checkout): lint the
# CI recipes and the spec, check the API and the exports, the package as a user installs it, the
# review against the manual, the reference through the gate, the table of faults, the live
# differential run.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/steps.sh"
cd "$(dirname "$0")/.."
# Bytecode written and reused (the checkout's __pycache__ is ignored by git and by the sdist): with
# PYTHONDONTWRITEBYTECODE in the environment, every process of the lane (a row of the table of
# faults, a mutant) would compile the package's modules again.
unset PYTHONDONTWRITEBYTECODE
steps_begin python

# The CI recipes as yamllint's users lint them (its default rules, warnings as errors).
step "yamllint"
python3 -m pip install --quiet --disable-pip-version-check yamllint
python3 -m yamllint --strict action.yml verifiers/ci

# Every fenced block of every README carries a marker: run by CI, or skipped with a reason.
step "every README block carries a marker"
python3 .ci/readme_snippets.py check README.md verifiers/*/README.md

step "plcvec lint"
python3 -m plcvec lint
# No import circle in the generator or the Python runner, and the generator's stages import only
# those before them (imports at any depth of a file count).
step "no import circle"
python3 .ci/circles.py
# The Python runner's public API against the previous release (griffe; each language's own check is
# in its .ci/lang script): a breaking change CHANGES.md does not list fails.
step "the public API against 0.1.0 (griffe)"
python3 .ci/api/python.py
# The copies of the vectors and the spec's names rendered into each native verifier.
step "export --all --check"
python3 -m plcvec export --all --check

# The package as a user installs it: the wheel and the sdist, each in a fresh virtual environment,
# run from a temporary folder with no checkout in reach (builds with `build`, checks with `twine`);
# every command on the wheel's installation, and the sdist's shown to be the same files.
step "the package as a user installs it"
bash .ci/package-check.sh

# Every quote found in the manual, every clause covered, every audit disagreement recorded.
step "review --check"
python3 -m plcvec review --check --manual-dir ../shared/manual --out build/review
# The decision inventory is complete: a seeded sample of the engine's mutants, each that changes the
# committed vectors touching a decision of decisions.yaml (the whole run, `plcvec mutation`, takes
# about 25 minutes here; the sample about 90 s).
step "mutation sample"
# Its timeout is 5 CPU seconds, about five times the unmutated engine's CPU time (under a second):
# the default's floor of 10 s is for a whole run on any machine, and the sample's mutant that never
# ends would sit it out.
python3 -m plcvec mutation --sample 60 --seed 1 --timeout 5

# The CI gate as an implementer runs it, on the reference implementation over the stdio protocol.
# The reference implements every instruction, so it may skip nothing.
step "verify the reference"
python3 -m plcvec verify --adapter "python3 -m plcvec_reference.adapter" --junit build/verify-reference.xml -q --max-skipped 0
# The shared table of faults (verifiers/parity/faults.toml), Python's rows: plcvec verify's verdicts
# are the rule every native runner's rows (in .ci/lang/<lang>.sh) are held to. The rows run as one
# batch (faults-entry --batch): each its own `plcvec verify` process, forked from one interpreter
# that imported it once.
step "table of faults"
python3 verifiers/parity/run.py --lang python
# Live differential run: fresh inputs through the reference and the spec engine (fixed seed: repeatable).
step "fuzz"
python3 -m plcvec fuzz --adapter "python3 -m plcvec_reference.adapter" --examples 2000 --seed 1
step "done"
