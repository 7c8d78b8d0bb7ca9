"""CI's lane runner (.ci/lanes.py): lanes side by side, a lane more while the cores sit idle, every
lane's status in the exit code, and no lane outliving its bound; the lanes' step lines (.ci/steps.sh)."""
import re
import runpy
import shlex
import subprocess
import sys
import time
from types import SimpleNamespace

import pytest

from conftest import REPO

lanes = SimpleNamespace(**runpy.run_path(str(REPO / ".ci" / "lanes.py"), run_name="ci_lanes"))


class Meter:
    """An IdleMeter that reports what the test sets."""

    def __init__(self, cores, seconds):
        self.cores, self.seconds, self.resets = cores, seconds, 0

    def idle_cores(self):
        return self.cores, self.seconds

    def reset(self):
        self.resets += 1


def args(jobs, fill):
    return SimpleNamespace(jobs=jobs, fill=fill)


def test_a_lane_more_only_after_a_whole_idle_window():
    window, idle = lanes.FILL_WINDOW_S, lanes.FILL_IDLE_CORES
    assert lanes._may_fill(Meter(idle, window), 2, args(2, 1))
    assert not lanes._may_fill(Meter(idle, window - 1), 2, args(2, 1)), "a window not yet whole"
    assert not lanes._may_fill(Meter(idle, window), 3, args(2, 1)), "--fill lanes already running"
    assert not lanes._may_fill(Meter(idle, window), 2, args(2, 0)), "no filling without --fill"
    busy = Meter(idle - 0.1, window)
    assert not lanes._may_fill(busy, 2, args(2, 1)) and busy.resets == 1, "a busy window starts a new one"


def _script(tmp_path, name, body):
    path = tmp_path / f"{name}.sh"
    path.write_text(f"#!/bin/bash\n{body}\n")
    return str(path)


def test_idle_cores_start_a_lane_more_and_every_status_is_reported(tmp_path, monkeypatch, capsys):
    monkeypatch.setitem(lanes.main.__globals__, "LOGS", tmp_path / "logs")
    monkeypatch.setitem(lanes.main.__globals__, "FILL_WINDOW_S", 0.5)
    monkeypatch.setitem(lanes.main.__globals__, "FILL_IDLE_CORES", 0.0)
    scripts = [_script(tmp_path, "one", "sleep 2"), _script(tmp_path, "two", "sleep 2"),
               _script(tmp_path, "three", "exit 3")]
    started = time.monotonic()
    assert lanes.main(["--jobs", "1", "--fill", "1", *scripts]) == 1   # a failed lane fails the run
    out = capsys.readouterr().out
    assert "-- lane two: started (cores idle)" in out
    assert time.monotonic() - started < 3.8, "the second lane waited for the first instead of filling"
    assert "three        failed (exit 3)" in out and "one          ok" in out


def test_a_lane_past_its_bound_is_killed(tmp_path, monkeypatch, capsys):
    monkeypatch.setitem(lanes.main.__globals__, "LOGS", tmp_path / "logs")
    started = time.monotonic()
    assert lanes.main(["--timeout", "1", _script(tmp_path, "hangs", "sleep 60")]) == 1
    assert time.monotonic() - started < 10
    assert "killed after 1 s" in capsys.readouterr().out


def test_sigterm_ends_every_running_lane_with_its_children(tmp_path):
    """CI ended from outside (SIGTERM to lanes.py): each lane runs in a session of its own, so
    nothing else would end it; lanes.py ends the lanes' process groups, their children too."""
    pids = tmp_path / "pids"
    lane = _script(tmp_path, "sleeps", f"sleep 60 & echo $! >> {pids}; echo $$ >> {pids}; wait")
    proc = subprocess.Popen([sys.executable, str(REPO / ".ci" / "lanes.py"), lane], stdout=subprocess.DEVNULL)
    deadline = time.monotonic() + 20
    while (not pids.exists() or len(pids.read_text().split()) < 2) and time.monotonic() < deadline:
        time.sleep(0.1)
    proc.terminate()
    assert proc.wait(timeout=20) == 130
    for pid in map(int, pids.read_text().split()):
        deadline = time.monotonic() + 10
        while _alive(pid) and time.monotonic() < deadline:
            time.sleep(0.1)
        assert not _alive(pid), f"process {pid} of the lane outlived lanes.py"


def _alive(pid):
    """Whether PID runs (a zombie, ended but not yet reaped by init, counts as ended)."""
    try:
        with open(f"/proc/{pid}/stat", encoding="ascii") as stat:
            return stat.read().rsplit(")", 1)[1].split()[0] != "Z"
    except FileNotFoundError:
        return False


def test_a_step_in_a_subshell_counts_the_cpu_of_what_ran_before_it(tmp_path):
    """.ci/steps.sh's step lines: the CPU seconds of what the lane ran so far, also inside a subshell
    ( ... ), whose children reach the lane's shell only when it ends (the TypeScript lane's first
    steps read 0.0 so). A child burns 0.4 s of CPU, by its own clock, before steps c and d (read to
    a tenth)."""
    burn = shlex.join([sys.executable, "-c",
                       "import time\nt = time.process_time()\nwhile time.process_time() - t < 0.4: pass"])
    script = tmp_path / "lane.sh"
    script.write_text(f"source {shlex.quote(str(REPO / '.ci' / 'steps.sh'))}\nsteps_begin t\nstep a\n"
                      f"( step b\n{burn}\nstep c )\nstep d\n")
    out = subprocess.run(["bash", str(script)], capture_output=True, text=True, check=True).stdout
    cpu = dict(re.findall(r"^-- t: (\w) \(\d+ s, ([\d.]+) CPU s\)$", out, re.M))
    assert set(cpu) == {"a", "b", "c", "d"}, out
    assert float(cpu["a"]) < 0.2 and float(cpu["b"]) < 0.2, out
    assert float(cpu["c"]) >= 0.3 and float(cpu["d"]) >= 0.3, out


def _ended_lane(tmp_path, name, log, seconds, cpu):
    lane = lanes.Lane(f".ci/{name}.sh")
    lane.log = tmp_path / f"{name}.log"
    lane.log.write_text(log)
    lane.seconds, lane.cpu, lane.status = seconds, cpu, "ok"
    return lane


def test_each_step_costs_what_its_lane_ran_until_the_next_step(tmp_path, capsys):
    # Three step lines as steps.sh prints them (a text with parentheses of its own, output between
    # them), the lane ending at 60 s and 50.0 CPU s; and a lane with no step line.
    log = ("-- demo: fetch (0 s, 0.2 CPU s)\nsome output (1 s, 2.0 CPU s)\n"
           "-- demo: cargo test (one test per vector) (4 s, 3.5 CPU s)\n"
           "-- demo: done (52 s, 47.5 CPU s)\n")
    demo = _ended_lane(tmp_path, "demo", log, 60.0, 50.0)
    plain = _ended_lane(tmp_path, "plain-lane", "202 passed\n", 95.0, 151.0)
    assert lanes.steps_of(demo) == [(pytest.approx(3.3), 4, "demo: fetch"),
                                    (pytest.approx(44.0), 48, "demo: cargo test (one test per vector)"),
                                    (pytest.approx(2.5), 8, "demo: done")]
    assert lanes.steps_of(plain) == [(151.0, 95.0, "plain: the whole lane (it marks no steps)")]
    lanes.print_steps([demo, plain])
    out = capsys.readouterr().out.splitlines()
    assert out[0].startswith("lanes: the 4 steps that took the most CPU, of 4")
    assert [line.split("  ")[-1] for line in out[1:]] == [
        "plain: the whole lane (it marks no steps)", "demo: cargo test (one test per vector)", "demo: fetch", "demo: done"]
