#!/usr/bin/env bash
# The package as a user gets it: build the sdist and the wheel (the wheel from the sdist, so the sdist
# is shown complete), check their metadata, install each into a fresh virtual environment outside the
# checkout, and run the commands from an empty temporary folder, where no checkout can be found: the
# installed spec and vectors must be enough. Every command runs on the wheel's installation; the
# sdist's is shown to hold the same files, byte for byte, and to run.
set -euo pipefail
cd "$(dirname "$0")/.."
checkout=$PWD
work=$(mktemp -d "${TMPDIR:-/tmp}/plcvec-package.XXXXXX")
trap 'rm -rf "$work"' EXIT
started=$SECONDS
step() { echo "== package-check [$((SECONDS - started)) s] $*"; }

# The tools' environment is made without ensurepip's pip (unpacked and compiled at each venv) and this
# pip installs into it; it gets a pip all the same, uncompiled, for `build`'s isolated environments.
step "build tools"
python3 -m venv --without-pip "$work/tools"
python3 -m pip --python "$work/tools/bin/python" install --quiet --disable-pip-version-check --no-compile \
    pip build twine vermin check-wheel-contents

# requires-python says 3.10: nothing newer may be used (tomllib comes from tomli below 3.11). vermin
# reads the code for the standard library's version history; it exits 1 on anything past 3.10.
step "nothing in the package needs a Python newer than 3.10"
"$work/tools/bin/vermin" -t=3.10- --violations --no-tips --eval-annotations generator verifiers/python

step "build the sdist, then the wheel from it"
"$work/tools/bin/python" -m build --outdir "$work/dist" "$checkout" >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
sdist=$(ls "$work"/dist/plcvec-*.tar.gz)
wheel=$(ls "$work"/dist/plcvec-*-py3-none-any.whl)
"$work/tools/bin/twine" check --strict "$sdist" "$wheel"
# As the wheel's users check it (its config, the three packages one install gives, is pyproject.toml's).
"$work/tools/bin/check-wheel-contents" "$wheel"

# Run a command of the installed package from $run, with nothing of the checkout reachable. Bytecode is
# written on first import, as on a user's machine (the install compiled none, and an environment
# with PYTHONDONTWRITEBYTECODE would compile every module again in every command).
installed() {
    (cd "$run" && env -u PYTHONPATH -u PYTHONDONTWRITEBYTECODE PATH="$venv/bin:$PATH" "$@")
}

# A fresh virtual environment with `kind`'s artifact installed (the pytest extra the README names),
# and $venv and $run set for `installed`. The venv is made without a pip of its own and this pip
# installs into it (`--python`): what is installed is the same, and ensurepip's copy of pip, which
# no check runs, is not unpacked and compiled into every environment. --no-compile: no .pyc written
# at install (`installed` writes those it uses).
install_artifact() {
    local kind=$1 artifact=$2
    venv="$work/venv-$kind"
    run="$work/run-$kind"
    mkdir -p "$run"
    step "$kind: install into a fresh virtual environment (the pytest extra the README names)"
    python3 -m venv --without-pip "$venv"
    python3 -m pip --python "$venv/bin/python" install --quiet --disable-pip-version-check --no-compile "$artifact[pytest]"
}

# What an installed plcvec must do, from an empty folder: run once, on the wheel's installation (the
# sdist's is shown below to be the same files).
check_version() {
    step "$1: plcvec --version"
    installed plcvec --version | tee "$run/version.txt"
    grep -q "installed with plcvec" "$run/version.txt"
    # The spec hash it prints is the one the committed manifest records.
    grep -q "spec sha256 $(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["spec_sha256"])' "$checkout/vectors/manifest.json")" "$run/version.txt"
}

check_verify() {
    step "$1: plcvec verify on the reference adapter"
    installed plcvec verify --adapter "python3 -m plcvec_reference.adapter" --junit verify.xml >"$run/verify.txt"
    tail -3 "$run/verify.txt"
    grep -q "against $venv/.*/site-packages/plcvec_verify/_data/vectors " "$run/verify.txt"   # the installed copy
    test -s "$run/verify.xml"
}

check_commands() {
    step "$1: pytest --plcvec-adapter (a selection)"
    installed python3 -m pytest -q -p no:cacheprovider --plcvec-adapter "python3 -m plcvec_reference.adapter" \
        -k "TADD and boundary or LDDT and nonexistent_date" | tail -2

    step "$1: the commands of the package's README (verifiers/python/README.md), as written there"
    python3 .ci/readme_snippets.py extract verifiers/python/README.md --out "$run/readme" >/dev/null
    cp "$run/readme/python-readme/"*.py "$run/"
    for script in "$run/readme/python-readme/"*.sh; do
        installed bash -euo pipefail "$script" >"$run/readme.txt" 2>&1 || { cat "$run/readme.txt"; exit 1; }
    done
    tail -2 "$run/readme.txt"

    step "$1: a closed pipe on stdout gives no traceback"
    installed python3 -c 'import subprocess, sys
p = subprocess.Popen(["plcvec", "--version"], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
p.stdout.close()
err = p.stderr.read().decode()
p.wait()
sys.exit("plcvec --version into a closed pipe: " + err if "Traceback" in err else 0)'

    step "$1: plcvec review and plcvec lint"
    installed plcvec review --out review
    test -s "$run/review/review.html" && test -s "$run/review/review.md"
    installed plcvec lint | tail -1

    step "$1: plcvec generate writes nowhere it is not told to"
    if installed plcvec generate 2>"$run/generate.err"; then
        echo "plcvec generate wrote somewhere outside a checkout without --out" >&2; exit 1
    fi
    grep -q -- "--out DIR" "$run/generate.err"
    step "$1: plcvec fuzz without its extra says which to install"
    if installed plcvec fuzz --adapter "python3 -m plcvec_reference.adapter" --examples 1 2>"$run/fuzz.err"; then
        echo "plcvec fuzz ran without hypothesis installed?" >&2; exit 1
    fi
    grep -q "plcvec\[fuzz\]" "$run/fuzz.err"
}

install_artifact wheel "$wheel"
check_version wheel
check_verify wheel
check_commands wheel
step "wheel: it carries the LICENSE"
# (listed to a file first: `grep -q` closing the pipe early would fail the pipeline under pipefail)
python3 -m zipfile -l "$wheel" >"$run/members.txt"
grep -q "licenses/LICENSE" "$run/members.txt"

# The sdist as a user installs it: pip builds a wheel from it and installs that. The wheel above was
# built from this sdist too, so the two installations must hold the same files, byte for byte (each
# file's sha256 in RECORD), and the same distributions beside them: then every check above holds for
# the sdist's installation as well, and is not run a second time. The console scripts, which pip
# writes for each environment from entry_points.txt (compared), and direct_url.json (the artifact's
# path) are the only files that differ. It is still run: its version, and verify on the reference.
install_artifact sdist "$sdist"
step "sdist: installs what the wheel installs, byte for byte"
python3 .ci/same-install.py "$work/venv-wheel" "$work/venv-sdist"
check_version sdist
check_verify sdist
step "sdist: it carries the LICENSE, and no tests/"
tar -tzf "$sdist" >"$run/members.txt"
grep -q "^plcvec-[^/]*/LICENSE$" "$run/members.txt"
if grep -q "/tests/" "$run/members.txt"; then echo "the sdist ships tests/ without the checkout they need" >&2; exit 1; fi

# Once: the installed generator reproduces the installed golden set byte for byte.
venv="$work/venv-wheel" run="$work/run-wheel"
step "wheel: plcvec generate --check against the installed vectors"
installed plcvec generate --check

step "done in $((SECONDS - started)) s"
