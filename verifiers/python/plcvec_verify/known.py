"""The expectations file: vectors an implementation is known to fail, each with a reason.

    # expectations.toml
    [[known-failure]]
    id = "fx5-date-compare/LDDT</nonexistent/2024-2-30/s1/vs-previous"
    reason = "our calendar check rejects 2008/02/31 (tracked as #12)"

A listed vector that fails is reported as `xfail` and does not fail the run. A listed vector that
passes is `stale` and fails the run, and so does a listed id the suite does not have: the list can
only shrink as bugs are fixed, never rot into hiding new failures (the complaint toml-test's users
raised about skip lists). Ids are exact, not patterns, for the same reason.
"""
from __future__ import annotations

import re
import sys
from dataclasses import dataclass
from pathlib import Path

if sys.version_info >= (3, 11):
    import tomllib
else:  # the same parser, published as a backport (a dependency below 3.11 only)
    import tomli as tomllib

from .atomic import write_atomic
from .errors import VerifyError
from .files import check_regular
from .verdict import ERROR, FAIL, FAILING, NOT_RUN, PASS, STALE, XFAIL, Verdict

SECTION = "known-failure"


@dataclass(frozen=True)
class KnownFailure:
    id: str
    reason: str
    line: int


class KnownFailures:
    def __init__(self, path, entries: dict[str, KnownFailure]):
        self.path = str(path)
        self.entries = entries

    @classmethod
    def load(cls, path) -> "KnownFailures":
        path = Path(path)
        check_regular(path)     # a named pipe nobody writes would hang the run before it starts
        try:
            text = path.read_text(encoding="utf-8")
        except OSError as exc:
            raise VerifyError(f"{path}: cannot read the expectations file: {exc.strerror or exc}")
        try:
            data = tomllib.loads(text)
        except tomllib.TOMLDecodeError as exc:
            # tomllib says where only inside its message: "... (at line 2, column 47)".
            at = re.search(r" \(at line (\d+), column \d+\)$", str(exc))
            where = f"{path}:{at.group(1)}" if at else str(path)
            raise VerifyError(f"{where}: not valid TOML: {str(exc)[:at.start()] if at else exc}")
        unknown = set(data) - {SECTION}
        if unknown:
            raise VerifyError(f"{path}:{_line_of(text, sorted(unknown)[0])}: unknown key {sorted(unknown)[0]!r}; "
                              f"an expectations file holds only [[{SECTION}]] entries")
        entries = {}
        headers = [i + 1 for i, line in enumerate(text.splitlines()) if line.strip().startswith(f"[[{SECTION}]]")]
        for n, entry in enumerate(data.get(SECTION, [])):
            line = headers[n] if n < len(headers) else 0
            if not isinstance(entry, dict):
                raise VerifyError(f"{path}:{line}: [[{SECTION}]] must be a table")
            extra = set(entry) - {"id", "reason"}
            if extra:
                raise VerifyError(f"{path}:{line}: unknown key {sorted(extra)[0]!r} (an entry has `id` and `reason`)")
            vid, reason = entry.get("id"), entry.get("reason")
            if not isinstance(vid, str) or not vid:
                raise VerifyError(f"{path}:{line}: entry without an `id`")
            if not isinstance(reason, str) or not reason.strip():
                raise VerifyError(f"{path}:{line}: {vid}: every known failure needs a `reason`")
            if vid in entries:
                raise VerifyError(f"{path}:{line}: {vid} is listed twice (first at line {entries[vid].line})")
            entries[vid] = KnownFailure(vid, reason.strip(), line)
        return cls(path, entries)

    def apply(self, results: list, suite) -> None:
        """Turn listed failures into xfail, listed passes into stale; add unknown ids as stale."""
        for i, r in enumerate(results):
            entry = self.entries.get(r.id)
            if entry is None:
                continue
            where = f"{self.path}:{entry.line}"
            if r.status in (FAIL, ERROR):
                results[i] = r._replace(status=XFAIL, message=f"known failure ({where}): {entry.reason}"
                                                              + (f"; {r.message}" if r.message else ""))
            elif r.status == PASS:
                results[i] = r._replace(status=STALE, message=(
                    f"listed as a known failure ({where}: {entry.reason}) but it passes; "
                    "remove it from the expectations file"))
        for vid, entry in sorted(self.entries.items()):
            if vid in suite.by_id:
                continue
            went = suite.merged.get(vid)
            why = (f": it was merged into {went}; list that id instead" if went
                   else "; remove it from the expectations file")
            results.append(Verdict(vid, "", "", STALE, message=(
                f"listed as a known failure ({self.path}:{entry.line}) but the suite has no such vector{why}")))


def _line_of(text: str, key: str) -> int:
    for i, line in enumerate(text.splitlines(), 1):
        if line.strip().startswith(key) or line.strip().startswith(f"[{key}"):
            return i
    return 1


def write_expectations(path, results, reason: str) -> int:
    """Write the failing vectors of a run as a new expectations file (for adopting the suite)."""
    check_regular(path)
    lines = ["# Known failures: each passing entry fails the run as stale, so fix and delete.", ""]
    n = 0
    for r in sorted(results, key=lambda r: r.id):
        if (r.status in FAILING and r.status != NOT_RUN and r.family) or r.status == XFAIL:
            lines += [f"[[{SECTION}]]", f"id = {_toml_str(r.id)}", f"reason = {_toml_str(reason)}", ""]
            n += 1
    write_atomic(path, "\n".join(lines))
    return n


def _toml_str(s: str) -> str:
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'
