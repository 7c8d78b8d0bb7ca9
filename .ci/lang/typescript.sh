#!/usr/bin/env bash
# The TypeScript verifier: install, lint, the package packed from a clean copy (whose prepack is the
# one type check and build), test under node:test, the public API, the package as npm would publish
# it; the README's code blocks built and run by an outside project that installs the packed tarball;
# the reference adapter through `plcvec verify`; and the shared table of faults.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../gate-rejects.sh"
source "$(dirname "${BASH_SOURCE[0]}")/../steps.sh"
cd "$(dirname "$0")/../.."
root=$PWD
steps_begin typescript
# node reads every certificate NODE_EXTRA_CA_CERTS names (where the machine sets it: the system's
# bundle of authorities) as it starts, whether or not it ever makes a TLS connection: some 40 ms of
# CPU per process, where node itself starts in 15. The lane starts hundreds of node processes (two
# per row of the table of faults, the tests' own runs of node --test, npm's); only npm's downloads
# make a TLS connection, so `npm ci`, the README's npm commands and `npm publish --dry-run` are given
# the variable, and every other process starts without it.
tls_ca=${NODE_EXTRA_CA_CERTS-}
unset NODE_EXTRA_CA_CERTS
with_ca() {
    if [ -n "$tls_ca" ]; then NODE_EXTRA_CA_CERTS=$tls_ca "$@"; else "$@"; fi
}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The clean copy of the package's tracked files, which `npm pack` builds and packs.
clean="$work/clean"
(
    cd verifiers/typescript
    # The README's own install command: the lock file records every platform's optional packages.
    # --prefer-offline: a package already in npm's cache is taken from it without asking the registry
    # whether it changed (a locked version never does); one not there is still downloaded.
    step "npm ci (the lock file: the same packages on every run)"
    with_ca npm ci --prefer-offline --no-audit --no-fund --loglevel=error >/dev/null
    step "eslint"
    npm run --silent lint
    step "madge: no import circle"
    # No import circle (madge counts `import type` too); its report is printed only when it finds one.
    npm run --silent circles >"$work/circles.log" 2>&1 || { cat "$work/circles.log"; exit 1; }
    step "npm pack from a clean copy: its prepack is the one tsc (the type check and the build)"
    # The tracked files alone (no dist/, no node_modules/, nothing untracked), packed: `npm pack` runs
    # `prepack`, `npm run build`, which type-checks as `npm run typecheck` does (one tsconfig: src,
    # test and fixtures). That build is the lane's only compile: its dist/ serves the tests below,
    # the API check, the reference adapter and faults-entry, as a build here would (the same sources).
    mkdir -p "$clean"
    git ls-files -z . | tar --null -T - -cf - | tar -xf - -C "$clean"
    # The packages installed above serve the clean copy.
    ln -s "$PWD/node_modules" "$clean/node_modules"
    (cd "$clean" && npm pack --silent --pack-destination "$work" >"$work/pack.log" 2>&1) || { cat "$work/pack.log"; exit 1; }
    rm -rf dist
    cp -a "$clean/dist" dist
    step "node --test over test/"
    # node:test over test/: its whole output only when something failed, else its counts on one line.
    npm test >"$work/test.log" 2>&1 || { cat "$work/test.log"; exit 1; }
    printf 'typescript tests: %s passed, %s failed\n' "$(sed -n 's/^ℹ pass //p' "$work/test.log")" "$(sed -n 's/^ℹ fail //p' "$work/test.log")"
    step "the public API against 0.1.0's (API Extractor), a deliberate rename caught"
    # The public API against 0.1.0's (API Extractor's reports): every change named in CHANGES.md's
    # Breaking or Deprecated section, and a deliberate rename in a scratch copy caught.
    python3 api/check.py --prove crc32=crc32Renamed
    # The licence in the tarball is the repository's, word for word.
    cmp LICENSE "$root/LICENSE"
)

step "package.json's metadata"
# The package's metadata names the project's one home (pyproject.toml [tool.plcvec] home), its
# licence and version as every plcvec package does.
python3 - <<'PY'
import json, sys, tomllib
home = tomllib.load(open("pyproject.toml", "rb"))["tool"]["plcvec"]["home"]
pkg = json.load(open("verifiers/typescript/package.json"))
want = {
    "repository.url": ("git+" + home + ".git", pkg["repository"]["url"]),
    "homepage": (home + "/tree/main/verifiers/typescript#readme", pkg["homepage"]),
    "bugs.url": (home + "/issues", pkg["bugs"]["url"]),
    "license": ("MIT", pkg["license"]),
    "author": ("plcvec contributors", pkg["author"]),
    "version": (json.load(open("vectors/manifest.json"))["generator_version"], pkg["version"]),
}
bad = [f"package.json {k}: {got!r}, not {exp!r}" for k, (exp, got) in want.items() if exp != got]
if bad:
    sys.exit("\n".join(bad))
PY

step "npm publish --dry-run of the clean copy; the tarball's files and source maps"
# Publishing the clean copy packed above: `npm publish --dry-run` of that folder must pass without a
# warning (a `bin` npm would rewrite, a missing field); its own `prepack` is skipped, the build being done.
(
    cd "$clean"
    with_ca npm publish --dry-run --ignore-scripts >"$work/publish.log" 2>&1 || { cat "$work/publish.log"; exit 1; }
    # The one warning a dry run cannot avoid without a registry account: not logged in.
    if grep -i "warn" "$work/publish.log" | grep -v "requires you to be logged in"; then
        echo "npm publish --dry-run warned (above)" >&2
        exit 1
    fi
    rm node_modules
)
tarball="$work/plcvec-0.2.0.tgz"
listing=$(tar -tzf "$tarball")
for f in package/LICENSE package/README.md package/dist/src/index.js package/dist/src/index.d.ts \
    package/bin/plcvec-reference-adapter.js package/dist/src/bin/reference-adapter.js package/src/index.ts \
    package/vectors/index.json; do
    grep -qx "$f" <<<"$listing" || { echo "the tarball lacks $f" >&2; exit 1; }
done
# Every source map points at a source the tarball ships.
tar -xzf "$tarball" -C "$work"
node -e '
const fs = require("node:fs"), path = require("node:path");
const root = process.argv[1]; let n = 0;
for (const f of fs.readdirSync(path.join(root, "dist/src"), { recursive: true })) {
  if (!f.endsWith(".map")) continue;
  const map = path.join(root, "dist/src", f);
  for (const s of JSON.parse(fs.readFileSync(map, "utf8")).sources) {
    if (!fs.existsSync(path.resolve(path.dirname(map), s))) { console.error(`${map}: ${s} is not in the tarball`); process.exit(1); }
    n++;
  }
}
if (n === 0) { console.error("no source map checked"); process.exit(1); }' "$work/package"

step "the README's blocks as written, in an empty folder, with the packed tarball"
# The README's code blocks, as an outside project in an empty folder, run as written: every block is
# marked, the runnable ones are extracted (never retyped) and run in order. The one difference from a
# newcomer's machine: `npm install plcvec` installs the tarball `npm pack` made (the package is not
# taken from the registry), and vitest at the version this folder pins.
python3 .ci/readme_snippets.py check verifiers/typescript/README.md >/dev/null
outside="$work/outside"
python3 .ci/readme_snippets.py extract verifiers/typescript/README.md --out "$outside" >/dev/null
vitest_version=$(node -p "require('$root/verifiers/typescript/node_modules/vitest/package.json').version")
npm() {
    local args=() a
    for a in "$@"; do
        case "$a" in plcvec) a="$tarball" ;; vitest) a="vitest@$vitest_version" ;; esac
        args+=("$a")
    done
    with_ca command npm "${args[@]}"
}
export -f npm with_ca
# The README's `npm install`s as the lane's `npm ci`: from npm's cache where it holds the version.
export tls_ca tarball vitest_version npm_config_audit=false npm_config_fund=false npm_config_loglevel=error npm_config_prefer_offline=true
(
    cd "$outside"
    bash -euo pipefail setup.sh
    # Before compiling, node --test finds no test file: plcvec's reporter must not call that green.
    if node --test --test-reporter=plcvec/reporter >"$work/uncompiled.log" 2>&1; then
        cat "$work/uncompiled.log"; echo "node --test on uncompiled TypeScript passed" >&2; exit 1
    fi
    grep -q "no plcvec vector ran" "$work/uncompiled.log"
    bash -euo pipefail node-test.sh
    grep -q "fx5-time-add/TADD/manual-example/program" plcvec.xml
    bash -euo pipefail known.sh
    node dist/gate.js
    # The command the package installs serves the protocol (hello, then bye). The lane's own commands
    # (this and the Vitest run below, not the README's) start the installed bin links themselves: the
    # same files `npx` would find there, without npx's own start-up (some 0.4 CPU s each).
    printf '%s\n' '{"type":"hello","protocol":1,"families":{}}' '{"type":"bye"}' | node_modules/.bin/plcvec-reference-adapter | grep -q '"type":"hello"'
    bash -euo pipefail vitest.sh
    # Vitest's -t matching no test: green for Vitest alone, not with plcvec's reporter.
    if node_modules/.bin/vitest run --reporter=default --reporter=plcvec/vitest-reporter -t "no test is named this" src/vitest >"$work/vitest-t.log" 2>&1; then
        cat "$work/vitest-t.log"; echo "vitest -t matching nothing passed" >&2; exit 1
    fi
    # Failed for the reporter's reason, not for want of the command.
    grep -q "plcvec/vitest-reporter: no plcvec vector ran" "$work/vitest-t.log" || { cat "$work/vitest-t.log"; exit 1; }
) >"$work/outside.log" 2>&1 || { cat "$work/outside.log"; exit 1; }

step "the reference adapter through plcvec verify; the gate rejects a mutant"
python3 -m plcvec verify --adapter verifiers/typescript/reference-adapter -q
# A mutant served the same way is rejected (exit 1): the gate is not passing by accident.
gate_rejects typescript "verifiers/typescript/reference-adapter --mutant tadd-hour-not-wrapped" --family fx5-time-add
step "the shared table of faults (verifiers/parity/faults.toml) through faults-entry"
# The shared table of faults through faults-entry (node --test over vectorTests): the verdict
# `plcvec verify` gives, for every row.
# Built above: --no-build spares faults-entry's own compile of the same sources.
python3 verifiers/parity/run.py --lang typescript --no-build
step "done"
