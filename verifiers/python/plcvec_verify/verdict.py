"""The verdict on one vector, and the statuses a verdict may have (VOCABULARY.md: `verdict`).

A leaf: the runner makes verdicts, the known-failures file turns some into others, the reports print
them; none of that is needed to say what a verdict is, so this module imports nothing of the runner's.
"""
from __future__ import annotations

from typing import NamedTuple

# Result statuses. Only the first three let a run pass.
PASS, SKIP, XFAIL = "pass", "skip", "xfail"
FAIL, ERROR, STALE, NOT_RUN = "fail", "error", "stale", "not-run"
STATUSES = (PASS, FAIL, ERROR, SKIP, XFAIL, STALE, NOT_RUN)
FAILING = frozenset((FAIL, ERROR, STALE, NOT_RUN))


class VectorResult(NamedTuple):
    """The verdict on one vector. Immutable: a change (a known failure applied) makes a new one."""

    id: str
    family: str
    instruction: str
    status: str
    problems: tuple = ()       # (Problem, ...) for fail
    message: str = ""          # error/skip/xfail/stale reason
    notes: tuple = ()          # e.g. what the adapter wrote to stderr
    choices: dict = {}         # interpretation -> alternative the vector was judged by; never mutated
    answer: list | None = None  # a failing vector's reported steps, for the inference (infer.py)


# VOCABULARY.md's name for the verdict type; VectorResult is the name 0.1.0's users import.
Verdict = VectorResult


def failing(status: str) -> bool:
    """Whether a verdict of this status fails the run."""
    return status in FAILING


__all__ = ["PASS", "SKIP", "XFAIL", "FAIL", "ERROR", "STALE", "NOT_RUN", "STATUSES", "FAILING", "VectorResult",
           "Verdict", "failing"]
