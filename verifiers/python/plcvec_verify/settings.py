"""The `PLCVEC_*` environment variables: the one table every runner reads them from.

Every runner (this one, and through `plcvec export` the C, Rust, Go, Java and TypeScript ones,
whose generated names carry this table) reads the same settings with the same meaning
(CONTRACT.md, "The environment"). A renamed setting is still read under its old name, with a
warning naming the new one, until the release `until` names; a `PLCVEC_*` variable that is none
of these is a misspelling until shown otherwise, and gets a warning naming the nearest setting.
"""
from __future__ import annotations

from typing import NamedTuple


class Setting(NamedTuple):
    name: str          # the variable
    option: str        # the `plcvec verify` option it is the default of
    meaning: str


class Deprecated(NamedTuple):
    name: str          # the old variable
    replacement: str   # the setting it is now read as
    since: str         # the release that renamed it
    until: str         # the first release that no longer reads it


SETTINGS = (
    Setting("PLCVEC_VECTORS", "--vectors", "a vector folder or a family file"),
    Setting("PLCVEC_ID", "--id", "exact ids or globs on the whole id, comma-separated"),
    Setting("PLCVEC_FAMILY", "--family", "family names, comma-separated"),
    Setting("PLCVEC_INSTRUCTION", "--instruction", "instruction names, comma-separated"),
    Setting("PLCVEC_TAG", "--tag", "tag names, comma-separated"),
    Setting("PLCVEC_INTERPRETATION", "--interpretation", "interpretation ids, comma-separated"),
    Setting("PLCVEC_SHARD", "--shard", "K/N: one of N shards"),
    Setting("PLCVEC_KNOWN_FAILURES", "--expectations", "the known-failures TOML file"),
    Setting("PLCVEC_WRITE_EXPECTATIONS", "--write-expectations", "write the run's failures to this TOML file"),
    Setting("PLCVEC_TIMEOUT", "--timeout", "the bound on an answer, in seconds"),
)

DEPRECATED = (
    Deprecated("PLCVEC_EXPECTATIONS", "PLCVEC_KNOWN_FAILURES", since="0.2.0", until="0.3.0"),
)

# Variables that are not settings of a run but are read by plcvec's own tools, so never misspellings:
# the validation cache of `plcvec verify`, the CI recipes (verifiers/ci), the table of faults
# (verifiers/parity), and the processes a runner starts of itself. `PLCVEC_TEST_*` is kept for the
# runners' own tests.
RESERVED = (
    "PLCVEC_CACHE_DIR",
    "PLCVEC_ADAPTER", "PLCVEC_ALTERNATIVES", "PLCVEC_GATE_SCRIPT", "PLCVEC_GATE_SHA256", "PLCVEC_PACKAGE", "PLCVEC_PYTHON",
    "PLCVEC_REPORT_DIR", "PLCVEC_SELECTION", "PLCVEC_SUMMARY",
    "PLCVEC_HOSTILE", "PLCVEC_HOSTILE_ON", "PLCVEC_HOSTILE_CHOICE", "PLCVEC_FILTER",
    "PLCVEC_CHILD", "PLCVEC_CHILD_WANT", "PLCVEC_GO_CHILD", "PLCVEC_GO_WANTED",
    "PLCVEC_HARNESS_PROGRESS", "PLCVEC_HARNESS_EACH_VECTOR", "PLCVEC_CHOOSE",
)
RESERVED_PREFIXES = ("PLCVEC_TEST_",)

# PLCVEC_TIMEOUT (CONTRACT.md, "The environment"): the bound on one answer, in seconds, when neither
# the variable nor the option sets it, and the largest bound taken (a day: no platform's clock
# overflows on it). Every runner's copy is generated from these two.
TIMEOUT_DEFAULT_S = 10
TIMEOUT_MAX_S = 86400

PREFIX = "PLCVEC_"
# The largest edit distance at which an unknown variable is taken for a misspelling of a setting.
NEAREST_DISTANCE = 3


def edit_distance(a: str, b: str) -> int:
    """Levenshtein distance (insert, delete, substitute, each 1)."""
    previous = list(range(len(b) + 1))
    for i, ca in enumerate(a, 1):
        current = [i]
        for j, cb in enumerate(b, 1):
            current.append(min(previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (ca != cb)))
        previous = current
    return previous[-1]


def nearest(name: str) -> str | None:
    """The setting `name` is most likely a misspelling of (the first by name among the closest), or
    None when none is within NEAREST_DISTANCE. A deprecated name counts as its replacement."""
    candidates = sorted({s.name for s in SETTINGS} | {d.name for d in DEPRECATED})
    best = min(candidates, key=lambda c: (edit_distance(name.upper(), c), c))
    if edit_distance(name.upper(), best) > NEAREST_DISTANCE:
        return None
    return next((d.replacement for d in DEPRECATED if d.name == best), best)


def warnings(environ) -> list[str]:
    """The warnings the environment gives (CONTRACT.md, "The environment"), sorted by variable."""
    known = {s.name for s in SETTINGS} | set(RESERVED)
    deprecated = {d.name: d for d in DEPRECATED}
    out = []
    for name in sorted(n for n in environ if n.startswith(PREFIX)):
        if name in known or name.startswith(RESERVED_PREFIXES):
            continue
        if name in deprecated:
            d = deprecated[name]
            if d.replacement in environ:
                out.append(f"warning: {name} is ignored: it is the old name of {d.replacement}, which is set too")
            else:
                out.append(f"warning: {name} is the old name of {d.replacement}, read as it until plcvec "
                           f"{d.until}; set {d.replacement} instead")
            continue
        guess = nearest(name)
        out.append(f"warning: {name} is not a plcvec setting"
                   + (f"; did you mean {guess}?" if guess else f"; the settings are {', '.join(s.name for s in SETTINGS)}"))
    return out


def read_deprecated(environ) -> dict:
    """{setting: value} for each deprecated variable set whose replacement is not set."""
    return {d.replacement: environ[d.name] for d in DEPRECATED
            if d.name in environ and d.replacement not in environ}


__all__ = ["Setting", "Deprecated", "SETTINGS", "DEPRECATED", "RESERVED", "RESERVED_PREFIXES", "warnings",
           "nearest", "edit_distance", "read_deprecated"]
