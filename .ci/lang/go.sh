#!/usr/bin/env bash
# The Go verifier (verifiers/go): format, vet, test with the race detector, the table of faults,
# the module fetched through a module proxy by the README's example, and the Go reference
# implementation through `plcvec verify` over the stdio protocol.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../gate-rejects.sh"
cd "$(dirname "$0")/../.."
GO_DIR=verifiers/go
export GOFLAGS="${GOFLAGS:-} -mod=readonly"

start=$SECONDS
(cd "$GO_DIR" && go mod download)

unformatted=$(cd "$GO_DIR" && gofmt -l .)
if [ -n "$unformatted" ]; then
    echo "gofmt: these files are not formatted:" >&2
    echo "$unformatted" >&2
    exit 1
fi
(cd "$GO_DIR" && go vet ./...)
(cd "$GO_DIR" && go test -race -count=1 ./...)
# The shared table of faults: every row gets `plcvec verify`'s verdict through go test + plcvec.Run.
python3 verifiers/parity/run.py --lang go
# The module as a user fetches it: a zip in a module proxy (the layout `go mod download` reads,
# made of the files git tracks, as `go mod` would zip them) under the path and version the README
# gives, and the README's example extracted from the Markdown and built as an outside module
# against it, with no `replace` line; then the README's commands run in it. A module cache of its
# own, so that this copy never stands in for a real release in the shared one.
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
python3 .ci/readme_snippets.py extract "$GO_DIR/README.md" --out "$outside/readme" >/dev/null
(
    cd "$outside/readme/go/myemu"
    grep -q "require $module $version" go.mod || { echo "go: the README's go.mod does not require $module $version" >&2; exit 1; }
    grep BurntSushi "$OLDPWD/$GO_DIR/go.sum" > go.sum   # the dependency's hashes as the module records them
    export GOFLAGS=-mod=mod GOMODCACHE="$outside/modcache" GONOSUMDB=github.com/plcvec GOPROXY="file://$outside/proxy,file://$(go env GOMODCACHE)/cache/download"
    unformatted=$(gofmt -l .)
    [ -z "$unformatted" ] || { echo "gofmt: the README's example: $unformatted" >&2; exit 1; }
    go vet ./...
    go test -race -count=1 ./...
    bash -euo pipefail run.sh
    grep -q "require $module $version" go.mod
)
# The Go reference over the stdio protocol passes the suite's own gate; a mutant does not.
python3 -m plcvec verify --adapter verifiers/go/reference-adapter -q
gate_rejects go "verifiers/go/reference-adapter --mutant cp1e-and-as-or" --family cp1e-time-compare
echo "go: built, vetted, tested and verified in $((SECONDS - start)) s"
