"""Adapter processes that misbehave: each fault is named with the vector being run, the other
vectors still get their verdicts, the reports keep everything, and nothing hangs.

tests/adapters/faulty.py answers correctly except on one target vector, and buffers its output
per batch as most real adapters do; the runner has to find the culprit itself.
"""
import json
import os
import shlex
import signal
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
BOUND_S = 60     # no test here may take longer, whatever the runner does


@pytest.fixture(autouse=True)
def bounded():
    """Fail a test whose run hangs, rather than hang the suite: the runner's waits are under test."""
    def expired(signum, frame):
        raise TimeoutError(f"the test did not finish within {BOUND_S} s")
    previous = signal.signal(signal.SIGALRM, expired)
    signal.alarm(BOUND_S)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)


@pytest.fixture(scope="module")
def suite():
    return Suite.load(REPO / "vectors")


@pytest.fixture(scope="module")
def target(suite):
    """A vector in the middle of the third batch of 16, so that vectors before and after it are in flight."""
    return FAMILY.apply(suite.vectors)[37]["id"]


def faulty(mode, target, batch_size=16):
    return StdioAdapter([sys.executable, str(FAULTY), mode, target], timeout=TIMEOUT, batch_size=batch_size)


FAULTS = [
    ("crash", "the adapter was killed by SIGABRT"),
    ("hang", f"no answer within {TIMEOUT:g} s (timeout); the adapter was killed"),
    ("garbage", "the adapter wrote a line that is not JSON: 'Segmentation fault in module clock.c'"),
    ("unknown-id", "the adapter answered id 'no-such/vector', which was not sent"),
    ("no-id", "the adapter wrote a message with no vector id: "),
    ("exit-early", "the adapter exited with status 0 before answering"),
    ("close-stdout", "the adapter closed its stdout but kept running; it was killed"),
    ("wrong-shape", "the result does not match result.schema.json: at steps/0/devices/D100: 'twelve'"),
    ("duplicate", "answered {target} twice"),
    ("repeated-key", "the answer reports D"),
]


@pytest.mark.parametrize("mode, message", FAULTS, ids=[mode for mode, _ in FAULTS])
def test_fault_is_blamed_on_the_vector_being_run(suite, target, mode, message):
    start = time.monotonic()
    report = run(suite, faulty(mode, target), FAMILY)
    elapsed = time.monotonic() - start
    bad = {r.id: r for r in report.results if r.status != "pass"}
    assert list(bad) == [target], {k: r.message for k, r in bad.items()}
    assert bad[target].status == "error"
    assert message.format(target=target) in bad[target].message
    if mode not in ("wrong-shape", "duplicate", "repeated-key"):
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


HANDSHAKE_FAULTS = [
    ("bad-hello", "the handshake answer does not match hello-response.schema.json"),
    ("fatal-hello", "refused the handshake: this adapter needs a license key"),
    ("hang-hello", f"no handshake: no answer within {TIMEOUT:g} s"),
    ("garbage-hello", "the handshake answer is not JSON: 'Welcome to EmuPLC 2.1'"),
    ("two-hellos", "wrote 2 lines for the handshake, expected one"),
    ("new-protocol", "speaks protocol 2; this runner speaks 1"),
]


@pytest.mark.parametrize("mode, message", HANDSHAKE_FAULTS, ids=[mode for mode, _ in HANDSHAKE_FAULTS])
def test_handshake_faults_stop_the_run_with_a_message(suite, mode, message):
    start = time.monotonic()
    with pytest.raises(VerifyError) as e:
        run(suite, faulty(mode, ""), FAMILY)
    assert message in str(e.value)
    assert time.monotonic() - start < TIMEOUT + 10


def test_a_fatal_message_mid_run_stops_the_run_and_keeps_the_results(suite, target):
    """`fatal` means the adapter cannot go on (PROTOCOL.md): no restart, exit 2, verdicts kept."""
    report = run(suite, faulty("fatal-run", target), FAMILY)
    assert report.exit_code == 2
    assert f"the adapter gave up while running {target}: emulator licence expired" in report.aborted
    statuses = {r.id: r.status for r in report.results}
    ids = [v["id"] for v in FAMILY.apply(suite.vectors)]
    # Answered before the target: judged; from the target on: not run.
    assert {statuses[i] for i in ids[:ids.index(target)]} == {"pass"}
    assert {statuses[i] for i in ids[ids.index(target):]} == {"not-run"}


def test_an_adapter_that_ignores_bye_is_killed_after_the_grace(suite, monkeypatch):
    from plcvec_verify import stdio

    # The grace is read when `bye` is sent: a shorter one here is the same code path, sat out for less.
    monkeypatch.setattr(stdio, "EXIT_GRACE_S", 1.0)
    EXIT_GRACE_S = stdio.EXIT_GRACE_S
    start = time.monotonic()
    report = run(suite, faulty("ignore-bye", ""), Selection(ids=(FAMILY.apply(suite.vectors)[0]["id"],)))
    assert report.exit_code == 0
    assert f"adapter did not exit within {EXIT_GRACE_S:.0f} s of `bye`; killed" in report.notes
    assert time.monotonic() - start < EXIT_GRACE_S + 10


def test_an_adapter_that_crashes_on_everything_is_given_up_and_results_are_kept(suite, tmp_path):
    """Every vector crashes it: after the restart budget the run stops; the reports still get written."""
    jsonl = tmp_path / "r.jsonl"
    proc = subprocess.run([sys.executable, "-m", "plcvec", "verify", "--adapter",
                           shlex.join([sys.executable, str(FAULTY), "crash-all", "x"]), "--family", "fx5-time-add",
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
                           shlex.join([sys.executable, str(FAULTY), "crash", target]), "--family", "fx5-time-add",
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


def test_a_line_that_never_ends_is_a_fault_not_a_memory_leak(suite, target, monkeypatch):
    from plcvec_verify import stdio

    monkeypatch.setattr(stdio, "MAX_LINE_BYTES", 1 << 20)
    report = run(suite, faulty("endless-line", target), FAMILY)
    bad = {r.id: r for r in report.results if r.status != "pass"}
    assert list(bad) == [target], {k: r.message for k, r in bad.items()}
    assert "the adapter wrote a line longer than 1 MiB without a newline: 'xxxx" in bad[target].message
    assert f"(while running {target})" in bad[target].message


# -- the runner itself stopped -----------------------------------------------------------------

SPAWNER = Path(__file__).parent / "adapters" / "spawner.py"


def _alive(pid: int) -> bool:
    """Running (a zombie waiting to be reaped counts as ended)."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except (FileNotFoundError, ProcessLookupError):
        return False
    return stat.rsplit(")", 1)[1].split()[0] != "Z"


def _wait_for(predicate, seconds: float) -> bool:
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(0.05)
    return predicate()


def _spawned(pidfile: Path, seconds: float = 60):
    """The adapter's and its child's pids, once the spawner has written them."""
    assert _wait_for(lambda: pidfile.exists() and len(pidfile.read_text().split()) >= 2, seconds), \
        "the adapter did not start"
    return [int(x) for x in pidfile.read_text().split()[:2]]


def _reap(pids):
    """Leave nothing behind when a test fails half-way (only the processes this test started)."""
    for pid in pids:
        if _alive(pid):
            os.kill(pid, signal.SIGKILL)


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT], ids=lambda s: s.name)
def test_stopping_verify_ends_the_adapter_and_its_child_and_writes_the_reports(tmp_path, signum):
    pidfile, jsonl, junit = tmp_path / "pids", tmp_path / "r.jsonl", tmp_path / "r.xml"
    proc = subprocess.Popen([sys.executable, "-m", "plcvec", "verify", "--adapter",
                             shlex.join([sys.executable, str(SPAWNER), str(pidfile)]), "--family", "fx5-time-add",
                             "--timeout", "300", "--jsonl", str(jsonl), "--junit", str(junit)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    pids = []
    try:
        pids = _spawned(pidfile)
        assert _wait_for(lambda: "answered" in pidfile.read_text(), 60)
        assert all(_alive(p) for p in pids)
        proc.send_signal(signum)
        out, err = proc.communicate(timeout=30)
        # Ended by the runner, not by a timeout (300 s) nor by the end of its stdin.
        assert _wait_for(lambda: not any(_alive(p) for p in pids), 10), "an adapter process was left running"
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate(timeout=30)
        _reap(pids)
    assert proc.returncode == 128 + signum, err
    assert f"stopped by {signum.name}" in err and "Traceback" not in err
    lines = [json.loads(x) for x in jsonl.read_text().splitlines()]
    statuses = [x["status"] for x in lines if x["type"] == "vector"]
    assert len(statuses) == len(FAMILY.apply(Suite.load(REPO / "vectors").vectors))
    assert set(statuses) <= {"pass", "not-run"} and "not-run" in statuses
    assert lines[-1]["exit_code"] == 128 + signum and signum.name in lines[-1]["aborted"]
    assert junit.read_text().rstrip().endswith("</testsuites>")


def test_an_adapter_left_running_is_ended_when_the_interpreter_exits(tmp_path):
    """A library caller that never calls close(): atexit still ends the adapter and its child."""
    pidfile = tmp_path / "pids"
    script = (
        "import sys\n"
        "from plcvec_verify import StdioAdapter, Suite\n"
        "from plcvec_verify.protocol import hello_request\n"
        f"suite = Suite.load({str(REPO / 'vectors')!r})\n"
        f"adapter = StdioAdapter([sys.executable, {str(SPAWNER)!r}, {str(pidfile)!r}])\n"
        "adapter.hello(hello_request(suite, ['fx5-time-add']))\n"
        "sys.exit(0)\n")
    pids = []
    try:
        subprocess.run([sys.executable, "-c", script], timeout=60, check=True)
        pids = _spawned(pidfile, 1)
        assert _wait_for(lambda: not any(_alive(p) for p in pids), 10), "an adapter process was left running"
    finally:
        _reap(pids)


# SIGINT takes the same path through the plugin as SIGTERM (stopping.py turns both into Stopped);
# the default run stops it with SIGTERM, CI with both.
def _signals_at_their_defaults():
    """In the child, SIGINT and SIGTERM as a terminal's user has them. A test run started in the
    background by a shell (`cmd &`) inherits SIGINT ignored, and Python then leaves it ignored: Ctrl-C
    could not reach the pytest under test at all."""
    for s in (signal.SIGINT, signal.SIGTERM):
        signal.signal(s, signal.SIG_DFL)


@pytest.mark.parametrize("signum", [signal.SIGTERM, pytest.param(signal.SIGINT, marks=pytest.mark.slow)],
                         ids=lambda s: s.name)
def test_stopping_pytest_with_the_plugin_ends_the_adapter_and_its_child(tmp_path, signum):
    """pytest itself ends on SIGTERM without unwinding: the plugin turns it into an interrupt."""
    pidfile = tmp_path / "pids"
    proc = subprocess.Popen([sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-q",
                             "--plcvec-adapter", shlex.join([sys.executable, str(SPAWNER), str(pidfile)]),
                             "--plcvec-family", "fx5-time-add", "--plcvec-timeout", "300"],
                            cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            preexec_fn=_signals_at_their_defaults)
    pids = []
    try:
        pids = _spawned(pidfile)
        assert _wait_for(lambda: "answered" in pidfile.read_text(), 60)
        proc.send_signal(signum)
        try:
            out, _ = proc.communicate(timeout=30)
        except subprocess.TimeoutExpired:
            # pytest's faulthandler prints every thread's stack on SIGABRT: where the stop was lost.
            proc.send_signal(signal.SIGABRT)
            out, _ = proc.communicate(timeout=30)
            pytest.fail(f"pytest did not end within 30 s of {signum.name}; its stacks on SIGABRT:\n{out}")
        assert _wait_for(lambda: not any(_alive(p) for p in pids), 10), "an adapter process was left running"
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate(timeout=30)
        _reap(pids)
    assert proc.returncode == pytest.ExitCode.INTERRUPTED, out


def test_a_stop_signal_waits_for_the_end_of_a_section_that_must_not_be_cut():
    """Starting the adapter and recording it (or killing and reaping it) is never cut in half by
    SIGTERM: the signal is raised when the section ends, once."""
    from plcvec_verify.stopping import Stopped, deferred, stop_on_signals

    reached = []
    with pytest.raises(Stopped) as e:
        with stop_on_signals():
            with deferred():
                os.kill(os.getpid(), signal.SIGTERM)
                os.kill(os.getpid(), signal.SIGINT)      # ignored: one stop is enough
                time.sleep(0.1)
                reached.append("end of the section")
            reached.append("after the section")
    assert reached == ["end of the section"] and e.value.signum == signal.SIGTERM
    assert signal.getsignal(signal.SIGTERM) is signal.SIG_DFL      # the handlers are put back


def test_a_repeated_key_is_told_from_keys_spelled_otherwise():
    """The quick check (one `":` per key) only sends a line the slow way; the slow way decides."""
    from plcvec_verify.stdio import Repeated, StdioAdapter

    lines = [b'{"type":"result","id":"a","skip":"no \\": here"}',            # `":` inside a string
             b'{"type" : "result", "id" : "b", "steps" : [{"devices" : {"D1" : 1}}]}',   # spaces
             b'{"type":"result","id":"c","steps":[{"devices":{"D1":1,"D1":2}}]}',
             b'{"type":"result","id":"d","steps":[{"devices":{"D1":1}}]}']
    parsed = StdioAdapter._messages(None, lines)
    assert [type(m) for m in parsed] == [dict, dict, Repeated, dict]
    assert parsed[2].text == "the answer reports D1 twice (a JSON object with a repeated key)"
    assert parsed[0]["skip"] == 'no ": here' and parsed[1]["steps"][0]["devices"] == {"D1": 1}
