"""The verifier's fast path (compare.passes) accepts only what the full comparison accepts.

An answer is built from each vector's own expectation, as a conforming adapter would report it; the
fast path must accept it, and must refuse every answer that differs from it in a value or in a JSON
type that Python's equality does not see (1 for true, 0 for false).
"""
import pytest

from plcvec_verify import Suite
from plcvec_verify.compare import compare, passes
from plcvec_verify.runner import Plan

from conftest import REPO


@pytest.fixture(scope="module")
def plan():
    suite = Suite.load(REPO / "vectors")
    return Plan(suite, suite.vectors, {})


def answer(exp):
    steps = []
    for state, result in zip(exp.states, exp.results):
        step = {"devices": dict(state)}
        if result is not None:
            step["result"] = result
        steps.append(step)
    return {"type": "result", "id": exp.id, "steps": steps}


def with_scratch(exp, msg):
    for step in msg["steps"]:
        step["devices"].update({k: 0 for k in exp.scratch})
    return msg


def test_a_conforming_answer_passes_at_once(plan):
    fast = 0
    for exp in plan.expected.values():
        msg = with_scratch(exp, answer(exp))
        assert compare(exp, msg["steps"]) == [], exp.id
        fast += passes(exp, msg)
        assert passes(exp, msg) is (not exp.scratch), exp.id   # scratch devices go the long way
    assert fast > len(plan.expected) * 0.9


def wrong_answers(exp):
    """(what is wrong, answer) for each way a near-miss can differ from the conforming answer."""
    last = len(exp.states) - 1
    for i, (state, result) in enumerate(zip(exp.states, exp.results)):
        if result is not None:
            msg = answer(exp)
            msg["steps"][i]["result"] = int(result)
            yield f"step {i} result as an integer", msg
            msg = answer(exp)
            msg["steps"][i]["result"] = not result
            yield f"step {i} result inverted", msg
        for dev, value in state.items():
            if isinstance(value, bool):
                swapped = int(value)
            elif value in (0, 1):
                swapped = bool(value)
            else:
                swapped = value + 1
            msg = answer(exp)
            msg["steps"][i]["devices"][dev] = swapped
            yield f"step {i} {dev} = {swapped!r}", msg
    msg = answer(exp)
    msg["steps"][last]["devices"]["D9999"] = 0
    yield "an extra device", msg
    msg = answer(exp)
    msg["steps"].pop()
    yield "a step missing", msg
    msg = answer(exp)
    msg["note"] = "x"
    yield "an extra key", msg


def test_a_near_miss_never_passes_at_once(plan):
    checked = 0
    for exp in list(plan.expected.values())[::7]:
        if exp.scratch:
            continue
        for what, msg in wrong_answers(exp):
            assert not passes(exp, msg), f"{exp.id}: {what}"
            checked += 1
    assert checked > 1000
