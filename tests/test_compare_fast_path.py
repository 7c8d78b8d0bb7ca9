"""The verifier's quick paths (compare.passes_at_once: an in-process answer's bytes, its steps value by
value, a process's message through compare.passes) accept only what the full judging accepts.

An answer is built from each vector's own expectation, as a conforming adapter would report it; the
quick paths must accept it, and must refuse every answer that differs from it in a value or in a JSON
type that Python's equality does not see (1 for true, 0 for false, 2105.0 for the word 2105), and
the full comparison must refuse it too.
"""
from marshal import dumps

import pytest

from plcvec_verify import Suite
from plcvec_verify.adapters import Answer, InProcess
from plcvec_verify.compare import compare, judge, passes, passes_at_once, steps_pass_by_value
from plcvec_verify.expect import PACKED_FORMAT
from plcvec_verify.protocol import result_errors
from plcvec_verify.runner import Plan, run

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
            if dev in exp.left_out:     # unjudged: any word or bit is right there (below)
                continue
            if isinstance(value, bool):
                near = [int(value), float(value)]
            else:
                near = [bool(value)] if value in (0, 1) else []
                near += [value + 1, float(value)]
            for swapped in near:
                msg = answer(exp)
                msg["steps"][i]["devices"][dev] = swapped
                yield f"step {i} {dev} = {swapped!r}", msg
    for dev in sorted(exp.left_out):
        msg = answer(exp)
        msg["steps"][last]["devices"][dev] = 2.5
        yield f"unjudged {dev} = 2.5, neither a word nor a bit", msg
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
            assert compare(exp, msg["steps"]) or result_errors(msg), f"{exp.id}: {what}"
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


# -- each quick way agrees with the judging it spares ----------------------------------------------

def unjudging_choices(suite):
    """Every interpretation that has an alternative leaving devices unjudged, set to it: the vectors it
    touches have devices never compared, which the quick paths must leave out too."""
    chosen = {}
    for v in suite.vectors:
        for alt in v.get("alternatives", ()):
            if alt.get("unjudged"):
                for interp in alt["unjudged"]:
                    chosen.setdefault(interp, alt["choices"][interp])
    return chosen


QUICK_WAYS = {
    # The runner's three quick ways, each on its own: what it says of an answer's steps. The bytes are
    # there only for a vector whose devices are all compared (the others' are the implementation's own).
    "in-process bytes": lambda exp, steps: not exp.ignored and _packs_to(exp, steps),
    "in-process value by value": lambda exp, steps: steps_pass_by_value(exp, steps),
    "a process's message": lambda exp, steps: passes(exp, {"type": "result", "id": exp.id, "steps": steps}),
}


def _packs_to(exp, steps):
    assert exp.packed_answer is not None, exp.id
    try:
        return dumps({"steps": steps}, PACKED_FORMAT) == exp.packed_answer
    except ValueError:
        return False


def _forms(exp, msg):
    """The answer `msg` (a result message) as each kind of adapter hands it to the runner."""
    bare = {k: v for k, v in msg.items() if k not in ("type", "id")}
    return {"in process": (exp.id, bare, None, True), "over stdio": Answer(exp.id, msg)}


@pytest.fixture(scope="module")
def expectations(plan):
    """A sample of every family's expectations under the defaults, and of those whose followed
    alternative leaves devices unjudged."""
    suite = Suite.load(REPO / "vectors")
    chosen = unjudging_choices(suite)
    assert chosen, "no alternative leaves devices unjudged: the sample would miss that path"
    unjudging = Plan(suite, [v for v in suite.vectors if set(chosen) & set(v["outcome"].get("interpretations", ()))],
                     chosen)
    out = list(plan.expected.values())[::9] + [e for e in unjudging.expected.values() if e.unjudged]
    assert {e.family for e in out} == set(suite.headers) and sum(bool(e.scratch) for e in out) > 10
    assert sum(bool(e.unjudged) for e in out) >= 10
    return out


@pytest.mark.parametrize("way", QUICK_WAYS)
def test_each_quick_way_agrees_with_compare(expectations, way):
    """A quick way accepts the conforming answer, which compare() and the result schema accept too (else
    the runner would take the long way for every vector), and refuses the steps of every near miss,
    in each of which compare() finds a problem or the schema one. (An extra key of the message is not in its steps:
    the runner's own test of the message's keys refuses it, below.)"""
    quick = QUICK_WAYS[way]
    refused = 0
    for exp in expectations:
        conforming = with_scratch(exp, answer(exp))
        assert compare(exp, conforming["steps"]) == [] and result_errors(conforming) == [], exp.id
        assert quick(exp, conforming["steps"]) is (way != "in-process bytes" or not exp.ignored), \
            f"{way}: {exp.id}: the conforming answer"
        for what, msg in wrong_answers(exp):
            if what == "an extra key":
                continue
            msg = with_scratch(exp, msg)
            assert compare(exp, msg["steps"]) or result_errors(msg), f"{exp.id}: {what}"
            assert not quick(exp, msg["steps"]), f"{way} passes {exp.id} with {what}"
            refused += 1
    assert refused > 1000


def test_an_answer_passed_at_once_is_one_the_judging_passes(expectations):
    """The runner's decision (passes_at_once, on an answer as each kind of adapter hands it over) against
    the long way (judge): the conforming answer passes both ways; every near miss is refused at once,
    and (a sixth of them: judging an answer the schema refuses is slow) fails or errs when judged."""
    for n, exp in enumerate(expectations):
        for kind, ans in _forms(exp, with_scratch(exp, answer(exp))).items():
            assert passes_at_once(ans, exp) is True, f"{kind}: {exp.id}"
            verdict = judge(ans, exp)
            assert (verdict.status, verdict.problems, verdict.message) == ("pass", (), ""), f"{kind}: {exp.id}"
        for what, msg in wrong_answers(exp):
            for kind, ans in _forms(exp, with_scratch(exp, msg)).items():
                assert not passes_at_once(ans, exp), f"{kind}: {exp.id}: {what}"
                assert n % 6 or judge(ans, exp).status in ("fail", "error"), f"{kind}: {exp.id}: {what}"
