"""CI's lane runner (.ci/lanes.py): lanes side by side, a lane more while the cores sit idle, every
lane's status in the exit code, and no lane outliving its bound; the lanes' step lines (.ci/steps.sh)."""
import os
import re
import runpy
import shlex
import subprocess
import sys
import time
from pathlib import Path
from types import SimpleNamespace

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


def test_a_head_start_runs_the_first_lane_alone_until_the_file_exists(tmp_path, monkeypatch, capsys):
    """--head-start FILE: the first lane starts at once, the others not before FILE exists, though
    --jobs would allow them (the first lane itself makes the file here, a second after it started)."""
    monkeypatch.setitem(lanes.main.__globals__, "LOGS", tmp_path / "logs")
    gate, made, second = tmp_path / "gate", tmp_path / "made", tmp_path / "second"
    held, freed = tmp_path / "held", tmp_path / "freed"
    niceness = "echo $(ps -o ni= -p $$) $(cat /proc/$$/autogroup 2>/dev/null)"
    first = _script(tmp_path, "first", f"sleep 1; {niceness} > {held}; date +%s.%N > {made}; touch {gate}; "
                                       f"sleep 1.5; {niceness} > {freed}")
    other = _script(tmp_path, "other", f"date +%s.%N > {second}")
    assert lanes.main(["--jobs", "2", "--head-start", str(gate), first, other]) == 0
    assert float(second.read_text()) >= float(made.read_text()), "the second lane did not wait for the file"
    # The lowest priority while held, the session's too where the kernel groups sessions; the usual
    # one once the file exists, where the test has the privilege to raise it back (root, as in CI).
    autogroup = Path("/proc/self/autogroup").exists()
    assert held.read_text().split()[0] == "19" and (not autogroup or "nice 19" in held.read_text())
    if os.geteuid() == 0:
        assert freed.read_text().split()[0] == "0" and (not autogroup or "nice 0" in freed.read_text())
    out = capsys.readouterr().out
    assert "-- lanes: the others start" in out and "once the others started)" in out


def test_a_lane_past_its_bound_is_killed(tmp_path, monkeypatch, capsys):
    monkeypatch.setitem(lanes.main.__globals__, "LOGS", tmp_path / "logs")
    started = time.monotonic()
    assert lanes.main(["--timeout", "1", _script(tmp_path, "hangs", "sleep 60")]) == 1
    assert time.monotonic() - started < 10
    assert "killed after 1 s" in capsys.readouterr().out


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
