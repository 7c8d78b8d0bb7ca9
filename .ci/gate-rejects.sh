# Sourced by .ci/lang/*.sh (kept out of that folder, whose every script .ci/run runs).
#
# gate_rejects LANG "ADAPTER COMMAND" [plcvec verify options...]
# The gate must reject a mutant served over stdio with exit 1 (failures): not 0, which would mean
# the vectors cannot tell it from the reference, and not 2, which would be a harness error.
gate_rejects() {
    local lang=$1 adapter=$2 rc=0
    shift 2
    python3 -m plcvec verify --adapter "$adapter" -q "$@" >/dev/null || rc=$?
    if [ "$rc" -ne 1 ]; then
        echo "$lang: plcvec verify gave exit $rc for '$adapter' (expected 1: rejected)" >&2
        exit 1
    fi
    echo "$lang: the gate rejects '$adapter'"
}
