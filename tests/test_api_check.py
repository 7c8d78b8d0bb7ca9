"""The Python runner's API check (.ci/api/python.py): it passes on this tree, whose breaking changes
since the previous release CHANGES.md lists, and fails on a deliberate rename it does not."""
import shutil
import subprocess
import sys

import pytest

from conftest import REPO

pytest.importorskip("griffe")
CHECK = REPO / ".ci" / "api" / "python.py"


def check(*args):
    return subprocess.run([sys.executable, str(CHECK), *args], capture_output=True, text=True, timeout=600, cwd=REPO)


def test_this_tree_passes_its_api_check():
    proc = check()
    if proc.returncode == 2:
        pytest.skip(proc.stderr.strip())     # a shallow clone without the previous release
    assert proc.returncode == 0, proc.stderr
    assert "breaking changes" in proc.stdout


def test_a_deliberate_rename_fails_it(tmp_path):
    copy = tmp_path / "python"
    shutil.copytree(REPO / "verifiers" / "python", copy, ignore=shutil.ignore_patterns("__pycache__"))
    suite = copy / "plcvec_verify" / "suite.py"
    text = suite.read_text(encoding="utf-8")
    assert "def shard_of(" in text
    suite.write_text(text.replace("def shard_of(", "def shard_number("), encoding="utf-8")
    proc = check("--new", str(copy))
    if proc.returncode == 2:
        pytest.skip(proc.stderr.strip())
    assert proc.returncode == 1
    assert "plcvec_verify.suite.shard_of" in proc.stderr
