#!/usr/bin/env bash
# CI's run of the README's two first commands (set up, generate and check the vectors; the test
# command), as written there, in a copy of this checkout whose path holds a hyphen, a space and a
# non-ASCII letter (a path like a user's), with ../shared beside it as here.
#
# They run in a fresh virtual environment of their own, with nothing installed in it, as a new user
# starts: the README's `pip install -e` must bring everything the test command needs (pytest and its
# plugins too), and points that environment's plcvec at the copy, while CI's stays at this checkout
# for the lanes after it. Run from the repository root by .ci/run.
set -euo pipefail
cd "$(dirname "$0")/.."
started=$SECONDS
python3 .ci/readme_snippets.py extract README.md --out build/readme >/dev/null
first_commands="$PWD/build/readme/readme/first-commands.sh"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
awkward="$scratch/plcvec ci-é"
mkdir -p "$awkward"
git clone --quiet "$PWD" "$awkward/plcvec"
ln -s "$(cd .. && pwd)/shared" "$awkward/shared"
python3 -m venv "$scratch/venv"
# shellcheck disable=SC1091
source "$scratch/venv/bin/activate"
(cd "$awkward/plcvec" && bash -euxo pipefail "$first_commands")
# The environment's plcvec was the copy's (a test that imported this checkout's would pass here for
# the wrong tree).
python3 -c 'import plcvec, sys; sys.exit(0 if "plcvec ci-é" in plcvec.__file__ else "plcvec came from " + plcvec.__file__)'
echo "readme-first-commands: the README's first commands in $((SECONDS - started)) s"
