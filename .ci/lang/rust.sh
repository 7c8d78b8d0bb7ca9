#!/usr/bin/env bash
# The Rust verifier (verifiers/rust/, the `plcvec` crate): lint, build and test it with cargo,
# run the README's example, and gate its reference implementation through `plcvec verify`.
# Run from the repository root by .ci/run, after the Python package is installed.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../gate-rejects.sh"
cd "$(dirname "$0")/../.."
crate=verifiers/rust
export CARGO_BUILD_JOBS=2 CARGO_TERM_COLOR=never
started=$SECONDS
step() { echo "-- rust: $* ($((SECONDS - started)) s)"; }

if ! command -v cargo >/dev/null; then
    echo "rust.sh: cargo is not installed (https://rustup.rs: the stable toolchain)" >&2
    exit 1
fi
# rustfmt and clippy come with rustup's default profile; add them where a minimal profile lacks them.
for component in rustfmt clippy; do
    if ! cargo "${component/rustfmt/fmt}" --version >/dev/null 2>&1; then
        rustup component add "$component"
    fi
done

step "fetch (Cargo.lock is committed: the same dependency versions on every run)"
cargo fetch --locked --manifest-path "$crate/Cargo.toml"

step "cargo fmt --check"
cargo fmt --manifest-path "$crate/Cargo.toml" --all --check

step "cargo clippy --all-targets -D warnings"
cargo clippy --locked --manifest-path "$crate/Cargo.toml" --workspace --all-targets -- -D warnings

# Release: the reference adapter below and the benchmark reuse the same build.
step "cargo test (one test per vector under the reference, mutants, loading, the harness)"
cargo test --locked --release --manifest-path "$crate/Cargo.toml" --workspace

step "the crate's LICENSE is the repository's (MIT asks for the notice in every copy)"
cmp LICENSE "$crate/LICENSE"

step "the README's emulator, extracted from the README and run as an outside crate"
readme=$(mktemp -d)
trap 'rm -rf "$readme"' EXIT
python3 .ci/readme_snippets.py extract "$crate/README.md" --out "$readme" >/dev/null
# The README depends on plcvec = "0.2" from crates.io: this checkout's crate stands in for it.
printf '\n[workspace]\n\n[patch.crates-io]\nplcvec = { path = "%s" }\n' "$PWD/$crate" >> "$readme/emulator/Cargo.toml"
(cd "$readme/emulator" && CARGO_TARGET_DIR="$OLDPWD/$crate/target/readme" bash -euo pipefail run.sh >/dev/null)

step "the published crate holds neither the reference implementation nor its mutants"
# They are the unpublished plcvec-reference crate (verifiers/rust/reference), an outside user of
# this crate's public API: the build fails if it reaches a private item.
packaged=$(cargo package --list --locked --manifest-path "$crate/Cargo.toml" -p plcvec) || {
    echo "$packaged"; exit 1; }
if echo "$packaged" | grep -v '^vectors/' | grep -Ei 'reference|mutant'; then
    echo "rust.sh: the plcvec crate's package lists the files above; they belong to plcvec-reference" >&2
    exit 1
fi

step "cargo publish --dry-run: packaged and built as crates.io would, no warning"
# The one warning a dry run always gives is that it does not upload.
published=$(cargo publish --dry-run --locked --manifest-path "$crate/Cargo.toml" -p plcvec 2>&1) || {
    echo "$published"; exit 1; }
if echo "$published" | grep '^warning:' | grep -v 'aborting upload due to dry run'; then
    echo "rust.sh: cargo publish --dry-run warns (above)" >&2
    exit 1
fi

step "the declared rust-version (1.82) builds the committed Cargo.lock"
# Cargo.lock is resolved with CARGO_RESOLVER_INCOMPATIBLE_RUST_VERSIONS=fallback (stable cargo),
# which keeps every dependency at a version whose rust-version is 1.82 or older.
rustup toolchain install 1.82 --profile minimal >/dev/null 2>&1 || {
    echo "rust.sh: cannot install the 1.82 toolchain with rustup" >&2; exit 1; }
CARGO_TARGET_DIR="$crate/target/msrv" cargo +1.82 check --locked --manifest-path "$crate/Cargo.toml" --workspace --all-targets

step "the shared table of faults (verifiers/parity/faults.toml) through the cargo test harness"
verifiers/rust/faults-entry --build
python3 verifiers/parity/run.py --lang rust --no-build

step "the reference over the stdio protocol: plcvec verify (built first, as the README says)"
"$crate/reference-adapter" --build
python3 -m plcvec verify --adapter "$crate/reference-adapter" -q
step "the gate rejects a mutant of the reference served over stdio"
gate_rejects rust "$crate/reference-adapter --mutant tadd-device-range-unchecked" --family fx5-time-add
step "done"
