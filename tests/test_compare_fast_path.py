"""The verifier's fast path (compare.passes) accepts only what the full comparison accepts.

An answer is built from each vector's own expectation, as a conforming adapter would report it; the
fast path must accept it, and must refuse every answer that differs from it in a value or in a JSON
type that Python's equality does not see (1 for true, 0 for false, 2105.0 for the word 2105), and
the full comparison must refuse it too.
"""
import pytest

from plcvec_verify import Suite
from plcvec_verify.compare import compare, passes
from plcvec_verify.runner import Plan, run
from plcvec_verify.adapters import InProcess

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
    scratch = 0
    for exp in plan.expected.values():
        msg = with_scratch(exp, answer(exp))
        assert compare(exp, msg["steps"]) == [], exp.id
        assert passes(exp, msg), exp.id
        scratch += bool(exp.scratch)
    assert scratch > 100      # the HOUR vectors, whose scratch words are the implementation's own


def test_a_scratch_device_that_is_not_a_word_goes_the_long_way(plan):
    exps = [exp for exp in plan.expected.values() if exp.scratch]
    for bad in (70000, -1, 2.0, "0", None, True):
        for exp in exps[::10]:
            msg = answer(exp)
            msg["steps"][0]["devices"][sorted(exp.scratch)[0]] = bad
            assert not passes(exp, msg), f"{exp.id}: scratch = {bad!r}"


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
                near = [int(value), float(value)]
            else:
                near = [bool(value)] if value in (0, 1) else []
                near += [value + 1, float(value)]
            for swapped in near:
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
        for what, msg in wrong_answers(exp):
            msg = with_scratch(exp, msg)
            assert not passes(exp, msg), f"{exp.id}: {what}"
            assert compare(exp, msg["steps"]) or "key" in what, f"{exp.id}: {what}"
            checked += 1
    assert checked > 1000


class _Words:
    """An in-process adapter that reports the conforming answer with one change to every word (above 1,
    or with `every_int` to every integer)."""

    def __init__(self, plan, change, every_int=False):
        self.plan, self.change, self.lowest = plan, change, 0 if every_int else 2

    def hello(self, request):
        return {"adapter": {"name": "words", "version": "0"},
                "instructions": sorted(self.plan.instructions), "interpretations": {}}

    def run(self, request):
        msg = with_scratch(self.plan.expected[request["id"]], answer(self.plan.expected[request["id"]]))
        for step in msg["steps"]:
            step["devices"] = {k: self.change(v) if type(v) is int and v >= self.lowest else v
                               for k, v in step["devices"].items()}
        return {"steps": msg["steps"]}


def test_a_run_fails_every_vector_whose_words_are_reported_as_floats(plan):
    """2105.0 is equal to 2105 in Python, but it is not a JSON integer: each such vector fails, by name."""
    suite = Suite.load(REPO / "vectors")
    report = run(suite, InProcess(_Words(plan, float)), plan=plan)
    with_words = {exp.id for exp in plan.expected.values() if any(type(v) is int and v > 1 for st in exp.states
                                                                  for v in st.values())}
    failed = {r.id for r in report.results if r.status == "fail"}
    assert len(with_words) > 1000 and failed == with_words
    assert report.exit_code == 1
    example = next(r for r in report.results if r.status == "fail")
    assert any(type(p.actual) is float and p.actual == p.expected for p in example.problems)


def test_the_same_answer_as_ints_passes_every_vector(plan):
    """The control for the test above: the same adapter reporting ints passes everything."""
    suite = Suite.load(REPO / "vectors")
    report = run(suite, InProcess(_Words(plan, int)), plan=plan)
    assert report.counts["pass"] == len(suite.vectors) and report.exit_code == 0


def test_devices_listed_in_another_order_pass(plan):
    """The bytes of such steps differ from the expectation's; they are judged value by value, and pass."""
    checked = 0
    for exp in plan.expected.values():
        msg = answer(exp)
        for step in msg["steps"]:
            step["devices"] = dict(reversed(step["devices"].items()))
        if len(msg["steps"][0]["devices"]) > 1:
            checked += 1
        assert passes(exp, with_scratch(exp, msg)), exp.id
    assert checked > 1000


class _Word(int):
    """An int of another class: a JSON integer all the same, which marshal refuses to write."""


def test_values_marshal_refuses_are_judged_by_value(plan):
    """An int subclass, a dict subclass, a list that holds itself: no exception, the right verdict."""
    exps = [exp for exp in plan.expected.values() if not exp.scratch][::25]
    # Every int of the answer (0 and 1 too) of an int subclass: JSON integers all the same, so whichever
    # way each is judged (the fast path may take it or say "look closer"), a run passes every one.
    suite = Suite.load(REPO / "vectors")
    report = run(suite, InProcess(_Words(plan, _Word, every_int=True)), vectors=[suite.by_id[e.id] for e in exps])
    assert report.counts["pass"] == len(exps) > 100 and report.exit_code == 0
    for exp in exps:
        msg = answer(exp)
        msg["steps"][0] = type("Step", (dict,), {})(msg["steps"][0])
        # A step of a dict subclass holding exactly the expected values: passes value by value.
        assert compare(exp, msg["steps"]) == [] and passes(exp, msg) is True, exp.id
        msg = answer(exp)
        msg["steps"].append(msg["steps"])
        assert not passes(exp, msg), exp.id


def test_a_run_with_int_subclass_words_passes(plan):
    """Words of an int subclass are JSON integers: the whole run passes, judged the long way."""
    suite = Suite.load(REPO / "vectors")
    report = run(suite, InProcess(_Words(plan, _Word)), plan=plan)
    assert report.counts["pass"] == len(suite.vectors) and report.exit_code == 0


class _Reversed(_Words):
    """The conforming answer with each step's devices listed last to first."""

    def run(self, request):
        body = super().run(request)
        for step in body["steps"]:
            step["devices"] = dict(reversed(step["devices"].items()))
        return body


def test_a_run_whose_devices_come_in_another_order_passes_and_still_sees_a_float(plan):
    """Bytes that differ send an in-process answer to the value-by-value comparison, which passes what is
    right and fails what is not (a word reported as 2105.0)."""
    suite = Suite.load(REPO / "vectors")
    some = suite.vectors[::3]       # every family, a third of the time
    assert {v["family"] for v in some} == set(suite.headers)
    report = run(suite, InProcess(_Reversed(plan, int)), vectors=some)
    assert report.counts["pass"] == len(some) and report.exit_code == 0
    report = run(suite, InProcess(_Reversed(plan, float)), vectors=some)
    assert report.counts["fail"] > 300 and report.exit_code == 1
