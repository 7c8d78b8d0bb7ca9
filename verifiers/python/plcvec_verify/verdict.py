"""The verdict on one vector, the statuses a verdict may have, and the problems a failing verdict
lists, each as the one failure text reads it (VOCABULARY.md: `verdict`; verifiers/parity/TEXT.md).

A leaf: the runner makes verdicts, the known-failures file turns some into others, the reports print
them; none of that is needed to say what a verdict is, so this module imports nothing of the runner's.
"""
from __future__ import annotations

import json
from dataclasses import dataclass
from typing import NamedTuple

# Result statuses. Only the first three let a run pass.
PASS, SKIP, XFAIL = "pass", "skip", "xfail"
FAIL, ERROR, STALE, NOT_RUN = "fail", "error", "stale", "not-run"
STATUSES = (PASS, FAIL, ERROR, SKIP, XFAIL, STALE, NOT_RUN)
FAILING = frozenset((FAIL, ERROR, STALE, NOT_RUN))


class Verdict(NamedTuple):
    """The verdict on one vector. Immutable: a change (a known failure applied) makes a new one.

    `VectorResult` (`plcvec_verify.runner`, `plcvec_verify`), its name until 0.3.0, still works until
    0.4.0, with a DeprecationWarning.
    """

    id: str
    family: str
    instruction: str
    status: str
    problems: tuple = ()       # (Problem, ...) for fail
    message: str = ""          # error/skip/xfail/stale reason
    notes: tuple = ()          # e.g. what the adapter wrote to stderr
    choices: dict = {}         # interpretation -> alternative the vector was judged by; never mutated
    answer: list | None = None  # a failing vector's reported steps, for the inference (infer.py)


MISSING = "<not reported>"
UNLISTED = "<not in the vector>"


@dataclass(frozen=True)
class Problem:
    """One field that differs: where, what was expected, what the implementation reported.

    `line()` is part of the one failure text every runner prints (verifiers/parity/TEXT.md).
    """

    step: int | None       # None: about the vector as a whole (e.g. the number of steps)
    field: str             # "result", a device address, or "steps"
    expected: object
    actual: object
    # For a device the vector lists: the value the implementation held before the step (what it was
    # given for step 0, its own report of the previous step after this step's `set` otherwise).
    held: object = None
    # The vector requires the step to leave the device as the vector had it before the step.
    keep: bool = False

    @property
    def before(self):
        """The value the implementation held before the step (None: not a listed device)."""
        return self.held

    def line(self) -> str:
        if self.step is None:       # about the vector as a whole: counts, shown as they are
            return f"{self.field}: expected {self.expected}, got {self.actual}"
        text = f"step {self.step} {self.field}: expected {show(self.expected)}, got {show(self.actual)}"
        if self.held is None:
            return text
        # "must leave it unchanged" only where the implementation wrote the device in this step: a
        # difference carried over from an earlier step shows the value it already held instead.
        wrote = self.actual is not MISSING and not same(self.held, self.actual)
        if self.keep and wrote:
            if same(self.held, self.expected):
                return text + " (the step must leave it unchanged)"
            return text + f" (before the step: {show(self.held)}; the step must leave it unchanged)"
        return text + f" (before the step: {show(self.held)})"


def show(value) -> str:
    """A value as the failure text shows it: JSON's spelling (true, 13, "x"), or a <...> marker."""
    if value is True:
        return "true"
    if value is False:
        return "false"
    if value is MISSING or value is UNLISTED:
        return value
    if type(value) is int:
        return str(value)
    try:
        return json.dumps(value, ensure_ascii=False, separators=(",", ":"), sort_keys=True)
    except (TypeError, ValueError):     # not a JSON value at all (an in-process answer)
        return repr(value)


def _json_type(value):
    """The JSON type a Python value stands for: a bool is a boolean, any other int an integer."""
    if isinstance(value, bool):
        return bool
    return int if isinstance(value, int) else type(value)


def same(expected, actual) -> bool:
    """Whether a reported value is the expected one: equal, and of the same JSON type (true is not 1)."""
    return expected == actual and _json_type(expected) is _json_type(actual)


def failing(status: str) -> bool:
    """Whether a verdict of this status fails the run."""
    return status in FAILING


__all__ = ["PASS", "SKIP", "XFAIL", "FAIL", "ERROR", "STALE", "NOT_RUN", "STATUSES", "FAILING",
           "Verdict", "Problem", "MISSING", "UNLISTED", "show", "same", "failing"]
