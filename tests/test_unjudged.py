"""Devices an alternative leaves unjudged (schema 1.1, `alternatives[].unjudged`): under such an entry a
wrong value in one of them passes, a write outside the vector or to another listed device still
fails, the failure text names them, and the inference and `judged by:` count them as
verifiers/parity/TEXT.md says."""
from __future__ import annotations

import copy
import json

import pytest

from plcvec_verify import InProcess, Selection, Suite, run
from plcvec_verify.compare import compare
from plcvec_verify.describe import block
from plcvec_verify.errors import VerifyError
from plcvec_verify.expect import expected_of
from plcvec_verify.infer import judge_all
from plcvec_verify.reports import summary_text
from plcvec_verify.validate import vector_problem
from plcvec_reference.adapter import ReferenceAdapter

from conftest import REPO

D1_OUT = "HOUR-D1-OUT-OF-RANGE"
# D1 = 0:00:75 and half a second: no whole second is added. Under as-seconds D1 is written back as
# 0:01:15 (75 s); the hour word D200 stays 0 under every reading that judges it.
HALF = "fc6a-hour-meter/HOUR/measured-out-of-range/second=75/500ms"
UNJUDGED_LINE = f"    not judged under {D1_OUT}=undefined: D200, D201, D202, M10, M8004"


@pytest.fixture(scope="module")
def suite():
    return Suite.load(REPO / "vectors")


class Tampered(ReferenceAdapter):
    """The reference, with `change` written over every step's report of the vectors it names."""

    def __init__(self, change: dict, choices: dict | None = None, declare: bool = True):
        super().__init__(choices=choices)
        self.change, self.declare = change, declare

    def hello(self, request):
        answer = super().hello(request)
        if not self.declare:
            answer["interpretations"] = {}
        return answer

    def run(self, request):
        answer = super().run(request)
        for step in answer["steps"]:
            step["devices"].update(self.change.get(request["id"], {}))
        return answer


def _run(suite, change, choices=None, declare=True, ids=(HALF,)):
    return run(suite, InProcess(Tampered(change, choices, declare)), Selection(ids=ids))


def test_the_vector_carries_the_unjudged_map(suite):
    v = suite.by_id[HALF]
    entry = next(a for a in v["alternatives"] if a["choices"] == {D1_OUT: "undefined"})
    assert entry["unjudged"] == {D1_OUT: ["D200", "D201", "D202", "M10", "M8004"]}
    assert entry["expect"] == [{"devices": {}}] and entry["final"]["devices"] == {"D100": 1, "D101": 0, "D102": 0}
    for device in entry["unjudged"][D1_OUT]:
        assert device in v["initial"]["devices"] and device in v["final"]["devices"]


@pytest.mark.parametrize("device, value", [("D200", 7), ("D202", 75), ("M10", True), ("M8004", True)])
def test_a_wrong_value_of_an_unjudged_device_passes_under_undefined_and_fails_under_as_seconds(suite, device, value):
    change = {HALF: {device: value}}
    assert _run(suite, change, {D1_OUT: "undefined"}).exit_code == 0
    report = _run(suite, change)
    assert report.exit_code == 1 and [p.field for p in report.results[0].problems] == [device]


@pytest.mark.parametrize("device", ["D999", "D100", "D301"])
def test_a_stray_write_or_a_judged_device_still_fails_under_undefined(suite, device):
    """D999 is outside the vector, D100 is S1 (listed, judged); D301 is scratch, never compared."""
    report = _run(suite, {HALF: {"D200": 7, device: 9}}, {D1_OUT: "undefined"})
    problems = [(p.field, p.expected) for p in report.results[0].problems]
    if device == "D301":
        assert report.exit_code == 0 and problems == []
    else:
        assert report.exit_code == 1 and problems == [(device, "<not in the vector>" if device == "D999" else 1)]


def test_an_unjudged_device_may_go_unreported_but_must_be_a_device_value(suite):
    class Drops(ReferenceAdapter):
        def run(self, request):
            answer = super().run(request)
            for step in answer["steps"]:
                del step["devices"]["D201"]
                step["devices"]["D202"] = self.bad
            return answer

    for bad, status in ((True, "pass"), (70000, "error"), (-1, "error")):
        adapter = Drops(choices={D1_OUT: "undefined"})
        adapter.bad = bad
        report = run(suite, InProcess(adapter), Selection(ids=(HALF,)))
        assert report.results[0].status == status, bad
        if status == "error":
            assert "does not match result.schema.json" in report.results[0].message


def test_the_failure_block_names_the_unjudged_devices(suite):
    report = _run(suite, {HALF: {"D999": 1}}, {D1_OUT: "undefined"})
    text = summary_text(report)
    block_lines = text.split("\n\n")[0].splitlines()
    assert block_lines[:3] == [
        f"FAIL {HALF}",
        "    HOUR: D1 second = 75 (over 59) and one scan of 500 ms with the input on; the preset is 1:00:00.",
        UNJUDGED_LINE,
    ]
    assert block_lines[3] == "    step 0 inputs: input=true, elapsed_ms=500"
    assert "    step 0 D999: expected <not in the vector>, got 1" in block_lines


def test_the_line_is_in_every_block_of_such_a_vector_and_only_there(suite):
    defaults = {i: d["default"] for i, d in suite.interpretations().items()}
    followed = dict(defaults, **{D1_OUT: "undefined"})
    from plcvec_verify.runner import Verdict

    v = suite.by_id[HALF]
    for status in ("error", "skip", "not-run", "stale", "xfail"):
        r = Verdict(v["id"], v["family"], v["instruction"], status, message="why")
        assert block(r, v, followed, defaults, suite.expectations)[2] == UNJUDGED_LINE, status
        assert UNJUDGED_LINE not in block(r, v, defaults, defaults, suite.expectations)
    # After the judged-by line, which a field that under-judging decides brings in (below).
    report = _run(suite, {HALF: {"D999": 1}}, {D1_OUT: "undefined"})
    assert "judged by" not in summary_text(report)


def test_judged_by_names_the_interpretation_whose_other_alternative_leaves_the_field_unjudged(suite):
    """D200 of HALF is 0 under every reading that judges it; only `undefined` differs, by not judging it."""
    v = suite.by_id[HALF]
    values = {json.dumps(a["final"]["devices"].get("D200")) for a in v["alternatives"]} | {json.dumps(v["final"]["devices"]["D200"])}
    assert values == {"0", "null"}
    report = _run(suite, {HALF: {"D200": 7}})
    lines = summary_text(report).splitlines()
    assert lines[2] == f"    judged by: {D1_OUT}=as-seconds"


def _judged(suite, change, choices, declare):
    report = _run(suite, change, choices, declare, ids=("fc6a-hour-meter/HOUR/measured-out-of-range/*",))
    return report, {j.id: j for j in judge_all(report)}


def test_a_failing_answer_passes_only_where_its_wrong_devices_are_unjudged(suite):
    """An implementation that leaves D1 out of range as it is and writes 9 into the hour (no reading
    says that) is explained by `undefined` alone: the inference finds it."""
    from plcvec_verify.infer import inference

    out = [v["id"] for v in suite.vectors if v["id"].startswith("fc6a-hour-meter/HOUR/measured-out-of-range/")]
    report, judged = _judged(suite, {vid: {"D200": 9} for vid in out}, {D1_OUT: "undefined"}, declare=False)
    assert report.failed and len(out) >= 6
    for vid in out:
        index = judged[vid].touched.index(D1_OUT)
        assert {combo[index] for combo in judged[vid].passing} == {"undefined"}, vid
    found = inference(report)
    assert found.changes == {D1_OUT: "undefined"} and found.complete


def test_a_passing_answer_does_not_pass_where_the_followed_reading_leaves_devices_unjudged(suite):
    """Declared `undefined`, a passing answer is not known to pass under a reading that judges D1: its
    D1 was never looked at. Declared as-seconds, it passes under `undefined` too (every device that
    reading judges is expected alike), and under no other reading of HALF. (Another vector of the
    interpretation fails, so that the inference asks where HALF passes: see TEXT.md's shortcut.)"""
    stray = {"fc6a-hour-meter/HOUR/measured-out-of-range/minute=75/1000ms": {"D999": 1}}
    _, judged = _judged(suite, stray, {D1_OUT: "undefined"}, declare=True)
    j = judged[HALF]
    assert {c[j.touched.index(D1_OUT)] for c in j.passing} == {"undefined"}
    _, judged = _judged(suite, stray, None, declare=True)
    j = judged[HALF]
    assert {c[j.touched.index(D1_OUT)] for c in j.passing} == {"as-seconds", "undefined"}


def test_the_expectation_leaves_unjudged_devices_at_the_value_they_had_before(suite):
    v = suite.by_id[HALF]
    defaults = {i: d["default"] for i, d in suite.interpretations().items()}
    exp = expected_of(v, {D1_OUT: "undefined"}, defaults)
    assert exp.unjudged == {D1_OUT: ("D200", "D201", "D202", "M10", "M8004")}
    assert exp.states[0]["D202"] == 75 and "D202" not in exp.compared[0] and exp.left_out >= {"D200", "M8004"}
    answer = [{"devices": dict(exp.states[0], D202=12, D999=1)}]
    assert [p.field for p in compare(exp, answer)] == ["D999"]


@pytest.mark.parametrize("edit, message", [
    (lambda e: e["unjudged"].update({"HOUR-FIRST-SCAN": ["D200"]}), "HOUR-FIRST-SCAN is not one of the entry's choices"),
    (lambda e: e["unjudged"][D1_OUT].append("Q9"), "Q9 is not in initial/devices"),
    (lambda e: e["unjudged"][D1_OUT].reverse(), "the devices are not sorted"),
    (lambda e: e["final"]["devices"].update({"M10": False}), "at alternatives/3/final/devices/M10: M10 is unjudged under"),
    (lambda e: e["expect"][0]["devices"].update({"D202": 1}), "at alternatives/3/expect/0/devices/D202: D202 is unjudged"),
])
def test_a_vector_whose_unjudged_map_contradicts_it_is_refused(suite, edit, message):
    v = copy.deepcopy(suite.by_id[HALF])
    index = next(k for k, a in enumerate(v["alternatives"]) if "unjudged" in a)
    assert index == 3
    edit(v["alternatives"][index])
    assert message in vector_problem(v)
    assert vector_problem(suite.by_id[HALF]) == ""


def test_a_vector_file_edited_so_is_refused_on_loading(tmp_path, suite):
    data = json.loads((REPO / "vectors" / "fc6a-hour-meter.json").read_text())
    v = next(x for x in data["vectors"] if x["id"] == HALF)
    entry = next(a for a in v["alternatives"] if "unjudged" in a)
    entry["unjudged"][D1_OUT] = ["D200", "D900"]
    (tmp_path / "schema").mkdir()
    (tmp_path / "schema" / "vector-file.schema.json").write_text(
        (REPO / "vectors" / "schema" / "vector-file.schema.json").read_text())
    path = tmp_path / "fc6a-hour-meter.json"
    path.write_text(json.dumps(data))
    with pytest.raises(VerifyError, match=f"vector {HALF}: at alternatives/3/unjudged/{D1_OUT}: D900 is not in initial/devices"):
        Suite.load(path)
