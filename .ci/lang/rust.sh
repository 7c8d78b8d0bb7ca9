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
step "cargo test (one test per vector, mutants, loading, the README's example crate)"
cargo test --locked --release --manifest-path "$crate/Cargo.toml" --workspace

step "the shared table of faults (verifiers/parity/faults.toml) through the cargo test harness"
verifiers/rust/faults-entry --build
python3 verifiers/parity/run.py --lang rust --no-build

step "the reference over the stdio protocol: plcvec verify"
python3 -m plcvec verify --adapter "$crate/reference-adapter" -q
step "the gate rejects a mutant of the reference served over stdio"
gate_rejects rust "$crate/reference-adapter --mutant tadd-device-range-unchecked" --family fx5-time-add
step "done"
