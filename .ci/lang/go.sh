#!/usr/bin/env bash
# The Go verifier (verifiers/go): format, vet, test with the race detector, the README's example,
# and the Go reference implementation through `plcvec verify` over the stdio protocol.
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
# The README's example: its own module, pointed at this one by a `replace` line.
unformatted=$(cd "$GO_DIR/examples/minimal" && gofmt -l .)
[ -z "$unformatted" ] || { echo "gofmt: $unformatted" >&2; exit 1; }
(cd "$GO_DIR/examples/minimal" && go vet ./... && go test -race -count=1 ./...)
# The Go reference over the stdio protocol passes the suite's own gate; a mutant does not.
python3 -m plcvec verify --adapter verifiers/go/reference-adapter -q
gate_rejects go "verifiers/go/reference-adapter --mutant cp1e-and-as-or" --family cp1e-time-compare
echo "go: built, vetted, tested and verified in $((SECONDS - start)) s"
