#!/usr/bin/env bash
# CI for the C verifier (verifiers/c): build with -Wall -Wextra -Werror, run the CTest suite
# (the reference under every combination of alternatives, every mutant rejected, the library's
# own tests, the examples), again under AddressSanitizer and UndefinedBehaviorSanitizer, then the
# reference adapter through `plcvec verify`. Run from the repository root by .ci/run.
set -euo pipefail
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

# The reference over the stdio protocol passes the Python gate; a mutant served the same way is
# rejected (exit 1), so the gate is not passing by accident.
python3 -m plcvec verify --adapter verifiers/c/reference-adapter -q
set +e
python3 -m plcvec verify --adapter "verifiers/c/reference-adapter --mutant cp1e-and-as-or" -q >/dev/null
rc=$?
set -e
if [ "$rc" -ne 1 ]; then
    echo "c: the gate did not reject the mutant cp1e-and-as-or over stdio (exit $rc)" >&2
    exit 1
fi
echo "c: the gate rejects a mutant served over stdio"
