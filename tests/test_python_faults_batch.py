"""The Python rows of the table of faults in one call (`verifiers/python/faults-entry --batch`): each
row gives the exit status and the output it gives when run alone, and a row that hangs is stopped at
its bound with everything in its process group."""
import os
import re
import runpy
import subprocess
import sys
import time
from types import SimpleNamespace

import pytest

from conftest import REPO

# A pass, a fail, usage errors of the environment, of a damaged file and of a known-failures file, the
# row pytest runs, and an implementation that leaves a child holding its standard output.
# With the statuses the contract gives their verdicts, exactly (Python is in run.py's EXACT). The default
# run takes the first three (a pass, a fail, a usage error); CI's slow lane takes all seven.
ROWS = {"reference": 0, "crash": 1, "unknown-family": 2, "damage-not-json": 2, "runner-filter-matches-nothing": 5,
        "known-failures-syntax": 2, "child-holds-stdout": 0}
FIRST = 3


# The two scripts, loaded as their own namespaces (neither is in a package).
parity = SimpleNamespace(**runpy.run_path(str(REPO / "verifiers" / "parity" / "run.py"), run_name="parity_run_batch"))
batch = SimpleNamespace(**runpy.run_path(str(REPO / "verifiers" / "python" / "faults_batch.py"), run_name="python_faults_batch"))


def _steady(text: str) -> str:
    """The output without what differs from one run to the next: the seconds a run took."""
    return re.sub(r"\d+(\.\d+)? ?s\b", "<s>", text)


def test_the_rows_named_here_are_in_the_table():
    table = {r.id for r in parity.load_table()}
    assert not [r for r in ROWS if r not in table], "rows this test names are no longer in faults.toml"


@pytest.mark.parametrize("names", [pytest.param(list(ROWS)[:FIRST], id="first"),
                                   pytest.param(list(ROWS), id="all", marks=pytest.mark.slow)])
def test_each_row_gives_in_the_batch_what_it_gives_alone(tmp_path, names):
    folders = parity.Folders(tmp_path / "vectors")
    table = {r.id: r for r in parity.load_table()}
    rows = [table[r] for r in names]
    together = parity.run_batch("python", rows, folders, tmp_path / "batch", 120)
    for row, joint in zip(rows, together):
        alone = parity.run_row("python", row, folders, tmp_path / "batch", 120)
        assert (joint.status, _steady(joint.output)) == (alone.status, _steady(alone.output)), row.id
        assert joint.ok, f"{row.id}: {joint.why}\n{joint.output}"
    assert [o.status for o in together] == [ROWS[r] for r in names]


def test_a_row_that_hangs_is_stopped_at_its_bound():
    """A row's process still running at its bound is killed with its group, and reported as a hang."""
    pid = os.fork()
    if pid == 0:
        os.setsid()
        subprocess.Popen(["sleep", "60"])   # a child in the row's group: ended with it
        time.sleep(60)
        os._exit(0)
    started = time.monotonic()
    assert batch.wait_bounded(pid, 0.5) is None
    assert time.monotonic() - started < 10
    assert not _group_alive(pid, 5), "a process of the row's group is left"


def _group_alive(pgid, within):
    """Whether the group still has a process after `within` seconds (a killed one is reaped by init)."""
    deadline = time.monotonic() + within
    while time.monotonic() < deadline:
        try:
            os.killpg(pgid, 0)
        except ProcessLookupError:
            return False
        time.sleep(0.05)
    return True


def test_the_interpreters_exit_status_for_sys_exit(capsys):
    assert [batch.exit_status(c) for c in (None, 0, 5, 256 + 2)] == [0, 0, 5, 2]
    assert batch.exit_status("plcvec: no such thing") == 1
    assert capsys.readouterr().err == "plcvec: no such thing\n"
