"""Field-by-field comparison of what an adapter reported with what a vector expects.

Everything must match exactly, including the JSON type: a bit device is true/false and a word
is an integer, so a bit reported as 1 is wrong even though Python's 1 == True.
"""
from __future__ import annotations

from dataclasses import dataclass
from marshal import dumps

from .expect import PACKED_FORMAT, Expected
from .protocol import WORD_MAX

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


def _json_type(value):
    """The JSON type a Python value stands for: a bool is a boolean, any other int an integer."""
    if isinstance(value, bool):
        return bool
    return int if isinstance(value, int) else type(value)


def _same(expected, actual) -> bool:
    return expected == actual and _json_type(expected) is _json_type(actual)


def passes(expected: Expected, msg) -> bool:
    """Whether a result message passes, decided at once for the usual answer; False means "look closer".

    True only for a result message whose steps equal the expectation value for value (one comparison
    of the whole list) and JSON type for JSON type (see `steps_pass`). Such an answer is one the
    shape check, the schema and compare() all accept, so it passes without them; anything else goes
    the long way, which names the differences.
    """
    return type(msg) is dict and len(msg) == 3 and msg.get("type") == "result" and type(msg.get("id")) is str \
        and steps_pass(expected, msg.get("steps"))


def steps_pass(expected: Expected, steps) -> bool:
    """Whether reported `steps` equal the expectation exactly, JSON types included (see `passes`).

    Python's 1 == True and 2105 == 2105.0: equal values can still be of the wrong JSON type. The usual
    answer is decided by one comparison of bytes: the steps in marshal's format, which names every
    value's exact type, against the expectation's (`Expected.packed`). Bytes that differ prove nothing
    (the devices may be listed in another order, or be of types marshal refuses, such as an int
    subclass): such steps are compared value by value and type by type.
    """
    packed = expected.packed
    if packed is not None:
        try:
            if dumps(steps, PACKED_FORMAT) == packed:
                return True
        except ValueError:      # not plain lists, dicts and numbers, or nested past marshal's depth
            pass
    return steps_pass_by_value(expected, steps)


def steps_pass_by_value(expected: Expected, steps) -> bool:
    """`steps_pass` for steps whose bytes differ from the expectation's, or whose vector has scratch
    devices (their values are the implementation's own, so there are no bytes to compare with).

    Where the values are equal, a wrong type can only be a bool for an integer 0/1 or the other way
    round (checked on the devices expected to hold 0, 1, false or true, and on the result, whose true
    and false are singletons), or a number that is not an integer at all, such as 2105.0 (caught by
    the type of the devices' sum, which is int only if every value is an int or a bool).
    """
    if expected.wire is None:
        return _steps_pass_with_scratch(expected, steps)
    if steps != expected.wire:
        return False
    for step, (want_result, keys, types) in zip(steps, expected.checks):
        devices = step["devices"]
        if step.get("result") is not want_result or type(sum(devices.values())) is not int \
                or tuple(map(type, map(devices.__getitem__, keys))) != types:
            return False
    return True


def _same_types(devices: dict, typed) -> bool:
    """The JSON-type half of an exact comparison, for `devices` already equal to the expectation."""
    keys, types = typed
    return type(sum(devices.values())) is int and tuple(map(type, map(devices.__getitem__, keys))) == types


def _steps_pass_with_scratch(expected: Expected, steps) -> bool:
    """`steps_pass` for a vector with scratch devices, whose reported values are the implementation's
    own: left out of the comparison, but still words (else the long way, with the schema)."""
    if type(steps) is not list or len(steps) != len(expected.states):
        return False
    scratch = expected.scratch
    for step, state, want_result, typed, packed in zip(steps, expected.states, expected.results, expected.typed,
                                                       expected.packed_states):
        if type(step) is not dict or len(step) != (1 if want_result is None else 2) \
                or step.get("result") is not want_result or type(step.get("devices")) is not dict:
            return False
        got = step["devices"].copy()
        for key in scratch:
            word = got.pop(key, 0)      # a scratch device may go unreported
            if type(word) is not int or not 0 <= word <= WORD_MAX:
                return False
        try:
            if dumps(got, PACKED_FORMAT) == packed:
                continue
        except ValueError:      # see steps_pass
            pass
        if got != state or not _same_types(got, typed):
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
        if got == want_state and _same_types(got, typed):
            continue
        before = expected.before(i)
        for dev in sorted(set(want_state) | set(got)):
            want, have = want_state.get(dev, _UNLISTED), got.get(dev, _MISSING)
            if not _same(want, have):
                problems.append(Problem(i, dev, want, have, before.get(dev)))
    return problems
