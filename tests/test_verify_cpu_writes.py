"""Devices an implementation's CPU writes on its own account (CONTRACT.md, "Comparing"): a write to a
declared device outside the vector is not stray; a declared device the vector lists is compared."""
from __future__ import annotations

import json
import sys

import pytest

from plcvec_verify import reports
from plcvec_verify.adapters import InProcess
from plcvec_verify.errors import VerifyError
from plcvec_verify.runner import run
from plcvec_verify.stdio import StdioAdapter
from plcvec_verify.suite import Suite
from plcvec_reference.adapter import ReferenceAdapter

from conftest import REPO


class Diagnostics(ReferenceAdapter):
    """The reference, also setting diagnostic devices after every step, as a real CPU's error logic would."""

    def __init__(self, writes: dict, declared=None):
        super().__init__()
        self.writes = writes
        if declared is not None:
            self.cpu_writes = declared

    def run(self, request):
        answer = super().run(request)
        for step in answer["steps"]:
            step["devices"].update(self.writes)
        return answer


@pytest.fixture(scope="module")
def suite():
    return Suite.load(REPO / "vectors")


def test_a_declared_device_outside_the_vector_is_not_a_stray_write(suite):
    report = run(suite, InProcess(Diagnostics({"SM0": True}, declared=["SM0"])))
    assert not any("SM0" in v["initial"]["devices"] for v in suite.vectors)
    assert report.exit_code == 0 and report.counts["pass"] == len(suite.vectors)
    assert report.cpu_writes == ("SM0",)
    undeclared = run(suite, InProcess(Diagnostics({"SM0": True})))
    assert undeclared.counts["fail"] == len(suite.vectors)
    assert undeclared.failed[0].problems[0].line() == "step 0 SM0: expected <not in the vector>, got true"


def test_a_declared_device_the_vector_lists_is_compared(suite):
    report = run(suite, InProcess(Diagnostics({"SM0": True, "SD0": 1}, declared=["SD0", "SM0"])))
    listing = {v["id"] for v in suite.vectors if "SD0" in v["initial"]["devices"]}
    assert listing, "the TADD vectors list SD0 (the error code)"
    assert {r.id for r in report.failed} == listing
    assert all({p.field for p in r.problems} == {"SD0"} for r in report.failed)


def test_reports_list_the_declared_devices(suite, tmp_path):
    report = run(suite, InProcess(Diagnostics({"SM0": True}, declared=["SM0", "SD0"])))
    assert "\ncpu_writes: SD0, SM0\n" in reports.summary_text(report)
    reports.write_jsonl(report, tmp_path / "r.jsonl")
    head = json.loads((tmp_path / "r.jsonl").read_text().splitlines()[0])
    assert head["cpu_writes"] == ["SD0", "SM0"]
    assert 'name="cpu_writes" value="SD0, SM0"' in reports.junit_xml(report)
    assert "cpu_writes" not in reports.summary_text(run(suite, InProcess(ReferenceAdapter())))


def test_the_hello_response_carries_cpu_writes_and_a_wrong_one_is_refused(suite, tmp_path):
    script = tmp_path / "adapter.py"
    script.write_text(
        "import json, sys\n"
        "from plcvec_reference.adapter import ReferenceAdapter\n"
        "from plcvec_verify.serve import serve\n"
        "class A(ReferenceAdapter):\n"
        "    def hello(self, request):\n"
        "        answer = super().hello(request)\n"
        "        answer['cpu_writes'] = json.loads(sys.argv[1])\n"
        "        return answer\n"
        "    def run(self, request):\n"
        "        answer = super().run(request)\n"
        "        for step in answer['steps']: step['devices']['SM0'] = True\n"
        "        return answer\n"
        "sys.exit(serve(A()))\n")
    good = StdioAdapter([sys.executable, str(script), '["SM0"]'], timeout=30)
    report = run(suite, good)
    assert report.exit_code == 0 and report.cpu_writes == ("SM0",)
    with pytest.raises(VerifyError, match="hello-response.schema.json"):
        run(suite, StdioAdapter([sys.executable, str(script), '"SM0"'], timeout=30))
