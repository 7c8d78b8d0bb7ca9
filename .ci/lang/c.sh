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

# An emulator's own project uses the library the three ways README.md shows.
start=$SECONDS
consumer="$C/examples/consumer"
out="$C/build-consumer"
rm -rf "$out"
cmake -S "$consumer" -B "$out/subdirectory" -G Ninja -DPLCVEC_HOW=subdirectory -DPLCVEC_SOURCE="$PWD" >/dev/null
cmake --build "$out/subdirectory" -j 2 >/dev/null
ctest --test-dir "$out/subdirectory" --output-on-failure
cmake --install "$out/subdirectory" --prefix "$out/prefix" >/dev/null
cmake -S "$consumer" -B "$out/package" -G Ninja -DPLCVEC_HOW=package -DCMAKE_PREFIX_PATH="$PWD/$out/prefix" >/dev/null
cmake --build "$out/package" -j 2 >/dev/null
ctest --test-dir "$out/package" --output-on-failure
if git rev-parse --verify -q HEAD >/dev/null; then      # FetchContent clones the committed tree
    cmake -S "$consumer" -B "$out/fetchcontent" -G Ninja -DPLCVEC_HOW=fetchcontent -DPLCVEC_SOURCE="$PWD" \
        -DPLCVEC_GIT_TAG="$(git rev-parse HEAD)" >/dev/null
    cmake --build "$out/fetchcontent" -j 2 >/dev/null
    ctest --test-dir "$out/fetchcontent" --output-on-failure
fi
echo "c: add_subdirectory, install + find_package and FetchContent consumers in $((SECONDS - start)) s"


start=$SECONDS
cmake -S "$C" -B "$C/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$C/build" -j 2
ctest --test-dir "$C/build" -j 2 --output-on-failure --timeout 300
echo "c: release build and tests in $((SECONDS - start)) s"

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
    --choose TADD-ERROR-ORDER=field-range-first --choose HOUR-PRESET-CHECK=every-execution --choose HOUR-M8004-OFF=valid-preset"
gate_rejects c "verifiers/c/reference-adapter --mutant cp1e-and-as-or"

# The shared table of faults through plcvec_main and the GoogleTest pattern: every row gives
# plcvec verify's verdict (verifiers/parity/README.md).
python3 verifiers/parity/run.py --lang c

# Live differential run: fresh cases drawn from the spec through the C reference and the spec engine.
python3 -m plcvec fuzz --adapter verifiers/c/reference-adapter --examples 500 --seed 3
