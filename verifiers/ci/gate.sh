#!/usr/bin/env bash
# The plcvec gate for a CI job: install plcvec, run `plcvec verify` on an implementation's adapter,
# keep the JUnit and JSON-lines reports, and write a Markdown summary (failures as a table of the
# fields that differ). The GitHub action (github/action.yml) and the GitLab template
# (gitlab/plcvec-gate.yml) both run this script; it reads its settings from the environment:
#
#   PLCVEC_ADAPTER       the adapter command (verifiers/PROTOCOL.md), required
#   PLCVEC_SELECTION     extra `plcvec verify` options choosing vectors, e.g. "--family fx5-time-add --tag boundary"
#   PLCVEC_KNOWN_FAILURES  the expectations file: known failures (TOML, verifiers/CONTRACT.md), optional;
#                        the variable every plcvec runner reads for it
#   PLCVEC_ALTERNATIVES  the interpretation alternatives followed, "ID=ALT ID=ALT", for adapters that
#                        do not declare them, optional
#   PLCVEC_PACKAGE       what to `pip install` (a requirement, a wheel or a source folder), installed into
#                        a fresh virtual environment; empty: the plcvec installed for PLCVEC_PYTHON
#   PLCVEC_REPORT_DIR    where the reports go (default: plcvec-reports)
#   PLCVEC_SUMMARY       a file the Markdown summary is appended to (default: $GITHUB_STEP_SUMMARY if
#                        set, else $PLCVEC_REPORT_DIR/summary.md)
#   PLCVEC_PYTHON        the Python that makes the virtual environment (default: python3)
#
# Under GitLab's `parallel: N` (CI_NODE_INDEX of CI_NODE_TOTAL) each job runs its shard of the vectors,
# unless PLCVEC_SHARD or a --shard in PLCVEC_SELECTION chooses one.
#
# Exit status: that of `plcvec verify` (0 passed, 1 failures, 2 usage or harness error, 5 nothing
# tested); the reports and the summary are written whatever it is.
set -uo pipefail

fail() { echo "plcvec gate: $*" >&2; exit 2; }

[ -n "${PLCVEC_ADAPTER:-}" ] || fail "PLCVEC_ADAPTER is empty: give the adapter command (the 'adapter' input)"
reports=${PLCVEC_REPORT_DIR:-plcvec-reports}
summary=${PLCVEC_SUMMARY:-${GITHUB_STEP_SUMMARY:-$reports/summary.md}}
python=${PLCVEC_PYTHON:-python3}
mkdir -p "$reports" || fail "cannot make the report folder $reports"

if [ -n "${PLCVEC_PACKAGE:-}" ]; then
    venv="${RUNNER_TEMP:-${TMPDIR:-/tmp}}/plcvec-gate-venv"
    "$python" -m venv "$venv" || fail "cannot make a virtual environment with $python"
    "$venv/bin/python" -m pip install --quiet --disable-pip-version-check "$PLCVEC_PACKAGE" \
        || fail "pip could not install $PLCVEC_PACKAGE"
    run_python="$venv/bin/python"
else
    "$python" -c "import plcvec, plcvec_verify" 2>/dev/null \
        || fail "PLCVEC_PACKAGE is empty and $python cannot import plcvec: install it or set PLCVEC_PACKAGE"
    run_python=$python
fi

args=(verify --adapter "$PLCVEC_ADAPTER" --no-progress
      --junit "$reports/junit.xml" --jsonl "$reports/results.jsonl")
if [ -n "${PLCVEC_SELECTION:-}" ]; then
    read -r -a selection <<<"$PLCVEC_SELECTION"
    args+=("${selection[@]}")
fi
[ -z "${PLCVEC_KNOWN_FAILURES:-}" ] || args+=(--expectations "$PLCVEC_KNOWN_FAILURES")
# plcvec verify reads the PLCVEC_* selection variables as defaults and refuses one that is set but
# empty; the recipes give every setting an empty default, so an empty one here means "not given".
for name in PLCVEC_ID PLCVEC_FAMILY PLCVEC_INSTRUCTION PLCVEC_TAG PLCVEC_INTERPRETATION PLCVEC_SHARD \
            PLCVEC_KNOWN_FAILURES PLCVEC_WRITE_EXPECTATIONS PLCVEC_TIMEOUT; do
    [ -n "${!name:-}" ] || unset "$name"
done
if [ "${CI_NODE_TOTAL:-1}" -gt 1 ] 2>/dev/null && [ -z "${PLCVEC_SHARD:-}" ] \
        && [[ " ${PLCVEC_SELECTION:-} " != *" --shard"* ]]; then
    args+=(--shard "${CI_NODE_INDEX:?CI_NODE_TOTAL is set but CI_NODE_INDEX is not}/$CI_NODE_TOTAL")
fi
for choice in ${PLCVEC_ALTERNATIVES:-}; do
    args+=(--choose "$choice")
done

echo "plcvec gate: plcvec ${args[*]}"
"$run_python" -m plcvec "${args[@]}" | tee "$reports/summary.txt"
status=${PIPESTATUS[0]}
# A gate that ran nothing has not passed (an empty selection, or everything skipped).
if [ "$status" = 0 ] && ! "$run_python" - "$reports/results.jsonl" <<'PY'
import json, sys
counts = json.loads(open(sys.argv[1], encoding="utf-8").read().splitlines()[-1])["counts"]
sys.exit(0 if counts.get("pass", 0) + counts.get("xfail", 0) else 1)
PY
then
    echo "plcvec gate: no vector was run and passed (empty selection, or every vector skipped): failing" >&2
    status=2
fi

if [ -s "$reports/results.jsonl" ]; then
    "$run_python" -m plcvec_verify.summary "$reports/results.jsonl" >>"$summary" \
        || echo "plcvec gate: could not write the summary" >&2
else
    {
        echo "## plcvec verify: could not run"
        echo
        echo "No report was written (exit status $status); see the job log."
    } >>"$summary"
fi
echo "plcvec gate: exit $status; reports in $reports, summary in $summary"
exit "$status"
