"""Field-by-field comparison of what an adapter reported with what a vector expects.

Everything must match exactly, including the JSON type: a bit device is true/false and a word
is an integer, so a bit reported as 1 is wrong even though Python's 1 == True.
"""
from __future__ import annotations

from dataclasses import dataclass

from .expect import Expected

_MISSING = "<not reported>"
_UNLISTED = "<not in the vector>"


@dataclass(frozen=True)
class Problem:
    """One field that differs: where, what was expected, what the adapter reported."""

    step: int | None       # None: about the vector as a whole (e.g. the number of steps)
    field: str             # "result", a device address, or "steps"
    expected: object
    actual: object
    before: object = None  # the field's value before the step, when it is a device

    def line(self) -> str:
        where = f"step {self.step} " if self.step is not None else ""
        text = f"{where}{self.field}: expected {_show(self.expected)}, got {_show(self.actual)}"
        if self.before is not None and self.expected == self.before:
            text += " (the step must leave it unchanged)"
        elif self.before is not None:
            text += f" (before the step: {_show(self.before)})"
        return text


def _show(value):
    if value is True:
        return "true"
    if value is False:
        return "false"
    if isinstance(value, str) and value.startswith("<"):
        return value
    return repr(value)


def _same(expected, actual) -> bool:
    return expected == actual and type(expected) is type(actual)


def passes(expected: Expected, msg) -> bool:
    """Whether a result message passes, decided at once for the usual answer; False means "look closer".

    True only for a result message whose steps equal the expectation value for value (one comparison
    of the whole list) and type for type wherever 1 could pass for true (the result, and devices
    expected to hold 0, 1, false or true). Such an answer is one the shape check, the schema and
    compare() all accept, so it passes without them; anything else goes the long way, which names
    the differences.
    """
    wire = expected.wire
    if wire is None or type(msg) is not dict or len(msg) != 3 or msg.get("steps") != wire \
            or msg.get("type") != "result" or type(msg.get("id")) is not str:
        return False
    for step, want, (keys, types) in zip(msg["steps"], wire, expected.typed_columns):
        if step.get("result") is not want.get("result"):   # true/false are singletons; 1 is not true
            return False
        if tuple(map(type, map(step["devices"].__getitem__, keys))) != types:
            return False
    return True


def compare(expected: Expected, steps: list) -> list[Problem]:
    """The problems of one vector's reported `steps` (an empty list means it passed)."""
    if len(steps) != len(expected.states):
        return [Problem(None, "steps", f"{len(expected.states)} steps", f"{len(steps)} steps")]
    problems = []
    scratch = expected.scratch
    for i, (step, want_state, want_result, typed) in enumerate(
            zip(steps, expected.states, expected.results, expected.typed)):
        if want_result is not None and not _same(want_result, step.get("result", _MISSING)):
            problems.append(Problem(i, "result", want_result, step.get("result", _MISSING)))
        got = step["devices"]
        if scratch:
            got = {k: v for k, v in got.items() if k not in scratch}
        # Fast path: equal dicts, and the right type wherever 0/1 could pass for false/true. Most
        # vectors pass, and this is where a run spends its time.
        if got == want_state and all(type(got[k]) is t for k, t in typed):
            continue
        before = expected.befores[i]
        for dev in sorted(set(want_state) | set(got)):
            want, have = want_state.get(dev, _UNLISTED), got.get(dev, _MISSING)
            if not _same(want, have):
                problems.append(Problem(i, dev, want, have, before.get(dev)))
    return problems
