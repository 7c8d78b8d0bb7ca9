#!/usr/bin/env bash
# The Go verifier (verifiers/go): format, vet and staticcheck as Go users run them, the public API
# against the previous release (apidiff), the tests (the race detector on the package whose
# concurrency it can see), the table of faults, the README's commands and files copied into an
# empty folder as a module that fetches plcvec through a module proxy, and the Go reference
# through `plcvec verify` over the stdio protocol. Quiet on success but for its last line; a step
# that fails prints its output.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../gate-rejects.sh"
source "$(dirname "${BASH_SOURCE[0]}")/../steps.sh"
cd "$(dirname "$0")/../.."
GO_DIR=verifiers/go
export GOFLAGS="${GOFLAGS:-} -mod=readonly"
# The collector paced at GOGC=400 (Go's default is 100) for every Go program the lane starts: the
# compiler, the linters, the tests and the runners' processes each build or load their all and
# exit, and at 100 a quarter of their CPU went to collecting the garbage. No check reads it: the
# allocation tests count allocations and bytes allocated, not the heap's size.
export GOGC="${GOGC:-400}"
# The linters' versions, pinned; installed into a cache of their own on first use.
STATICCHECK=honnef.co/go/tools/cmd/staticcheck@v0.8.2
tools="${XDG_CACHE_HOME:-$HOME/.cache}/plcvec/go-tools"
steps_begin go

# quiet runs a step and shows its output only when it fails.
quiet() {
    local out
    if ! out=$("$@" 2>&1); then
        printf '%s\n' "$out" >&2
        echo "go: failed: $*" >&2
        return 1
    fi
}

step "mod download"
(cd "$GO_DIR" && quiet go mod download)
step "gofmt"
unformatted=$(cd "$GO_DIR" && gofmt -l .)
if [ -n "$unformatted" ]; then
    echo "gofmt: these files are not formatted:" >&2
    echo "$unformatted" >&2
    exit 1
fi
step "vet"
(cd "$GO_DIR" && quiet go vet ./...)
step "staticcheck"
if [ ! -x "$tools/staticcheck@${STATICCHECK##*@}/staticcheck" ]; then
    GOBIN="$tools/staticcheck@${STATICCHECK##*@}" GOFLAGS= quiet go install "$STATICCHECK"
fi
(cd "$GO_DIR" && quiet "$tools/staticcheck@${STATICCHECK##*@}/staticcheck" ./...)
# A change apidiff calls incompatible must be under Breaking in CHANGES.md; a rename must fail it.
step "apicheck"
quiet "$GO_DIR/apicheck" --self-test
# Import cycles: the Go toolchain refuses any (go vet and go build above), so none needs a tool.
# The race detector on the package with goroutines of its own (Load's parallel reads, Run's
# second process and its bound), -short trimming its whole-set run there; the other packages
# without it. The package's tests that give the detector nothing new run without it, each once:
# those whose goroutines run in a child test binary whose failure they expect, so that a race
# report there would go unread (TestTimeout, TestSettingWarningsOncePerRun); those that start a
# child only to read a setting or a selection (TestRunPatternSelectsID, TestEnvVectors); and those
# that drive once more a path the race run's other tests drive (Run's second process on a
# passing family: TestPlcvecReference; a sound load and a refused one: TestLoadRefusesDamage); and
# those of loading's shortcuts, which decode or check both ways in the test's goroutine alone
# (TestFastDecodeOfTheEmbeddedSet, TestFastDecodeOfDamagedLines, FuzzFastDecode's seeds,
# TestDeviceTypeConflictFound).
# Under the detector they were three quarters of its time. Every go test here runs with -vet=off:
# `go vet ./...` above ran every analyzer go test would run, on the same files.
race_blind='^(TestTimeout|TestSettingWarningsOncePerRun|TestRunPatternSelectsID|TestEnvVectors|TestEnvShard|TestRepositoryFolder|TestLoadingAFamilyAllocatesAboutItsVectors|TestLoadNamesTheVectorAtFaultInAFamilyJSON|TestUnjudgedRefusedWhenMalformed|TestFastDecodeOfTheEmbeddedSet|TestFastDecodeOfDamagedLines|FuzzFastDecode|TestDeviceTypeConflictFound)$'
step "test -race ."
(cd "$GO_DIR" && quiet go test -vet=off -race -short -count=1 -skip "$race_blind" .)
step "test the race-blind tests of . without -race"
out=$(cd "$GO_DIR" && go test -vet=off -short -count=1 -v -run "$race_blind" . 2>&1) || { echo "$out" >&2; exit 1; }
# Each by name: a name in the list that matches no test (a test renamed) must not pass unseen.
for name in $(tr -d '^$()' <<<"$race_blind" | tr '|' ' '); do
    grep -q "^--- PASS: $name (" <<<"$out" || { echo "go: $name did not run without -race:" >&2; echo "$out" >&2; exit 1; }
done
# Every package but the root one and internal/faults, whose one test (TestFaults, which skips
# outside a row) the table of faults below vets, builds and runs once per row: not built a second
# time here to run nothing.
step "test the other packages"
others=$(cd "$GO_DIR" && go list ./... | grep -v -x -e "$(sed -n 's/^module //p' go.mod)" -e '.*/internal/faults')
(cd "$GO_DIR" && quiet go test -vet=off -count=1 $others)
# The shared table of faults: every row gets `plcvec verify`'s verdict through go test + plcvec.Run.
step "table of faults"
quiet python3 verifiers/parity/run.py --lang go

# The module as a user fetches it: a zip in a module proxy (the layout `go mod download` reads,
# made of the files git tracks, as `go mod` would zip them) under the path and version the README
# gives; the README's blocks extracted into an empty folder and run there as an outside module,
# with no `replace` line. A module cache of its own, so that this copy never stands in for a real
# release in the shared one.
step "the README's module from a proxy"
outside=$(mktemp -d)
trap 'chmod -R u+w "$outside" 2>/dev/null; rm -rf "$outside"' EXIT
cmp LICENSE "$GO_DIR/LICENSE" || { echo "go: $GO_DIR/LICENSE is not the repository's LICENSE" >&2; exit 1; }
module=$(sed -n 's/^module //p' "$GO_DIR/go.mod")
version=v$(python3 -c 'import plcvec; print(plcvec.__version__)')
python3 - "$GO_DIR" "$module" "$version" "$outside/proxy" <<'PY'
import json, subprocess, sys, zipfile
from pathlib import Path
folder, module, version, proxy = sys.argv[1:]
files = subprocess.run(["git", "ls-files", "-z", folder], capture_output=True, text=True, check=True).stdout.split("\0")
# A folder with a go.mod of its own is another module, which go's module zip leaves out too.
nested = {str(Path(f).parent) for f in files if f.endswith("/go.mod") and str(Path(f).parent) != folder}
at = Path(proxy, *module.split("/"), "@v")
at.mkdir(parents=True)
with zipfile.ZipFile(at / f"{version}.zip", "w", zipfile.ZIP_DEFLATED) as z:
    for f in sorted(files):
        if f and not any(f.startswith(n + "/") for n in nested):
            z.write(f, f"{module}@{version}/{Path(f).relative_to(folder)}")
(at / f"{version}.mod").write_bytes(Path(folder, "go.mod").read_bytes())
(at / f"{version}.info").write_text(json.dumps({"Version": version, "Time": "2026-01-01T00:00:00Z"}))
(at / "list").write_text(version + "\n")
PY
quiet python3 .ci/readme_snippets.py extract "$GO_DIR/README.md" --out "$outside/readme"
(
    cd "$outside/readme/go/myemu"
    grep -q "require $module $version" go.mod || { echo "go: the README's go.mod does not require $module $version" >&2; exit 1; }
    # The dependency's hashes as the module records them (go get would ask the checksum database).
    grep BurntSushi "$OLDPWD/$GO_DIR/go.sum" > go.sum
    export GOFLAGS=-mod=mod GOMODCACHE="$outside/modcache" GONOSUMDB=github.com/plcvec GOPROXY="file://$outside/proxy,file://$(go env GOMODCACHE)/cache/download"
    quiet bash -euo pipefail get.sh
    grep -q "require $module $version" go.mod || { echo "go: go get changed the README's require line" >&2; exit 1; }
    unformatted=$(gofmt -l .)
    [ -z "$unformatted" ] || { echo "gofmt: the README's example: $unformatted" >&2; exit 1; }
    quiet go vet ./...
    # The README's commands; a test command that loads no test file or runs no vector cannot look
    # green: the one that names a vector must have run it.
    out=$(bash -euo pipefail run.sh 2>&1) || { echo "$out" >&2; exit 1; }
    grep -q -- "--- PASS: TestPlcvec/fx5-time-add/TADD/manual-example/program" <<<"$out" \
        || { echo "go: the README's commands ran no vector:" >&2; echo "$out" >&2; exit 1; }
    quiet bash -euo pipefail vectors.sh
    # The README's known-failures file lists a vector the example passes: stale, so the run fails.
    if out=$(PLCVEC_KNOWN_FAILURES=known.toml go test -count=1 -v ./... 2>&1); then
        echo "go: the README's known.toml lists a vector the example passes, yet the run passed:" >&2
        echo "$out" >&2
        exit 1
    fi
    grep -qF "listed as a known failure (known.toml:1: our D31 is off by one) but it passes" <<<"$out" \
        || { echo "go: the README's known.toml did not give the stale message the README quotes:" >&2; echo "$out" >&2; exit 1; }
)
# The Go reference over the stdio protocol passes the suite's own gate; a mutant does not.
step "plcvec verify"
quiet python3 -m plcvec verify --adapter verifiers/go/reference-adapter -q
quiet gate_rejects go "verifiers/go/reference-adapter --mutant cp1e-and-as-or" --family cp1e-time-compare
step "done"
echo "go: formatted, vetted, staticchecked, API-checked, tested and verified in $((SECONDS - steps_started)) s"
