"""`plcvec bench --baseline REV`: the revision is exported and measured with its own code; a revision
that does not exist is a usage error, not a traceback. (Speed itself is shown by the figures the
benchmark prints, not by a timed test.)"""
import json
import subprocess
import sys
from pathlib import Path

from plcvec.bench import Tree, export_revision, golden_in_process
from plcvec.output.workers import usable_cores

from conftest import REPO


def test_an_unknown_revision_exits_2_naming_it():
    proc = subprocess.run([sys.executable, "-m", "plcvec", "bench", "--baseline", "no-such-revision", "--no-verify"],
                          capture_output=True, text=True, cwd=REPO, timeout=120)
    assert proc.returncode == 2
    assert "'no-such-revision' is not a commit" in proc.stderr and "Traceback" not in proc.stderr


def test_the_baseline_is_measured_with_its_own_code(tmp_path, monkeypatch):
    monkeypatch.chdir(REPO)
    head = subprocess.run(["git", "rev-parse", "HEAD"], capture_output=True, text=True, timeout=60).stdout.strip()
    assert export_revision("HEAD", tmp_path / "head") == head
    tree = Tree("HEAD", tmp_path / "head")
    _, _, _, out = tree.child(["-c", "import plcvec, plcvec_verify; print(plcvec.__file__); print(plcvec_verify.__file__)"],
                              "an import")
    for path in out.split():
        assert Path(path).is_relative_to(tree.root), path
    rows = golden_in_process(tree, tmp_path, processes=1)
    assert [row[0] for row in rows] == ["golden set, in process, 1 process"] + (
        [f"golden set, in process, {usable_cores()} processes"] if usable_cores() > 1 else [])
    for label, vectors, seconds, cpu, rss in rows:
        assert vectors == json.loads((tree.root / "vectors" / "manifest.json").read_text())["total"]
        assert seconds > 0 and cpu > 0 and rss is None
