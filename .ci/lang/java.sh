#!/usr/bin/env bash
# The Java verifier (verifiers/java/): build every module with warnings as errors, run the JUnit
# tests (the reference on every vector under every combination of alternatives, the mutants each
# rejected by name, the library's own tests, the README's example project), then serve the
# reference over the stdio protocol to the Python gate. Run from the repository root.
set -euo pipefail

if ! command -v mvn >/dev/null || ! command -v javac >/dev/null; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq openjdk-17-jdk-headless maven >/dev/null
fi

started=$SECONDS
# -B -q: no progress bars or download logs. Dependencies and pinned plugins come from Maven Central
# the first time, from ~/.m2 after that (the build also runs with -o once they are there).
(cd verifiers/java && mvn -B -q -Dstyle.color=never verify)
echo "java: mvn verify in $((SECONDS - started)) s"

python3 -m plcvec verify --adapter verifiers/java/reference-adapter -q
# The same gate must reject a mutant served the same way (exit 1, not 0 and not 2).
status=0
python3 -m plcvec verify --adapter "verifiers/java/reference-adapter --mutant tadd-sm8022-not-written" \
    --family fx5-time-add -q >/dev/null || status=$?
if [ "$status" -ne 1 ]; then
    echo "java: plcvec verify gave exit $status for the mutant tadd-sm8022-not-written (expected 1)" >&2
    exit 1
fi
