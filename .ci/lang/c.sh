#!/usr/bin/env bash
# CI for the C verifier (verifiers/c): build with -Wall -Wextra -Werror, run the CTest suite
# (the reference under every combination of alternatives, every mutant rejected, the library's
# own tests, the examples), again under AddressSanitizer and UndefinedBehaviorSanitizer, then the
# reference adapter through `plcvec verify`. Run from the repository root by .ci/run.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../gate-rejects.sh"
cd "$(dirname "$0")/../.."
C=verifiers/c

# Debian's packages: CMake and Ninja to build, cJSON for the stdio adapter only, GoogleTest for
# the C++ example. Installed only when missing, quietly.
need=()
for pkg in cmake ninja-build g++ libcjson-dev libgtest-dev; do
    dpkg -s "$pkg" >/dev/null 2>&1 || need+=("$pkg")
done
if [ ${#need[@]} -gt 0 ]; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need[@]}" >/dev/null
fi

# The README's blocks, extracted (never retyped) and run as an emulator's own project runs them:
# the library installed as the README says, then found by CMake (find_package after
# cmake --install) and by pkg-config; and FetchContent from a source archive of this folder (what
# `plcvec release` publishes as plcvec-c-<version>.tar.gz), given to FetchContent as a local source.
start=$SECONDS
python3 .ci/readme_snippets.py check "$C/README.md"
out="$PWD/$C/build-readme"
rm -rf "$out"
mkdir -p "$out/work" "$out/home"
python3 .ci/readme_snippets.py extract "$C/README.md" --out "$out/snippets" >/dev/null
ln -s "$PWD/verifiers" "$out/work/verifiers"
(cd "$out/work" && HOME="$out/home" bash "$out/snippets/install/install.sh" >/dev/null)
prefix="$out/home/.local/plcvec"
test -f "$prefix/lib/cmake/plcvec/plcvecConfigVersion.cmake" && test -f "$prefix/lib/pkgconfig/plcvec.pc"
cmp "$prefix/share/licenses/plcvec/LICENSE" LICENSE
(cd "$out/snippets/consumer" && CMAKE_PREFIX_PATH="$prefix" bash run.sh)
# GoogleTest's own filter matching nothing, and a run of nothing but skips, are not green (exit 5).
set +e
"$out/snippets/consumer/build/my_emulator_tests" --gtest_filter='NoSuchTest.*' >"$out/filter.txt" 2>&1
rc=$?
PLCVEC_FAMILY=fx5-time-add "$out/snippets/consumer/build/my_emulator_tests" >"$out/empty.txt" 2>&1
rc_empty=$?
# The README's known-failures file parses, and its entry (a vector this emulator passes) is stale.
PLCVEC_KNOWN_FAILURES="$out/snippets/known/known-failures.toml" "$out/snippets/consumer/build/my_emulator_tests" \
    >"$out/known.txt" 2>&1
rc_known=$?
set -e
[ "$rc_known" = 1 ] && grep -q "but it passes" "$out/known.txt" || { cat "$out/known.txt"; echo "c: known failures gave $rc_known"; exit 1; }
[ "$rc" = 5 ] && grep -q PLCVEC_ID "$out/filter.txt" || { cat "$out/filter.txt"; echo "c: a filter of nothing gave $rc"; exit 1; }
[ "$rc_empty" = 5 ] || { cat "$out/empty.txt"; echo "c: an empty selection gave $rc_empty"; exit 1; }
# PLCVEC_WRITE_EXPECTATIONS under GoogleTest: a run without failures writes a list without entries.
PLCVEC_WRITE_EXPECTATIONS="$out/written.toml" "$out/snippets/consumer/build/my_emulator_tests" >/dev/null
[ "$(cat "$out/written.toml")" = "# Known failures: each passing entry fails the run as stale, so fix and delete." ]
(cd "$out/snippets/consumer" && PKG_CONFIG_PATH="$prefix/lib/pkgconfig" bash pkgconfig.sh && ./my_emulator_tests >/dev/null)
# The version file: 0.2 is found (the project above), 0.3 is not.
mkdir -p "$out/version"
printf 'cmake_minimum_required(VERSION 3.16)\nproject(v NONE)\nfind_package(plcvec 0.3 QUIET)\nif(plcvec_FOUND)\n  message(FATAL_ERROR "0.3 found")\nendif()\n' \
    > "$out/version/CMakeLists.txt"
cmake -S "$out/version" -B "$out/version/build" -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
version=$(python3 -c 'import plcvec; print(plcvec.__version__)')
mkdir -p "$out/archive"
git ls-files -z "$C" | tar --null -T - --transform "s|^$C|plcvec-c-$version|" -cf "$out/archive/c.tar"
tar --transform "s|^|plcvec-c-$version/|" -rf "$out/archive/c.tar" LICENSE
tar -C "$out/archive" -xf "$out/archive/c.tar"
cp "$out/snippets/consumer/my_emulator_tests.cpp" "$out/snippets/fetchcontent/"
cmake -S "$out/snippets/fetchcontent" -B "$out/snippets/fetchcontent/build" -G Ninja \
    -DFETCHCONTENT_SOURCE_DIR_PLCVEC="$out/archive/plcvec-c-$version" >/dev/null
cmake --build "$out/snippets/fetchcontent/build" -j 2 >/dev/null
"$out/snippets/fetchcontent/build/my_emulator_tests" >/dev/null
echo "c: the README's CMake package, pkg-config and FetchContent projects in $((SECONDS - start)) s"


start=$SECONDS
cmake -S "$C" -B "$C/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$C/build" -j 2
ctest --test-dir "$C/build" -j 2 --output-on-failure --timeout 300
echo "c: release build and tests in $((SECONDS - start)) s"
# The run's text of the shared cases, byte for byte the expected text of every runner (verifiers/parity/TEXT.md).
python3 "$C/tests/text_blocks.py" "$C/build"

start=$SECONDS
cmake -S "$C" -B "$C/build-sanitize" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DPLCVEC_SANITIZE=address,undefined >/dev/null
cmake --build "$C/build-sanitize" -j 2
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir "$C/build-sanitize" -j 2 --output-on-failure --timeout 600
echo "c: sanitized build and tests in $((SECONDS - start)) s"

# Shards agree with the Python runner's: the same ids in shard 2 of 3.
diff <("$C/build/examples/tadd_emulator" --list --shard 2/3) \
     <(python3 -c 'import sys; from plcvec_verify.suite import Suite, Selection
for v in Selection(shard=(2, 3)).apply(Suite.load("vectors").vectors): print(v["id"])')
echo "c: shard 2/3 holds the same vectors as the Python runner's"

# The reference over the stdio protocol passes the Python gate; a mutant served the same way is
# rejected (exit 1), so the gate is not passing by accident.
python3 -m plcvec verify --adapter verifiers/c/reference-adapter -q
# ... and under declared alternatives other than the defaults, judged by the vectors' alternatives.
python3 -m plcvec verify -q --adapter "verifiers/c/reference-adapter --choose FX5-SM709-SCOPE=compared-operands \
    --choose CP1E-ALL-MASKED=not-compared --choose TADD-FLAGS-OFF=set-only --choose HOUR-INPUT-OFF=reset \
    --choose CP1E-ERROR-FLAGS=off --choose HOUR-FIRST-SCAN=from-next-scan --choose FX5-OR-ON-ERROR=result-off \
    --choose TADD-ERROR-ORDER=field-range-first --choose HOUR-PRESET-CHECK=every-execution --choose HOUR-M8004-OFF=valid-preset \
    --choose HOUR-D1-OUT-OF-RANGE=error"
gate_rejects c "verifiers/c/reference-adapter --mutant cp1e-and-as-or"
# The whole run's text (the failure blocks, the roll-up by reading, the skips, the summary) is
# plcvec verify's: each mutant judged in process by the C library, and served to plcvec verify by
# the stdio adapter (the header line, the time and the adapter's build notes left out).
for mutant in fx5-and-executed-when-off hour-drops-fraction cp1e-flags-not-reflected; do
    diff <("$C/build/tests/test_mutant" "$mutant" --run | grep -v '^plcvec: ' | sed -E 's/ in [0-9]+\.[0-9]{2} s$//') \
         <(python3 -m plcvec verify --adapter "verifiers/c/reference-adapter --mutant $mutant" 2>/dev/null |
           grep -v '^plcvec verify: \|^NOTE adapter: ' | sed -E 's/ in [0-9]+\.[0-9]{2} s$//')
done
echo "c: the run's text of three mutants is plcvec verify's, byte for byte"

# The shared table of faults through plcvec_main and the GoogleTest pattern: every row gives
# plcvec verify's verdict (verifiers/parity/README.md).
python3 verifiers/parity/run.py --lang c

# Live differential run: fresh cases drawn from the spec through the C reference and the spec engine.
python3 -m plcvec fuzz --adapter verifiers/c/reference-adapter --examples 500 --seed 3
