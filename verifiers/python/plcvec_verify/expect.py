"""What a vector expects of an implementation that follows given interpretation alternatives.

A vector stores, per step, only the devices that changed (`expect.devices`) and the full state at
the end (`final.devices`). Adapters report the full state after every step, which is simpler to
produce for any emulator; so the expected full state after each step is worked out here once, and
checked against the vector's own `final` so that an inconsistent vector file is caught, not trusted.

An `alternatives` entry may leave devices unjudged (`unjudged`, schema 1.1): where the pages define
nothing, that reading judges what they do define. Those devices are listed in `initial.devices` (a
write to them is no stray write) and absent from the entry's steps and final; under that entry they
keep, in `states`, the value they had before (what the failure text shows as the state before a
step), and are left out of `compared`, the states an answer is held to.
"""
from __future__ import annotations

import marshal
from dataclasses import dataclass, field

from .choices import applied_choices
from .errors import VerifyError
from .vector import request_of

# marshal's format 2 writes every object out in full (format 3 on refers back to an object met before,
# so equal steps built from shared objects would give other bytes) and names each value's exact type:
# true is not 1, 2105.0 is not 2105, and a subclass of int or dict is refused (ValueError).
PACKED_FORMAT = 2

# A step's expectation; everything else a step holds is an input.
_EXPECT = "expect"


@dataclass(frozen=True)
class Expected:
    id: str
    results: tuple          # per step: True/False for contact instructions, None otherwise
    states: tuple           # per step: {device: value} after the step, scratch left out
    initial: dict           # the state before the first step, scratch left out
    sets: tuple             # per step: its `set` (scratch left out), for `before`
    typed: tuple            # per step: (devices, their types) of the values equal to 0 or 1, see compare.py
    scratch: frozenset
    outcome: dict           # the outcome category under the chosen alternatives
    choices: dict           # interpretation -> alternative applied (only those the vector depends on)
    # The answer's steps exactly as a passing adapter reports them, for compare.passes(): None when
    # scratch devices make the reported state differ from `states`.
    wire: list | None = None
    family: str = ""
    instruction: str = ""
    # Per step: (result, *typed): what compare.steps_pass reads of a step, in one tuple.
    checks: tuple = ()
    # `wire` in marshal's format 2, for compare.steps_pass: None with `wire`.
    packed: bytes | None = None
    # {"steps": wire} in marshal's format 2: an in-process adapter's passing answer (runner.run).
    packed_answer: bytes | None = None
    # Per step: `states` in marshal's format 2, for compare.steps_pass on a vector with scratch devices.
    packed_states: tuple = ()
    # {interpretation: devices} the followed entry leaves unjudged; `ignored` holds them and the scratch
    # devices, which compare.py never compares; `compared` is `states` without the unjudged devices.
    unjudged: dict = field(default_factory=dict)
    ignored: frozenset = frozenset()
    compared: tuple = ()

    @property
    def left_out(self) -> frozenset:
        """The devices the followed alternatives leave unjudged."""
        return self.ignored - self.scratch

    def before(self, step: int) -> dict:
        """The state step `step` started from (after its `set`): only a failure's message needs it."""
        state = dict(self.states[step - 1] if step else self.initial)
        state.update(self.sets[step])
        return state


def expected_of(vector: dict, choices: dict, defaults: dict) -> Expected:
    """The expectation of `vector` for an implementation declaring `choices` (others: `defaults`)."""
    outcome = vector["outcome"]
    touched = outcome.get("interpretations", ())
    applied = applied_choices(vector, choices, defaults)
    steps_expect = [s[_EXPECT] for s in vector["steps"]]
    final = vector["final"]["devices"]
    category = outcome.get("default", outcome) if touched else outcome
    unjudged = {}
    if any(applied[i] != defaults.get(i) for i in touched):
        for alt in vector.get("alternatives", ()):
            if all(alt["choices"].get(i) == a for i, a in applied.items()):
                steps_expect, final, category = alt["expect"], alt["final"]["devices"], alt["outcome"]
                unjudged = {i: tuple(d) for i, d in sorted(alt.get("unjudged", {}).items())}
                break
        else:
            raise VerifyError(f"vector {vector['id']}: no expectation for "
                              + ", ".join(f"{i}={a}" for i, a in sorted(applied.items()))
                              + " (the vector file lists no such alternative)")
    scratch = frozenset(vector["initial"].get("scratch", ()))
    devices = vector["initial"]["devices"]
    initial = {k: v for k, v in devices.items() if k not in scratch} if scratch else dict(devices)
    state, states, sets, results = dict(initial), [], [], []
    for step, expect in zip(vector["steps"], steps_expect):
        written = step.get("set") or {}
        if scratch:
            written = {k: v for k, v in written.items() if k not in scratch}
        sets.append(written)
        state.update(written)
        state.update(expect.get("devices", {}))
        states.append(dict(state))
        results.append(expect.get("result"))
    if len(steps_expect) != len(vector["steps"]):
        raise VerifyError(f"vector {vector['id']}: {len(vector['steps'])} steps but {len(steps_expect)} expectations")
    left_out = frozenset(d for devices in unjudged.values() for d in devices)
    compared = [{k: v for k, v in st.items() if k not in left_out} for st in states] if left_out else states
    if compared[-1] != final:
        raise VerifyError(f"vector {vector['id']}: the per-step changes do not add up to `final` "
                          "(the vector file is inconsistent; regenerate it)")
    # Python's 1 == True: of equal values, those equal to 0 or 1 can be of the wrong JSON type.
    typed = []
    for st in compared:
        keys = tuple(k for k, v in st.items() if v in (0, 1))
        typed.append((keys, tuple(map(type, map(st.__getitem__, keys)))))
    ignored = scratch | left_out
    wire = None if ignored else [{"devices": st} if r is None else {"devices": st, "result": r}
                                 for st, r in zip(states, results)]
    return Expected(vector["id"], tuple(results), tuple(states), initial, tuple(sets), tuple(typed), scratch,
                    category, applied, wire, vector["family"], vector["instruction"],
                    tuple((r, *t) for r, t in zip(results, typed)),
                    None if wire is None else marshal.dumps(wire, PACKED_FORMAT),
                    None if wire is None else marshal.dumps({"steps": wire}, PACKED_FORMAT),
                    tuple(marshal.dumps(st, PACKED_FORMAT) for st in compared) if ignored else (),
                    unjudged, ignored, tuple(compared))


class Expectations:
    """The requests and expectations of one loaded vector set, each worked out once.

    A run builds them for every vector it runs; runs over the same set (every combination of
    alternatives, the pytest plugin, a benchmark) would build the same ones again. A vector's
    expectation depends only on the alternatives of the interpretations it touches, so it is kept by
    those. The vectors are not changed once loaded; an entry is used only for the very vector object
    it was made from.
    """

    def __init__(self):
        self._requests: dict[str, tuple[dict, dict]] = {}
        self._expected: dict[tuple, tuple[dict, Expected]] = {}

    def request(self, vector: dict) -> dict:
        kept = self._requests.get(vector["id"])
        if kept is None or kept[0] is not vector:
            kept = self._requests[vector["id"]] = (vector, request_of(vector))
        return kept[1]

    def expected(self, vector: dict, choices: dict, defaults: dict) -> Expected:
        key = (vector["id"], *applied_choices(vector, choices, defaults).values())
        kept = self._expected.get(key)
        if kept is None or kept[0] is not vector:
            kept = self._expected[key] = (vector, expected_of(vector, choices, defaults))
        return kept[1]
