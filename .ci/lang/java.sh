#!/usr/bin/env bash
# The Java verifier (verifiers/java/), from the repository root; quiet when it passes. The README's
# install block builds every module (warnings as errors, javadoc) and runs their JUnit tests (the
# library's own, the reference on every vector under the defaults and under every combination of
# alternatives, the mutants each rejected by name and none explained away by a reading); then a
# deployment signed with a throwaway key is staged and checked as Maven Central would, with the
# relocation of 0.1.0's coordinates; the public API is held to 0.1.0 (japicmp); the README's
# example is built from the README's blocks as an outside project; the reference, served over the
# stdio protocol, passes the Python gate (under the defaults and under two sets of other
# alternatives) and a seeded differential fuzz run; the table of faults
# runs; and the gate rejects a mutant.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../gate-rejects.sh"
source "$(dirname "${BASH_SOURCE[0]}")/../steps.sh"

if ! command -v mvn >/dev/null || ! command -v javac >/dev/null || ! command -v gpg >/dev/null; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq openjdk-17-jdk-headless maven gnupg >/dev/null
fi

repo="$(pwd)"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
# Every Maven run and every test JVM Surefire forks here is short-lived: the client compiler alone
# and the serial collector start fastest and use about half the CPU of the default tiered compiler
# and G1 (reference-adapter and faults-entry run theirs so too). Surefire reads argLine from Maven's
# system properties; MAVEN_OPTS is split on spaces, so each forked JVM (the tests, the javadoc tool)
# is given one option, the file that holds them. Maven's own JVM loads its plugins' classes (a few
# thousand, from the local repository) afresh at every start: it skips their bytecode verification,
# about a tenth of a start's CPU (the classes are javac's and the plugins' published ones).
fork_options="$scratch/fork-jvm.options"
printf '%s\n' -XX:TieredStopAtLevel=1 -XX:+UseSerialGC > "$fork_options"
export MAVEN_OPTS="${MAVEN_OPTS:-} -XX:TieredStopAtLevel=1 -XX:+UseSerialGC \
    -XX:+UnlockDiagnosticVMOptions -XX:-BytecodeVerificationRemote -DargLine=-XX:VMOptionsFile=$fork_options \
    -DadditionalJOption=-J-XX:VMOptionsFile=$fork_options"
# A step's output is kept, and shown only when it fails (Debian's Maven prints bare colour resets).
quiet() {
    local log="$scratch/step.log"
    if ! "$@" > "$log" 2>&1; then
        sed -e 's/\x1b\[[0-9;]*m//g' "$log"
        echo "java: failed: $*" >&2
        exit 1
    fi
}
steps_begin java

# The README's blocks, each marked; its install block is run as a newcomer runs it, from an empty
# folder beside a checkout called plcvec (Maven's dependencies and pinned plugins come from Maven
# Central the first time, from the local repository after that).
step "README blocks"
quiet python3 .ci/readme_snippets.py check verifiers/java/README.md verifiers/java/mutants/MUTANTS.md
quiet python3 .ci/readme_snippets.py extract verifiers/java/README.md --out "$scratch/readme"
ln -s "$repo" "$scratch/readme/plcvec"
step "install block (build, tests)"
install() { (cd "$scratch/readme" && bash install.sh); }
# The classes of Maven and of the plugins it ran, written at the end of this first build to a
# class-data archive every later Maven start of the lane maps instead of loading and verifying
# them again (some twenty starts, each about a third cheaper). Made by this run, kept by none.
maven_classes="$scratch/maven-classes.jsa"
MAVEN_OPTS="$MAVEN_OPTS -XX:ArchiveClassesAtExit=$maven_classes -Xlog:cds*=off" quiet install
if [ -f "$maven_classes" ]; then
    export MAVEN_OPTS="$MAVEN_OPTS -XX:SharedArchiveFile=$maven_classes -Xlog:cds*=off"
fi

# Ready to publish: the deployment signed with a key made for this run, staged to a folder and
# checked as Central checks one; a project naming 0.1.0's coordinates resolves the new artifact.
# The same Maven run compiles the hostile implementations of the table of faults (the faults
# profile's module, never installed or deployed: the staged folder is the same) beside the reference
# it installs: what `faults-entry --build` would do in a Maven start of its own, further down.
step "signed staged deployment"
export GNUPGHOME="$scratch/gnupg"
mkdir -m 700 "$GNUPGHOME"
quiet gpg --batch --passphrase '' --quick-gen-key 'plcvec CI throwaway <ci@plcvec.invalid>' ed25519 sign 1d
stage() { (cd verifiers/java && mvn -B -q -Dstyle.color=never deploy -Prelease,faults -DskipTests \
    -DaltDeploymentRepository="staging::file://$scratch/stage"); }
quiet stage
step "central-check"
quiet verifiers/java/central-check --signed "$scratch/stage"
step "relocation-check"
quiet verifiers/java/relocation-check "$scratch/stage"

# The public API against 0.1.0; and the same check failing when the Breaking section leaves out a
# name japicmp finds (Result, the class 0.2.0 renamed Verdict).
step "api-check"
quiet verifiers/java/api-check
step "api-check without a Breaking name"
mkdir "$scratch/unlisted" "$scratch/unlisted/changes.d"
sed 's/`Result`/Result/g' CHANGES.md > "$scratch/unlisted/CHANGES.md"
for f in changes.d/*.md; do [ -e "$f" ] && sed 's/`Result`/Result/g' "$f" > "$scratch/unlisted/$f"; done
reports=(verifiers/java/library/target/japicmp/default-cli.xml verifiers/java/reference/target/japicmp/default-cli.xml)
if verifiers/java/api-check --reports "${reports[@]}" --changes "$scratch/unlisted/CHANGES.md" 2> "$scratch/unlisted.log" \
        || ! grep -q 'org.plcvec.verify.Result: class removed' "$scratch/unlisted.log"; then
    cat "$scratch/unlisted.log"
    echo "java: api-check passed a Breaking section that does not name \`Result\`" >&2
    exit 1
fi

# The README's example, built from its blocks as an outside project.
step "README example"
quiet verifiers/java/readme-example "$scratch/example"

step "gate, defaults"
quiet python3 -m plcvec verify --adapter verifiers/java/reference-adapter -q
# The same reference under the alternatives the defaults leave out, the newest readings among them.
step "gate, other alternatives"
quiet python3 -m plcvec verify -q --adapter "verifiers/java/reference-adapter --choose HOUR-FIRST-SCAN=after-cpu-start \
    --choose HOUR-D1-OUT-OF-RANGE=by-field --choose HOUR-WRAP-REACH=before-wrap --choose HOUR-M8004-REPEAT=once \
    --choose HOUR-D2-SPECIAL=undefined --choose HOUR-S1-CONSTANT-RANGE=low-16-bits --choose TADD-OVERLAP=second-first \
    --choose FX5-INVALID-S3-DEVICE-RANGE=s3-first --choose CP1E-PAST-AREA-END=program-error"
quiet python3 -m plcvec verify -q --adapter "verifiers/java/reference-adapter \
    --choose HOUR-D1-OUT-OF-RANGE=as-seconds-if-added --choose HOUR-D2-SPECIAL=error --choose HOUR-S1-CONSTANT-RANGE=as-is \
    --choose TADD-OVERLAP=hour-first"
# Fresh inputs through the Java reference and the spec engine, under the defaults and under a set
# of other alternatives (fixed seeds: repeatable).
step "fuzz"
fuzz() {
    python3 -m plcvec fuzz --adapter verifiers/java/reference-adapter --examples 500 --seed 1
    python3 -m plcvec fuzz --examples 500 --seed 2 --adapter "verifiers/java/reference-adapter \
    --choose FX5-SM709-SCOPE=compared-operands --choose FX5-AND-OR-WHEN-OFF=short-circuit \
    --choose TADD-EXACT-24=carry-above-24 --choose TADD-ON-ERROR=computed --choose HOUR-OUTPUT-OFF=recompared \
    --choose HOUR-INPUT-OFF=hold-drop-fraction --choose CP1E-NON-BCD=raw-bytes --choose CP1E-ALL-MASKED=not-compared \
    --choose CP1E-ER-FLAG=held --choose CP1E-ERROR-FLAGS=off --choose HOUR-FIRST-SCAN=from-next-scan \
    --choose HOUR-PRESET-CHECK=every-execution --choose HOUR-M8004-OFF=valid-preset --choose FX5-OR-ON-ERROR=result-off \
    --choose TADD-ERROR-ORDER=field-range-first --choose HOUR-D1-OUT-OF-RANGE=error --choose TADD-OVERLAP=hour-first \
    --choose FX5-INVALID-S3-DEVICE-RANGE=s3-first --choose CP1E-PAST-AREA-END=program-error"
}
quiet fuzz

# The shared table of faults through the README's entry point (the JUnit 5 factory under
# Surefire, the rows in one run but for those that end their process, each of which has a Surefire
# run and test JVM of its own; all in one Maven run); built by the deployment's Maven run above
# (the reference installed, the hostile implementations compiled), so --no-build.
step "table of faults"
quiet python3 verifiers/parity/run.py --lang java --no-build

# The same gate must reject a mutant served the same way (exit 1, not 0 and not 2).
step "gate rejects a mutant"
gate_rejects java "verifiers/java/reference-adapter --mutant tadd-sm8022-not-written" --family fx5-time-add
step "done"
