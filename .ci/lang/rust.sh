#!/usr/bin/env bash
# The Rust verifier (verifiers/rust/, the `plcvec` crate): lint, build and test it with cargo,
# run the README's blocks as written, check the public API against the 0.1.0 release, and gate its
# reference implementation through `plcvec verify` and the shared table of faults.
# Run from the repository root by .ci/run, after the Python package is installed.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../gate-rejects.sh"
source "$(dirname "${BASH_SOURCE[0]}")/../steps.sh"
cd "$(dirname "$0")/../.."
crate=verifiers/rust
export CARGO_BUILD_JOBS=2 CARGO_TERM_COLOR=never
# Every build here is from scratch and built once: incremental data would only be written, and at
# opt-level 0 (the dev profile: clippy's and rustdoc's proc macros, the README's emulator, the
# dry run, the unit tests, the 1.82 check) one codegen unit per crate costs a fifth less CPU than
# 256 on two cores. Neither changes what is compiled or run.
export CARGO_INCREMENTAL=0 CARGO_PROFILE_DEV_CODEGEN_UNITS=1
# The release the public API is checked against (the crate's 0.1.0).
api_baseline=9ebc6da
steps_begin rust

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
scratch=$(mktemp -d)
cleanup() {
    git worktree remove --force "$scratch/baseline" >/dev/null 2>&1 || true
    rm -rf "$scratch"
}
trap cleanup EXIT

step "fetch (Cargo.lock is committed: the same dependency versions on every run)"
cargo fetch --locked --manifest-path "$crate/Cargo.toml" -q

step "cargo fmt --check"
cargo fmt --manifest-path "$crate/Cargo.toml" --all --check

# Clippy and the rustdoc JSON of the API check below share one build dir: they check the same
# dependencies, but rustdoc writes JSON on stable only with RUSTC_BOOTSTRAP=1, and cargo builds
# again what was built without it (proc-macro2's build script watches it). Clippy only lints;
# that the code builds on stable without it is the release build's and the 1.82 check's job.
checked=(env RUSTC_BOOTSTRAP=1 CARGO_BUILD_BUILD_DIR="$PWD/$crate/target/check")
step "cargo clippy --all-targets -D warnings"
"${checked[@]}" CARGO_TARGET_DIR="$crate/target/check" cargo clippy --locked --quiet --manifest-path "$crate/Cargo.toml" \
    --workspace --all-targets -- -D warnings

# Release: the reference adapter below and the benchmark reuse the same build. All but the plcvec
# crate's unit tests, which would compile the whole crate once more (with cfg(test)) in release:
# they run after the publish dry run below, in the dev profile whose dependencies it builds.
step "cargo test (one test per vector under the reference, mutants, loading, the harness, no import circle)"
cargo test --locked --release --manifest-path "$crate/Cargo.toml" --workspace --exclude plcvec
cargo test --locked --release --manifest-path "$crate/Cargo.toml" -p plcvec --test '*' --bins --examples
cargo test --locked --release --manifest-path "$crate/Cargo.toml" -p plcvec --doc

step "the crate's LICENSE is the repository's (MIT asks for the notice in every copy)"
cmp LICENSE "$crate/LICENSE"

step "the README's blocks as written: the emulator, from an empty folder, as an outside crate"
python3 .ci/readme_snippets.py extract "$crate/README.md" --out "$scratch/readme" >/dev/null
# The README depends on plcvec from crates.io: this checkout's crate stands in for it.
printf '\n[workspace]\n\n[patch.crates-io]\nplcvec = { path = "%s" }\n' "$PWD/$crate" >> "$scratch/readme/emulator/Cargo.toml"
# Its target dir is the crate's, where the dry run below builds the packaged crate in the same
# profile. Few dependencies are shared: the README's build resolves the newest versions (no lock
# file, as a user's first build), the dry run the committed lock's, and a crate is built again when
# anything below it differs; each build is a check of its own. Neither is run under a debugger, so
# neither writes debug info (a fifth of their time).
undebugged=(env CARGO_PROFILE_DEV_DEBUG=0 CARGO_TARGET_DIR="$PWD/$crate/target")
(cd "$scratch/readme/emulator" && "${undebugged[@]}" bash -euo pipefail run.sh >/dev/null)

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
published=$("${undebugged[@]}" cargo publish --dry-run --locked --manifest-path "$crate/Cargo.toml" -p plcvec 2>&1) || {
    echo "$published"; exit 1; }
if echo "$published" | grep '^warning:' | grep -v 'aborting upload due to dry run'; then
    echo "rust.sh: cargo publish --dry-run warns (above)" >&2
    exit 1
fi

step "the plcvec crate's unit tests (the dev profile: with overflow checks, on the dry run's dependencies)"
"${undebugged[@]}" cargo test --locked --manifest-path "$crate/Cargo.toml" -p plcvec --lib

step "the declared rust-version (1.82) builds the committed Cargo.lock and packages the crate without a warning"
# Cargo.lock is resolved with CARGO_RESOLVER_INCOMPATIBLE_RUST_VERSIONS=fallback (stable cargo),
# which keeps every dependency at a version whose rust-version is 1.82 or older. The package is
# not built again by 1.82 (--no-verify): cargo 1.82 resolves a packaged library afresh, to
# versions that need 1.85 (README, "Rust 1.82 to 1.84"); the check above builds it with the lock.
rustup toolchain install 1.82 --profile minimal >/dev/null 2>&1 || {
    echo "rust.sh: cannot install the 1.82 toolchain with rustup" >&2; exit 1; }
CARGO_TARGET_DIR="$crate/target/msrv" cargo +1.82 check --quiet --locked --manifest-path "$crate/Cargo.toml" --workspace --all-targets
packaged=$(CARGO_TARGET_DIR="$crate/target/msrv" cargo +1.82 package --locked --no-verify --allow-dirty \
    --manifest-path "$crate/Cargo.toml" -p plcvec 2>&1) || { echo "$packaged"; exit 1; }
if echo "$packaged" | grep -i '^warning'; then
    echo "rust.sh: cargo +1.82 package warns (above)" >&2
    exit 1
fi

step "the public API against the 0.1.0 release ($api_baseline): every breaking change listed under Breaking"
# rustdoc's JSON of both, compared by verifiers/rust/api/public_api.py (why not cargo-semver-checks:
# its docstring). Built on stable, as rustdoc writes JSON there with RUSTC_BOOTSTRAP=1.
# Both in clippy's build dir (above), which holds most of what they depend on checked already;
# each JSON in a target dir of its own (both are doc/plcvec.json).
rustdoc_json() {  # <crate folder> <target dir>
    "${checked[@]}" CARGO_TARGET_DIR="$2" cargo rustdoc --quiet --locked --manifest-path "$1/Cargo.toml" \
        -p plcvec --lib -- -Z unstable-options --output-format json
}
git worktree add --quiet --detach "$scratch/baseline" "$api_baseline"
rustdoc_json "$scratch/baseline/$crate" "$crate/target/api-baseline"
rustdoc_json "$crate" "$crate/target/api"
version=$(sed -n 's/^version = "\(.*\)"$/\1/p' "$crate/Cargo.toml" | head -1)
api=(python3 "$crate/api/public_api.py")
"${api[@]}" diff "$crate/target/api-baseline/doc/plcvec.json" "$crate/target/api/doc/plcvec.json" \
    --changes CHANGES.md --version "$version" --fragments changes.d
# The check fails on a rename nobody listed: `shard_of` renamed in a copy of today's API.
# Every occurrence (`g`): the re-export and the function both carry the name, in an order rustdoc
# does not promise, and only the re-export's is the path users write.
sed 's/"name":"shard_of"/"name":"shard_number"/g' "$crate/target/api/doc/plcvec.json" > "$scratch/renamed.json"
if "${api[@]}" diff "$crate/target/api/doc/plcvec.json" "$scratch/renamed.json" \
    --changes "$scratch/none" --version "$version" 2> "$scratch/renamed.txt"; then
    echo "rust.sh: public_api.py passed a rename of shard_of that no Breaking section lists" >&2
    exit 1
fi
grep -q 'shard_of: removed' "$scratch/renamed.txt" || { cat "$scratch/renamed.txt" >&2; exit 1; }

step "the shared table of faults (verifiers/parity/faults.toml) through the cargo test harness"
verifiers/rust/faults-entry --build
python3 verifiers/parity/run.py --lang rust --no-build

step "the README's reference over the stdio protocol, from the repository root as written"
bash -euo pipefail "$scratch/readme/repo/reference-adapter.sh"
step "the gate rejects a mutant of the reference served over stdio"
gate_rejects rust "$crate/reference-adapter --mutant tadd-device-range-unchecked" --family fx5-time-add
step "done"
