"""Runs of one Plan judge every answer afresh.

A Plan keeps, per vector, the result it gets when its answer passes; nothing of a run's verdicts may
carry over to the next: a vector that passed fails when the next run's answer is wrong, and passes
again when it is right.
"""
from plcvec_verify import Suite
from plcvec_verify.adapters import InProcess
from plcvec_verify.runner import Plan, run

from conftest import REPO


class _Conforming:
    """Reports each vector's own expectation; `broken` ids get one word or bit wrong."""

    def __init__(self, plan, broken=frozenset()):
        self.plan, self.broken = plan, broken

    def hello(self, request):
        return {"adapter": {"name": "conforming", "version": "0"},
                "instructions": sorted(self.plan.instructions), "interpretations": {}}

    def run(self, request):
        exp = self.plan.expected[request["id"]]
        steps = []
        for state, result in zip(exp.states, exp.results):
            devices = dict(state)
            devices.update({k: 0 for k in exp.scratch})
            step = {"devices": devices} if result is None else {"devices": devices, "result": result}
            steps.append(step)
        if request["id"] in self.broken:
            devices = steps[-1]["devices"]
            name = sorted(k for k in devices if k not in exp.scratch)[0]
            value = devices[name]
            devices[name] = (not value) if type(value) is bool else value ^ 1   # still a word
        return {"steps": steps}


def test_a_plan_run_again_judges_each_answer_again():
    suite = Suite.load(REPO / "vectors")
    plan = Plan(suite, suite.vectors, {})
    broken = frozenset(v["id"] for v in suite.vectors[::5])

    first = run(suite, InProcess(_Conforming(plan)), plan=plan)
    assert first.counts["pass"] == len(suite.vectors) and first.exit_code == 0

    second = run(suite, InProcess(_Conforming(plan, broken)), plan=plan)
    failed = {r.id for r in second.results if r.status == "fail"}
    assert failed == broken and second.exit_code == 1
    assert all(r.problems for r in second.results if r.status == "fail")
    assert {r.id for r in second.results if r.status == "pass"} == {v["id"] for v in suite.vectors} - broken

    third = run(suite, InProcess(_Conforming(plan)), plan=plan)
    assert third.counts["pass"] == len(suite.vectors) and third.exit_code == 0
    # A pass names the vector and the alternatives it was judged by, as a freshly made result would.
    for r, v in zip(third.results, suite.vectors):
        assert (r.id, r.family, r.instruction, r.problems, r.message) == (v["id"], v["family"], v["instruction"], (), "")
        assert r.choices == plan.expected[v["id"]].choices


def test_plans_over_one_set_share_expectations_only_where_the_alternatives_agree():
    """Expectations are made once per vector and alternatives: a vector an interpretation touches gets
    the alternative's own expectation, read from its `alternatives` entry, never the default's."""
    import copy

    suite = Suite.load(REPO / "vectors")
    touched, alt = next((v, a) for v in suite.vectors for a in v.get("alternatives", ())
                        if a["final"]["devices"] != v["final"]["devices"])
    default = Plan(suite, [touched], {}).expected[touched["id"]]
    chosen = Plan(suite, [touched], alt["choices"]).expected[touched["id"]]
    assert Plan(suite, [touched], {}).expected[touched["id"]] is default
    assert chosen.choices == alt["choices"] and chosen.outcome == alt["outcome"]
    assert chosen.states[-1] == alt["final"]["devices"] and default.states[-1] == touched["final"]["devices"]
    # A vector the interpretation does not touch is judged the same whatever is chosen.
    other = next(v for v in suite.vectors if v["family"] == touched["family"]
                 and not v["outcome"].get("interpretations"))
    assert Plan(suite, [other], alt["choices"]).expected[other["id"]] is Plan(suite, [other], {}).expected[other["id"]]
    # Another vector object with the same id (not the one the set loaded) is worked out afresh.
    contact = next(v for v in suite.vectors if "result" in v["steps"][-1]["expect"])
    edited = copy.deepcopy(contact)
    edited["steps"][-1]["expect"]["result"] = not contact["steps"][-1]["expect"]["result"]
    assert Plan(suite, [contact], {}).expected[contact["id"]].results[-1] == contact["steps"][-1]["expect"]["result"]
    assert Plan(suite, [edited], {}).expected[edited["id"]].results[-1] == edited["steps"][-1]["expect"]["result"]
