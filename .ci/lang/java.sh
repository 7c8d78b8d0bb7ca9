#!/usr/bin/env bash
# The Java verifier (verifiers/java/): build every module with warnings as errors, run the JUnit
# tests (the library's own, the reference on every vector under the defaults and under every
# combination of alternatives, the mutants each rejected by name, and the README's example project
# examples/minimal), then serve the reference over the stdio protocol to the Python gate and to a
# seeded differential fuzz run, and check that the gate rejects a mutant. From the repository root.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../gate-rejects.sh"

if ! command -v mvn >/dev/null || ! command -v javac >/dev/null; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq openjdk-17-jdk-headless maven >/dev/null
fi

started=$SECONDS
# -B -q: no progress bars or download logs (Debian's Maven still prints bare colour resets: drop
# them). Dependencies and the pinned plugins come from Maven Central the first time, from ~/.m2
# after that (the build then also runs with -o).
(cd verifiers/java && mvn -B -q -Dstyle.color=never verify) 2>&1 | sed -e 's/\x1b\[0m//g' -e '/^$/d'
echo "java: mvn verify (build, lint, $(cat verifiers/java/*/target/surefire-reports/*.xml \
    verifiers/java/examples/*/target/surefire-reports/*.xml | grep -c '<testcase') JUnit tests) in $((SECONDS - started)) s"

python3 -m plcvec verify --adapter verifiers/java/reference-adapter -q

# Fresh inputs through the Java reference and the spec engine, under the defaults and under a set
# of other alternatives (fixed seeds: repeatable).
python3 -m plcvec fuzz --adapter verifiers/java/reference-adapter --examples 500 --seed 1
python3 -m plcvec fuzz --examples 500 --seed 2 --adapter "verifiers/java/reference-adapter \
    --choose FX5-SM709-SCOPE=compared-operands --choose FX5-AND-OR-WHEN-OFF=short-circuit \
    --choose TADD-EXACT-24=carry-above-24 --choose TADD-ON-ERROR=computed --choose HOUR-OUTPUT-OFF=recompared \
    --choose HOUR-INPUT-OFF=hold-drop-fraction --choose CP1E-NON-BCD=raw-bytes --choose CP1E-ALL-MASKED=not-compared \
    --choose CP1E-ER-FLAG=held --choose CP1E-ERROR-FLAGS=off --choose HOUR-FIRST-SCAN=from-next-scan \
    --choose HOUR-PRESET-CHECK=every-execution --choose HOUR-M8004-OFF=valid-preset --choose FX5-OR-ON-ERROR=result-off \
    --choose TADD-ERROR-ORDER=field-range-first"

# The shared table of faults through the README's entry point (the JUnit 5 factory under
# Surefire), every row; the modules are built by now, so `--build` only compiles the hostile ones.
python3 verifiers/parity/run.py --lang java

# The same gate must reject a mutant served the same way (exit 1, not 0 and not 2).
gate_rejects java "verifiers/java/reference-adapter --mutant tadd-sm8022-not-written" --family fx5-time-add
echo "java: done in $((SECONDS - started)) s"
