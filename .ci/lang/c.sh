#!/usr/bin/env bash
# CI for the C verifier (verifiers/c): the README's blocks run as a newcomer runs them (the library
# installed where cJSON and GoogleTest cannot be found, found by CMake and by pkg-config, fetched
# from a source archive; the C program; the export; the project's own build, with -Wall -Wextra
# -Werror and the CTest suite: the reference under every combination of alternatives, every mutant
# rejected and none a reading, the library's own tests, the examples), the house rules (no circle
# between modules, no long function), the shared text byte for byte, the same tests under
# AddressSanitizer and UndefinedBehaviorSanitizer, the ABI against 0.1.0 (abidiff), the reference
# adapter through `plcvec verify`, and the shared table of faults. Run from the repository root by
# .ci/run; quiet on success but for one line per part and a line as each step begins, with the
# second it began at and the CPU seconds so far (`-- c: <step> (<s> s, <cpu> CPU s)`, .ci/steps.sh).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../gate-rejects.sh"
source "$(dirname "${BASH_SOURCE[0]}")/../steps.sh"
cd "$(dirname "$0")/../.."
C=verifiers/c
steps_begin c

# Debian's packages: CMake and Ninja to build, cJSON for the stdio adapter only, GoogleTest for the
# C++ example, pkg-config for the README's pkg-config line, abigail-tools for the ABI check, ccache
# so that the library's tables, compiled in several folders here (the README's install, FetchContent,
# the project's build, the sanitized build, the ABI check's, a damaged copy's), are compiled once per
# content. Installed only when missing, quietly.
need=()
for pkg in cmake ninja-build g++ pkg-config libcjson-dev libgtest-dev abigail-tools ccache; do
    dpkg -s "$pkg" >/dev/null 2>&1 || need+=("$pkg")
done
if [ ${#need[@]} -gt 0 ]; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need[@]}" >/dev/null
fi
# Every CMake configure below (the README's blocks as written too) takes the launcher from the
# environment. The README's install and the project's build compile the library with the same
# flags from the same absolute paths (both configured from $out/work): hashed as absolute paths,
# the project's build finds the install's objects. From the sanitized build on, paths under the
# repository are hashed relative to it (CCACHE_BASEDIR), and the temporary folders (the ABI
# check's trees, the table of faults' copies) are made under it.
# On a fresh machine most compiles are misses: ccache's depend mode takes a miss's includes from
# the compiler's own -MD file instead of running the preprocessor once more for a hash that the
# direct mode (where every hit here is found) does not need.
export CMAKE_C_COMPILER_LAUNCHER=ccache CMAKE_CXX_COMPILER_LAUNCHER=ccache
export CCACHE_NOHASHDIR=1 CCACHE_DEPEND=1
export TMPDIR="$PWD/$C/build-tmp"
mkdir -p "$TMPDIR"

# ---- the README's blocks, extracted (never retyped), each run from an empty folder ---------------
# (with bash -e: a block whose first command fails does not pass on its last one's status)
start=$SECONDS
python3 .ci/readme_snippets.py check "$C/README.md" >/dev/null
skipped=$(python3 .ci/readme_snippets.py list "$C/README.md" | grep -c ': snippet-skip: ' || true)
[ "$skipped" -le 2 ] || { echo "c: the README skips $skipped blocks (at most 2: a diagram or a sample of output)"; exit 1; }
out="$PWD/$C/build-readme"
rm -rf "$out"
mkdir -p "$out/work" "$out/home"
python3 .ci/readme_snippets.py extract "$C/README.md" --out "$out/snippets" >/dev/null
ln -s "$PWD/verifiers" "$out/work/verifiers"
snippets="$out/snippets"
prefix="$out/home/.local/plcvec"

# The install, as written, on a configure where cJSON and GoogleTest cannot be found: the library
# needs a C compiler and CMake alone.
cmake() {
    if [ "${1:-}" = "-S" ]; then
        command cmake "$@" -DCMAKE_DISABLE_FIND_PACKAGE_cJSON=ON -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON
    else
        command cmake "$@"
    fi
}
export -f cmake
step "README: install"
(cd "$out/work" && HOME="$out/home" bash -e "$snippets/install/install.sh" >"$out/install.txt" 2>&1) ||
    { cat "$out/install.txt"; echo "c: the README's install fails where cJSON cannot be found"; exit 1; }
unset -f cmake
grep -q "plcvec: building the library alone" "$out/install.txt" || { cat "$out/install.txt"; echo "c: the install configured the tests"; exit 1; }
test -f "$prefix/lib/cmake/plcvec/plcvecConfigVersion.cmake" && test -f "$prefix/lib/pkgconfig/plcvec.pc"
cmp "$prefix/share/licenses/plcvec/LICENSE" LICENSE

# The GoogleTest project, found by find_package after the install.
step "README: the GoogleTest project, pkg-config"
(cd "$snippets/consumer" && CMAKE_PREFIX_PATH="$prefix" bash -e run.sh >"$out/consumer.txt" 2>&1) ||
    { cat "$out/consumer.txt"; exit 1; }
tests="$snippets/consumer/build/my_emulator_tests"
# GoogleTest's own filter matching nothing, and a run of nothing but skips, are not green (exit 5).
set +e
"$tests" --gtest_filter='NoSuchTest.*' >"$out/filter.txt" 2>&1
rc=$?
PLCVEC_FAMILY=fx5-time-add "$tests" >"$out/empty.txt" 2>&1
rc_empty=$?
# The README's known-failures file parses, and its entry (a vector this emulator passes) is stale.
PLCVEC_KNOWN_FAILURES="$snippets/known/known-failures.toml" "$tests" >"$out/known.txt" 2>&1
rc_known=$?
set -e
[ "$rc_known" = 1 ] && grep -q "but it passes" "$out/known.txt" || { cat "$out/known.txt"; echo "c: known failures gave $rc_known"; exit 1; }
[ "$rc" = 5 ] && grep -q PLCVEC_ID "$out/filter.txt" || { cat "$out/filter.txt"; echo "c: a filter of nothing gave $rc"; exit 1; }
[ "$rc_empty" = 5 ] || { cat "$out/empty.txt"; echo "c: an empty selection gave $rc_empty"; exit 1; }
# PLCVEC_WRITE_EXPECTATIONS under GoogleTest: a run without failures writes a list without entries.
PLCVEC_WRITE_EXPECTATIONS="$out/written.toml" "$tests" >/dev/null
[ "$(cat "$out/written.toml")" = "# Known failures: each passing entry fails the run as stale, so fix and delete." ]
(cd "$snippets/consumer" && PKG_CONFIG_PATH="$prefix/lib/pkgconfig" bash -e pkgconfig.sh && ./my_emulator_tests >/dev/null)
# The version file: 0.2 is found (the projects above), 0.3 is not.
mkdir -p "$out/version"
printf 'cmake_minimum_required(VERSION 3.16)\nproject(v NONE)\nfind_package(plcvec 0.3 QUIET)\nif(plcvec_FOUND)\n  message(FATAL_ERROR "0.3 found")\nendif()\n' \
    > "$out/version/CMakeLists.txt"
cmake -S "$out/version" -B "$out/version/build" -DCMAKE_PREFIX_PATH="$prefix" >/dev/null

# The C program at the level of the contract, run by CTest and by hand.
step "README: the C program"
(cd "$snippets/c-program" && CMAKE_PREFIX_PATH="$prefix" bash -e run.sh >"$out/c-program.txt" 2>&1) ||
    { cat "$out/c-program.txt"; exit 1; }
grep -q "vectors: [1-9][0-9]* pass, 0 fail" "$out/c-program.txt" || { cat "$out/c-program.txt"; exit 1; }

step "README: FetchContent"
# FetchContent, from a source archive of this folder (what `plcvec release` publishes as
# plcvec-c-<version>.tar.gz), given to FetchContent as a local source.
version=$(python3 -c 'import plcvec; print(plcvec.__version__)')
mkdir -p "$out/archive"
git ls-files -z "$C" | tar --null -T - --transform "s|^$C|plcvec-c-$version|" -cf "$out/archive/c.tar"
tar --transform "s|^|plcvec-c-$version/|" -rf "$out/archive/c.tar" LICENSE
tar -C "$out/archive" -xf "$out/archive/c.tar"
cp "$snippets/consumer/my_emulator_tests.cpp" "$snippets/fetchcontent/"
cmake -S "$snippets/fetchcontent" -B "$snippets/fetchcontent/build" -G Ninja \
    -DFETCHCONTENT_SOURCE_DIR_PLCVEC="$out/archive/plcvec-c-$version" >/dev/null
cmake --build "$snippets/fetchcontent/build" -j 2 >/dev/null
"$snippets/fetchcontent/build/my_emulator_tests" >/dev/null

step "README: export"
# The export of a vector folder into a copy laid out as the repository: the golden set's gives the
# library's own tables back.
mkdir -p "$out/export/verifiers"
cp -r "$out/archive/plcvec-c-$version" "$out/export/verifiers/c"
cp verifiers/CONTRACT.md "$out/export/verifiers/"
ln -s "$PWD/vectors" "$out/export/vectors"
(cd "$out/export" && bash -e "$snippets/export/export.sh" >/dev/null)
diff -r "$out/export/verifiers/c/src/generated" "$C/src/generated" >/dev/null
diff -r "$out/export/verifiers/c/include/plcvec/generated" "$C/include/plcvec/generated" >/dev/null
echo "c: the README's blocks (install without cJSON, CMake package, pkg-config, C program, FetchContent, export) in $((SECONDS - start)) s"

# The project's own build and checks, as the README gives them (its build folder is the one the
# steps below use).
start=$SECONDS
step "README: the project's build, CTest, plcvec verify"
(cd "$out/work" && bash -e "$snippets/project/build.sh" >"$out/project.txt" 2>&1) || { cat "$out/project.txt"; exit 1; }
grep -q "100% tests passed" "$out/project.txt" && grep -q "vectors: [1-9][0-9]* pass, 0 fail, 0 skip" "$out/project.txt" ||
    { cat "$out/project.txt"; exit 1; }
step "the house rules, the shared text"
python3 "$C/tests/house.py" "$C/build"
# The run's text of the shared cases, byte for byte the expected text of every runner (verifiers/parity/TEXT.md).
python3 "$C/tests/text_blocks.py" "$C/build" >/dev/null
echo "c: the project's build, CTest, the house rules and the shared text in $((SECONDS - start)) s"

start=$SECONDS
step "sanitized build and CTest"
export CCACHE_BASEDIR="$PWD"
# The shared library (the project's build tests the static one): the tables are linked once, into
# it, not into each of the sanitized programs.
cmake -S "$C" -B "$C/build-sanitize" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DPLCVEC_BUILD_TESTS=ON \
    -DBUILD_SHARED_LIBS=ON -DPLCVEC_SANITIZE=address,undefined >/dev/null
cmake --build "$C/build-sanitize" -j 2 >/dev/null
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir "$C/build-sanitize" -j 2 --output-on-failure --timeout 600 >"$out/sanitize.txt" 2>&1 ||
    { cat "$out/sanitize.txt"; exit 1; }
echo "c: sanitized build and tests in $((SECONDS - start)) s"

# The ABI against 0.1.0, and the check failing on a deliberate rename.
start=$SECONDS
step "abicheck --self-test"
"$C/abicheck" --self-test
echo "c: abidiff against 0.1.0 (and a rename caught) in $((SECONDS - start)) s"

step "shards, the reference over stdio, the mutants' text"
# Shards agree with the Python runner's: the same ids in shard 2 of 3.
diff <("$C/build/examples/tadd_emulator" --list --shard 2/3) \
     <(python3 -c 'import sys; from plcvec_verify.suite import Suite, Selection
for v in Selection(shard=(2, 3)).apply(Suite.load("vectors").vectors): print(v["id"])')

# The reference over the stdio protocol, under declared alternatives other than the defaults,
# judged by the vectors' alternatives; a mutant served the same way is rejected (exit 1), so the
# gate is not passing by accident.
start=$SECONDS
python3 -m plcvec verify -q --adapter "verifiers/c/reference-adapter --choose FX5-SM709-SCOPE=compared-operands \
    --choose CP1E-ALL-MASKED=not-compared --choose TADD-FLAGS-OFF=set-only --choose HOUR-INPUT-OFF=reset \
    --choose CP1E-ERROR-FLAGS=off --choose HOUR-FIRST-SCAN=after-cpu-start --choose FX5-OR-ON-ERROR=result-off \
    --choose TADD-ERROR-ORDER=field-range-first --choose HOUR-PRESET-CHECK=every-execution --choose HOUR-M8004-OFF=valid-preset \
    --choose HOUR-D1-OUT-OF-RANGE=by-field --choose HOUR-WRAP-REACH=before-wrap --choose HOUR-M8004-REPEAT=once \
    --choose HOUR-D2-SPECIAL=undefined --choose HOUR-S1-CONSTANT-RANGE=low-16-bits --choose TADD-OVERLAP=second-first \
    --choose FX5-INVALID-S3-DEVICE-RANGE=s3-first --choose CP1E-PAST-AREA-END=program-error" >/dev/null
gate_rejects c "verifiers/c/reference-adapter --mutant cp1e-and-as-or" >/dev/null
# The whole run's text (the failure blocks, the roll-up by reading, the skips, the summary) is
# plcvec verify's: each mutant judged in process by the C library, and served to plcvec verify by
# the stdio adapter (the header line, the time and the adapter's build notes left out).
for mutant in fx5-and-ignores-preceding-off hour-drops-fraction cp1e-flags-not-reflected; do
    diff <("$C/build/tests/test_mutant" "$mutant" --run | grep -v '^plcvec: ' | sed -E 's/ in [0-9]+\.[0-9]{2} s$//') \
         <(python3 -m plcvec verify --adapter "verifiers/c/reference-adapter --mutant $mutant" 2>/dev/null |
           grep -v '^plcvec verify: \|^NOTE adapter: ' | sed -E 's/ in [0-9]+\.[0-9]{2} s$//')
done
echo "c: shards, the reference under other alternatives, a mutant rejected and three mutants' text as plcvec verify's in $((SECONDS - start)) s"

# The shared table of faults through plcvec_main and the GoogleTest pattern: every row gives
# plcvec verify's verdict (verifiers/parity/README.md).
start=$SECONDS
step "table of faults"
python3 verifiers/parity/run.py --lang c >"$out/faults.txt" 2>&1 || { cat "$out/faults.txt"; exit 1; }
echo "c: $(tail -1 "$out/faults.txt") in $((SECONDS - start)) s"

# Live differential run: fresh cases drawn from the spec through the C reference and the spec engine.
step "fuzz"
python3 -m plcvec fuzz --adapter verifiers/c/reference-adapter --examples 500 --seed 3 >/dev/null
step "done"
