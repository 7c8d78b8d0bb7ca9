"""Field-by-field comparison of what an adapter reported with what a vector expects.

Everything must match exactly, including the JSON type: a bit device is true/false and a word
is an integer, so a bit reported as 1 is wrong even though Python's 1 == True. Two kinds of listed
device are never compared: the scratch words (the implementation's own work area) and the devices
the followed alternatives leave unjudged (expect.py); writing either is no stray write.
"""
from __future__ import annotations

from functools import partial
from marshal import dumps

from .adapters import result_message
from .expect import PACKED_FORMAT, Expected
from .protocol import WORD_MAX, result_errors, result_shape_ok
# Problem, MISSING, UNLISTED and show are the verdict's (verdict.py), imported here also for those who
# import them from this module, as 0.1.0 had them.
from .verdict import ERROR, FAIL, MISSING, PASS, SKIP, UNLISTED, Problem, Verdict, same, show  # noqa: F401

_MISSING, _UNLISTED = MISSING, UNLISTED


def passes_at_once(answer, expected: Expected) -> bool:
    """Whether an adapter's answer passes, decided at once for the usual one; False means "look closer"
    (judge). One of three quick ways, each accepting only what judge() passes (the test of this module
    holds each of them to it, tests/test_compare_fast_path.py):

    - an in-process adapter's answer (`bare`: the result message without `type` and `id`, never a
      fault) whose bytes in marshal's format are the expectation's (`Expected.packed_answer`;
      steps_pass says why equal bytes are exact, JSON types included);
    - such an answer whose steps equal the expectation value for value and type for type (devices
      listed in another order, values of types marshal refuses, devices never compared);
    - a process's result message, through `passes`.
    """
    _, msg, fault, bare = answer
    if not bare:
        return fault is None and passes(expected, msg)
    try:
        if dumps(msg, PACKED_FORMAT) == expected.packed_answer:
            return True
    except ValueError:      # marshal refuses it: not plain dicts, lists and numbers
        pass
    return len(msg) == 1 and steps_pass_by_value(expected, msg.get("steps"))


def judge(answer, expected: Expected, cpu_writes=frozenset()) -> Verdict:
    """The verdict on one adapter's answer (an adapters.Answer, or its fields as a plain tuple), the long
    way: a fault or a message the schema refuses is an error, steps are compared field by field, a
    `skip` skips and an `error` is one. Right for every answer; `passes_at_once` spares the usual one.
    """
    fault = answer[2]
    msg = result_message(answer)
    problems = None
    if not fault and result_shape_ok(msg):
        problems = compare(expected, msg["steps"], cpu_writes)     # shape fine: compare at once
    # A comparison that passes has seen every reported value equal to one of the vector's, which
    # are valid; the values of devices it does not compare (scratch, unjudged) it has not seen.
    errors = () if fault or (problems == [] and not expected.ignored) else result_errors(msg)
    verdict = partial(Verdict, expected.id, expected.family, expected.instruction, choices=expected.choices)
    if fault or errors:
        return verdict(ERROR, message=fault or "the result does not match result.schema.json: " + "; ".join(errors))
    if "steps" in msg:
        if problems is None:
            problems = compare(expected, msg["steps"], cpu_writes)
        return verdict(FAIL if problems else PASS, tuple(problems), answer=msg["steps"] if problems else None)
    if "skip" in msg:
        return verdict(SKIP, message=msg["skip"])
    return verdict(ERROR, message=f"the implementation reported an error: {msg['error']}")


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
    """`steps_pass` for steps whose bytes differ from the expectation's, or whose vector has devices
    that are not compared (scratch or unjudged: their values are the implementation's own, so there
    are no bytes to compare with).

    Where the values are equal, a wrong type can only be a bool for an integer 0/1 or the other way
    round (checked on the devices expected to hold 0, 1, false or true, and on the result, whose true
    and false are singletons), or a number that is not an integer at all, such as 2105.0 (caught by
    the type of the devices' sum, which is int only if every value is an int or a bool).
    """
    if expected.wire is None:
        return _steps_pass_ignoring(expected, steps)
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


def _steps_pass_ignoring(expected: Expected, steps) -> bool:
    """`steps_pass` for a vector with devices that are not compared (scratch or unjudged), whose
    reported values are the implementation's own: left out of the comparison, but still words or bits
    (else the long way, with the schema)."""
    if type(steps) is not list or len(steps) != len(expected.compared):
        return False
    scratch, left_out = expected.scratch, expected.left_out
    for step, state, want_result, typed, packed in zip(steps, expected.compared, expected.results, expected.typed,
                                                       expected.packed_states):
        if type(step) is not dict or len(step) != (1 if want_result is None else 2) \
                or step.get("result") is not want_result or type(step.get("devices")) is not dict:
            return False
        got = step["devices"].copy()
        for key in scratch:
            word = got.pop(key, 0)      # a scratch device may go unreported
            if type(word) is not int or not 0 <= word <= WORD_MAX:
                return False
        for key in left_out:
            value = got.pop(key, False)     # so may an unjudged one, a bit or a word
            if type(value) is not bool and (type(value) is not int or not 0 <= value <= WORD_MAX):
                return False
        try:
            if dumps(got, PACKED_FORMAT) == packed:
                continue
        except ValueError:      # see steps_pass
            pass
        if got != state or not _same_types(got, typed):
            return False
    return True


def compare(expected: Expected, steps: list, cpu_writes=frozenset()) -> list[Problem]:
    """The problems of one vector's reported `steps` (an empty list means it passed).

    `cpu_writes`: devices the implementation's CPU writes on its own account (CONTRACT.md); a write
    to one of them that the vector does not list is not a stray write. One the vector lists is
    compared like any other.
    """
    if len(steps) != len(expected.compared):
        return [Problem(None, "steps", f"{len(expected.compared)} steps", f"{len(steps)} steps")]
    problems = []
    ignored = expected.ignored
    for i, (step, want_state, want_result, typed) in enumerate(
            zip(steps, expected.compared, expected.results, expected.typed)):
        if want_result is not None and not same(want_result, step.get("result", _MISSING)):
            problems.append(Problem(i, "result", want_result, step.get("result", _MISSING)))
        got = step["devices"]
        if ignored:
            got = {k: v for k, v in got.items() if k not in ignored}
        # Fast path: equal dicts, and the right type wherever 0/1 could pass for false/true. Most
        # vectors pass, and this is where a run spends its time.
        if got == want_state and _same_types(got, typed):
            continue
        before = expected.before(i)
        held = _held(expected, steps, i)
        for dev in sorted(set(want_state) | set(got)):
            want, have = want_state.get(dev, _UNLISTED), got.get(dev, _MISSING)
            if want is _UNLISTED and dev in cpu_writes:
                continue
            if not same(want, have):
                if want is _UNLISTED:
                    problems.append(Problem(i, dev, want, have))
                else:
                    problems.append(Problem(i, dev, want, have, held.get(dev, _MISSING),
                                            dev in before and same(before[dev], want)))
    return problems


def _held(expected: Expected, steps: list, i: int) -> dict:
    """What the implementation held before step `i`: for step 0 what the vector gave it; after that
    its own report of step i-1, with step i's `set` written over it (the outside world writes it)."""
    if i == 0:
        return expected.before(0)
    previous = steps[i - 1].get("devices") if isinstance(steps[i - 1], dict) else None
    held = dict(previous) if isinstance(previous, dict) else {}
    held.update(expected.sets[i])
    return held
