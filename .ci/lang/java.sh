#!/usr/bin/env bash
# The Java verifier (verifiers/java/): build every module with warnings as errors, run the JUnit
# tests (the library's own, the reference on every vector under the defaults and under every
# combination of alternatives, the mutants each rejected by name), stage a deployment and check it
# as Maven Central would, build the README's example from the README's blocks as an outside
# project (every vector run; each failure block printed once in a failing run), serve the reference over the stdio protocol to the Python gate and to a seeded
# differential fuzz run, run the table of faults, and check that the gate rejects a mutant. From
# the repository root.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../gate-rejects.sh"

if ! command -v mvn >/dev/null || ! command -v javac >/dev/null; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq openjdk-17-jdk-headless maven >/dev/null
fi

started=$SECONDS
# -B -q: no progress bars or download logs (Debian's Maven still prints bare colour resets: drop
# them). Dependencies and the pinned plugins come from Maven Central the first time, from ~/.m2
# after that (the build then also runs with -o). `install`: the README's example below is an
# outside project, which finds plcvec-verify in the local repository as a user's project would.
(cd verifiers/java && mvn -B -q -Dstyle.color=never install) 2>&1 | sed -e 's/\x1b\[0m//g' -e '/^$/d'
echo "java: mvn install (build, lint, javadoc, $(cat verifiers/java/*/target/surefire-reports/*.xml \
    | grep -c '<testcase') JUnit tests) in $((SECONDS - started)) s"

# Ready to publish: a deployment staged to a folder (no network but Maven Central, no signing key)
# and checked as Central checks one; the mutants and the hostile implementations are not in it.
stage="$(mktemp -d)"
(cd verifiers/java && mvn -B -q -Dstyle.color=never deploy -DskipTests \
    -DaltDeploymentRepository="staging::file://$stage") 2>&1 | sed -e 's/\x1b\[0m//g' -e '/^$/d'
verifiers/java/central-check "$stage"
rm -rf "$stage"

# Every fenced block of the README is marked; the runnable ones are built and run as an outside
# project under Maven's default plugins plus exactly the README's blocks.
python3 .ci/readme_snippets.py check verifiers/java/README.md verifiers/java/mutants/MUTANTS.md
example="$(mktemp -d)"
verifiers/java/readme-example "$example" | sed -e 's/\x1b\[[0-9;]*m//g' | grep -v '^\[INFO\]'
rm -rf "$example"

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
    --choose TADD-ERROR-ORDER=field-range-first --choose HOUR-D1-OUT-OF-RANGE=error"

# The shared table of faults through the README's entry point (the JUnit 5 factory under
# Surefire), every row; the modules are built by now, so `--build` only compiles the hostile ones.
python3 verifiers/parity/run.py --lang java

# The same gate must reject a mutant served the same way (exit 1, not 0 and not 2).
gate_rejects java "verifiers/java/reference-adapter --mutant tadd-sm8022-not-written" --family fx5-time-add
echo "java: done in $((SECONDS - started)) s"
