"""When a run proves too little to pass: no vector selected, nothing passed, too much skipped.

A gate must never pass by accident. A typo in a CI file's selection, an empty vector file, or an
adapter that supports nothing or answers `skip` to everything would otherwise report "0 failed"
and exit 0. Such a run exits NOTHING_TESTED instead (pytest's "no tests collected" status, so a
CI system treats both alike), unless the job says it means it (`--allow-empty`). `--max-skipped`
sets how much may be skipped in a run that does pass some vectors.
"""
from __future__ import annotations

from dataclasses import dataclass

from .errors import VerifyError

# The exit status of a run that proves nothing or too little (CONTRACT.md, "Exit status").
NOTHING_TESTED = 5

_WORDS = {"skip": "skipped", "xfail": "known failures"}


@dataclass(frozen=True)
class Gate:
    """What a run must show beyond "no failures" to pass."""

    allow_empty: bool = False           # accept a run that selects nothing or passes nothing
    max_skipped: float | None = None    # at most this many skipped vectors...
    percent: bool = False               # ...or, when set, this percentage of the selected ones
    option_prefix: str = "--"           # how the options are spelled where the messages are read

    def describe_limit(self) -> str:
        return f"{self.max_skipped:g}%" if self.percent else f"{self.max_skipped:g}"

    def shortfall(self, counts: dict, selected: int) -> str:
        """Why a run without failures still proves too little ("" when it is enough).

        `counts` is status -> number (runner.STATUSES); `selected` the vectors the run was given.
        """
        skipped = counts.get("skip", 0)
        allow = f"({self.option_prefix}allow-empty if this job means it)"
        if selected == 0:
            return "" if self.allow_empty else f"no vector selected: the selection matches nothing {allow}"
        if counts.get("pass", 0) == 0 and not self.allow_empty:
            others = ", ".join(f"{n} {_WORDS.get(s, s)}" for s, n in counts.items() if n)
            return f"nothing passed ({others}): the run proves nothing {allow}"
        if self.max_skipped is not None:
            share = 100.0 * skipped / selected
            over = share > self.max_skipped if self.percent else skipped > self.max_skipped
            if over:
                return (f"{skipped} of {selected} vectors skipped ({share:.1f}%), more than "
                        f"{self.option_prefix}max-skipped {self.describe_limit()} allows")
        return ""


def parse_max_skipped(text: str, option: str = "--max-skipped") -> tuple[float, bool]:
    """`N` (a count) or `N%` (a share of the selected vectors) -> (limit, percent)."""
    percent = text.endswith("%")
    number = text[:-1] if percent else text
    try:
        value = float(number) if percent else int(number)
    except ValueError:
        raise VerifyError(f"{option} takes a count N or a percentage N%, got {text!r}")
    if value < 0 or (percent and value > 100):
        raise VerifyError(f"{option} {text}: must be a count >= 0 or a percentage from 0% to 100%")
    return value, percent
