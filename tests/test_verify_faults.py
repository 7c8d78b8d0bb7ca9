"""Adapter processes that misbehave: each fault is named with the vector being run, the other
vectors still get their verdicts, the reports keep everything, and nothing hangs.

tests/adapters/faulty.py answers correctly except on one target vector, and buffers its output
per batch as most real adapters do; the runner has to find the culprit itself.
"""
import json
import subprocess
import sys
import time
from pathlib import Path

import pytest

from plcvec_verify import Selection, StdioAdapter, Suite, VerifyError, run

from conftest import REPO

FAULTY = Path(__file__).parent / "adapters" / "faulty.py"
FAMILY = Selection(families=("fx5-time-add",))
TIMEOUT = 1.0


@pytest.fixture(scope="module")
def suite():
    return Suite.load(REPO / "vectors")


@pytest.fixture(scope="module")
def target(suite):
    """A vector in the middle of the third batch of 16, so that vectors before and after it are in flight."""
    return FAMILY.apply(suite.vectors)[37]["id"]


def faulty(mode, target, batch_size=16):
    return StdioAdapter([sys.executable, str(FAULTY), mode, target], timeout=TIMEOUT, batch_size=batch_size)


@pytest.mark.parametrize("mode, message", [
    ("crash", "the adapter was killed by SIGABRT"),
    ("hang", f"no answer within {TIMEOUT:g} s (timeout); the adapter was killed"),
    ("garbage", "the adapter wrote a line that is not JSON: 'Segmentation fault in module clock.c'"),
    ("unknown-id", "the adapter answered id 'no-such/vector', which was not sent"),
    ("exit-early", "the adapter exited with status 0 before answering"),
    ("wrong-shape", "the result does not match result.schema.json: at steps/0/devices/D100: 'twelve'"),
    ("duplicate", "answered {target} twice"),
])
def test_fault_is_blamed_on_the_vector_being_run(suite, target, mode, message):
    start = time.monotonic()
    report = run(suite, faulty(mode, target), FAMILY)
    elapsed = time.monotonic() - start
    bad = {r.id: r for r in report.results if r.status != "pass"}
    assert list(bad) == [target], {k: r.message for k, r in bad.items()}
    assert bad[target].status == "error"
    assert message.format(target=target) in bad[target].message
    if mode not in ("wrong-shape", "duplicate"):
        assert f"(while running {target})" in bad[target].message
    assert report.counts["pass"] == len(FAMILY.apply(suite.vectors)) - 1
    assert report.exit_code == 1 and not report.aborted
    # A hang costs one timeout to notice and one to pin on its vector; nothing waits longer.
    assert elapsed < 4 * TIMEOUT + 10


def test_stderr_is_kept_as_a_note_on_the_vector_not_a_failure(suite, target):
    report = run(suite, faulty("stderr", target, batch_size=1), FAMILY)
    assert report.exit_code == 0
    noted = [r for r in report.results if r.notes]
    text = "\n".join(n for r in noted for n in r.notes)
    assert f"warning: clock not set while running {target}" in text
    ids = [v["id"] for v in FAMILY.apply(suite.vectors)]
    # Written between the answers of the target's neighbours: pinned to within one vector.
    assert {r.id for r in noted} <= set(ids[ids.index(target):ids.index(target) + 2])


@pytest.mark.parametrize("mode, message", [
    ("bad-hello", "the handshake answer does not match hello-response.schema.json"),
    ("fatal-hello", "refused the handshake: this adapter needs a license key"),
])
def test_handshake_faults_stop_the_run_with_a_message(suite, mode, message):
    with pytest.raises(VerifyError, match=message):
        run(suite, faulty(mode, ""), FAMILY)


def test_an_adapter_that_crashes_on_everything_is_given_up_and_results_are_kept(suite, tmp_path):
    """Every vector crashes it: after the restart budget the run stops; the reports still get written."""
    jsonl = tmp_path / "r.jsonl"
    proc = subprocess.run([sys.executable, "-m", "plcvec", "verify", "--adapter",
                           f"{sys.executable} {FAULTY} crash-all x", "--family", "fx5-time-add",
                           "--max-restarts", "2", "--batch-size", "4", "--jsonl", str(jsonl)],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 2, proc.stdout + proc.stderr
    assert "gave up after 2 restarts" in proc.stderr and "Traceback" not in proc.stderr
    lines = [json.loads(x) for x in jsonl.read_text().splitlines()]
    statuses = [x["status"] for x in lines if x["type"] == "vector"]
    assert statuses.count("error") >= 1 and statuses.count("not-run") >= 1
    assert len(statuses) == len(FAMILY.apply(Suite.load(REPO / "vectors").vectors))
    assert lines[-1]["aborted"] and lines[-1]["exit_code"] == 2


def test_crash_mid_batch_via_cli_keeps_all_other_verdicts_in_the_reports(target, tmp_path):
    jsonl, junit = tmp_path / "r.jsonl", tmp_path / "r.xml"
    proc = subprocess.run([sys.executable, "-m", "plcvec", "verify", "--adapter",
                           f"{sys.executable} {FAULTY} crash {target}", "--family", "fx5-time-add",
                           "--batch-size", "16", "--jsonl", str(jsonl), "--junit", str(junit)],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 1
    assert f"ERROR {target}" in proc.stdout and "killed by SIGABRT" in proc.stdout
    lines = [json.loads(x) for x in jsonl.read_text().splitlines()]
    assert sum(x.get("status") == "pass" for x in lines) == len([x for x in lines if x["type"] == "vector"]) - 1
    assert "SIGABRT" in junit.read_text()


def test_a_fault_on_the_last_vector_leaves_the_adapter_usable(suite, target):
    """Callers that drive `answers` themselves (fuzz, shrinking) call again after a fault."""
    from plcvec_verify.expect import request_of

    adapter = faulty("crash", target)
    first = run(suite, adapter, Selection(ids=(target,)), keep_open=True)
    assert first.results[0].status == "error"
    other = next(v for v in FAMILY.apply(suite.vectors) if v["id"] != target)
    (answer,) = list(adapter.answers([request_of(other)]))
    assert answer.fault is None and answer.id == other["id"] and "steps" in answer.message
    adapter.close()
