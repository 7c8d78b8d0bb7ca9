"""`plcvec verify --infer` and the roll-up by reading: the alternatives an implementation follows,
found from its answers alone (infer.py; verifiers/parity/TEXT.md, "The inference")."""
from __future__ import annotations

import subprocess
import sys

import pytest

from plcvec_verify.adapters import InProcess
from plcvec_verify.infer import Judged, infer, inference
from plcvec_verify.reports import summary_text
from plcvec_verify.runner import run
from plcvec_verify.suite import Selection, Suite
from plcvec_reference.adapter import ReferenceAdapter

from adapters.undeclared import Undeclared
from conftest import REPO

# Alternatives the golden set tells apart from the defaults (each changes vectors of its own).
FOLLOWED = {"TADD-FLAGS-OFF": "set-only", "CP1E-NON-BCD": "raw-bytes", "HOUR-INPUT-OFF": "reset"}


@pytest.fixture(scope="module")
def suite():
    return Suite.load(REPO / "vectors")


def test_the_alternatives_an_implementation_follows_without_declaring_them_are_found(suite):
    report = run(suite, InProcess(Undeclared(",".join(f"{i}={a}" for i, a in FOLLOWED.items()))))
    assert report.failed, "judged by the defaults, the undeclared alternatives must fail somewhere"
    found = inference(report)
    assert found.changes == dict(sorted(FOLLOWED.items()))
    assert found.complete and not found.unexplained and not found.broken
    assert set(found.explained) == {r.id for r in report.failed}
    # Each failure is explained by the one interpretation whose alternative it needs.
    assert {change for change in found.explained.values()} == {((i, a),) for i, a in FOLLOWED.items()}
    text = summary_text(report)
    assert f"READINGS: {len(report.failed)} of {len(report.failed)} failing vectors pass under other alternatives:" in text
    assert "    declare: " + " ".join(f"--choose {i}={a}" for i, a in sorted(FOLLOWED.items())) + "\n" in text
    assert "NOT EXPLAINED" not in text


def test_every_last_alternative_at_once_is_explained_by_one_choice(suite):
    """The reference following the last alternative of every interpretation (vectors that touch several
    need them together): one choice explains every vector, and that choice declared passes the run."""
    last = {i: d["alternatives"][-1] for i, d in suite.interpretations().items()}
    report = run(suite, InProcess(Undeclared(",".join(f"{i}={a}" for i, a in last.items()))))
    found = inference(report)
    assert found.complete, (found.unexplained[:5], found.broken[:5])
    declared = run(suite, InProcess(ReferenceAdapter(choices=found.choice)))
    assert declared.exit_code == 0 and not declared.failed


def test_a_mutant_is_not_explained_and_its_failures_are_grouped_by_clause(suite):
    report = run(suite, InProcess(ReferenceAdapter(mutant="fx5-le-as-lt")), Selection(families=("fx5-time-compare",)))
    found = inference(report)
    assert report.failed and not found.complete
    assert set(found.unexplained) == {r.id for r in report.failed}
    text = summary_text(report)
    assert f"NOT EXPLAINED by any reading: {len(report.failed)} failing vectors, by the clauses they cite:" in text
    assert "READINGS:" not in text


def test_verify_infer_exit_status_and_lines(tmp_path):
    def verify(*args, follow=""):
        env = {**__import__("os").environ, "PLCVEC_TEST_FOLLOW": follow,
               "PYTHONPATH": f"{REPO / 'tests'}:{REPO / 'generator'}:{REPO / 'verifiers' / 'python'}"}
        proc = subprocess.run([sys.executable, "-m", "plcvec", "verify", "--infer", "--family", "fx5-time-add",
                               "--family", "fc6a-hour-meter", *args], capture_output=True, text=True, env=env,
                              cwd=tmp_path, timeout=300)
        return proc.returncode, proc.stdout + proc.stderr

    rc, out = verify("--python", "adapters.undeclared:Undeclared", follow="TADD-FLAGS-OFF=set-only,HOUR-INPUT-OFF=reset")
    assert rc == 0, out
    assert "    TADD-FLAGS-OFF=set-only (inferred; followed written-each-execution)\n" in out
    assert "    HOUR-INPUT-OFF=reset (inferred; followed hold)\n" in out
    choose = next(line for line in out.splitlines() if line.startswith("choose: ")).split()
    assert "HOUR-INPUT-OFF=reset" in choose and "TADD-FLAGS-OFF=set-only" in choose and choose.count("--choose") > 2
    assert '"HOUR-INPUT-OFF": "reset"' in out and "one choice of alternatives explains every vector" in out
    assert "\nFAIL " not in out, "a failure a reading explains gets no block under --infer"
    rc, out = verify("--adapter", f"{sys.executable} -m plcvec_reference.adapter --mutant tadd-no-wrap-at-24")
    assert rc == 1, out
    assert "no one choice of alternatives explains every vector" in out and "\nFAIL fx5-time-add/" in out


def _j(vid, touched, passing, failed=True):
    return Judged(vid, touched, frozenset(passing), failed)


def test_infer_moves_one_interpretation_at_a_time_and_keeps_the_current_one_on_a_tie():
    alternatives = {"A": ["a0", "a1"], "B": ["b0", "b1", "b2"]}
    followed = {"A": "a0", "B": "b0"}
    judged = [
        _j("1", ("A",), {("a1",)}),                      # needs A=a1
        _j("2", ("A", "B"), {("a1", "b2")}),             # needs both: B can move once A has
        _j("3", ("B",), {("b2",), ("b0",)}, False),      # passes now, and under b2
        _j("4", ("B",), {("b1",), ("b2",)}),
    ]
    # A first (id order): a1 explains vector 1. Then B: b0 explains 3, b1 explains 4, b2 explains 2, 3, 4.
    assert infer(judged, alternatives, followed) == {"A": "a1", "B": "b2"}
    # Two alternatives that explain as much: the first in file order; none better than now: no change.
    assert infer([_j("4", ("B",), {("b1",), ("b2",)})], alternatives, followed) == {"A": "a0", "B": "b1"}
    assert infer([_j("5", ("A",), {("a0",), ("a1",)}, False)], alternatives, followed) == followed
    # A move that would turn a pass into a failure for one explained failure is no gain: kept.
    judged = [_j("6", ("A",), {("a1",)}), _j("7", ("A",), {("a0",)}, False)]
    assert infer(judged, alternatives, followed) == followed


def test_a_reading_that_judges_is_preferred_to_one_that_leaves_devices_unjudged(monkeypatch):
    """An undeclared HOUR-FIRST-SCAN=after-cpu-start reader: its failures also pass under the `undefined`
    alternatives (they judge nothing of D1, D2, M8004), whose ids come first. The search tries the
    readings that judge first, so the choice is after-cpu-start alone (TEXT.md, "The inference")."""
    suite = Suite.load(REPO / "vectors")
    report = run(suite, InProcess(Undeclared("HOUR-FIRST-SCAN=after-cpu-start")),
                 Selection(families=("fc6a-hour-meter",)))
    assert report.counts["fail"] > 0
    found = inference(report)
    assert found.changes == {"HOUR-FIRST-SCAN": "after-cpu-start"}
    assert not found.unexplained and not found.broken
