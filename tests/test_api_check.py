"""The Python runner's API check (.ci/api/python.py): it passes on this tree, whose breaking changes
since the previous release CHANGES.md lists, and fails on a deliberate rename it does not."""
import re
import shutil
import subprocess
import sys

import pytest

from conftest import REPO

pytest.importorskip("griffe")
CHECK = REPO / ".ci" / "api" / "python.py"


def check(*args):
    proc = subprocess.run([sys.executable, str(CHECK), *args], capture_output=True, text=True, timeout=600, cwd=REPO)
    if proc.returncode == 2:
        # Skipped only where the previous release is not in the history (a shallow clone); any other
        # reason the check could not run is a failure.
        commit = re.search(r"^PREVIOUS = \(.*, \"([0-9a-f]+)\"\)", CHECK.read_text(encoding="utf-8"), re.M).group(1)
        there = subprocess.run(["git", "cat-file", "-e", f"{commit}^{{commit}}"], cwd=REPO, capture_output=True)
        if there.returncode == 0:
            pytest.fail(f"the API check could not run although {commit} is in the history: {proc.stderr}")
        pytest.skip(proc.stderr.strip())
    return proc


def test_this_tree_passes_its_api_check():
    proc = check()
    assert proc.returncode == 0, proc.stderr
    assert "breaking changes" in proc.stdout


@pytest.mark.parametrize("module, name, new_name, named", [
    # A name defined where 0.1.0 had it: griffe's own comparison.
    ("adapters.py", "load_python_adapter", "load_adapter", "plcvec_verify.adapters.load_python_adapter"),
    # A name 0.1.0 had in suite.py, moved to selection.py and imported back: the old home now imports
    # a name that is gone, which griffe's comparison does not follow (the check's dangling re-exports).
    ("selection.py", "shard_of", "shard_number", "plcvec_verify.suite.shard_of"),
], ids=["defined-in-place", "moved-and-re-exported"])
def test_a_deliberate_rename_fails_it(tmp_path, module, name, new_name, named):
    copy = tmp_path / "python"
    shutil.copytree(REPO / "verifiers" / "python", copy, ignore=shutil.ignore_patterns("__pycache__"))
    path = copy / "plcvec_verify" / module
    text = path.read_text(encoding="utf-8")
    assert f"def {name}(" in text
    path.write_text(text.replace(f"def {name}(", f"def {new_name}("), encoding="utf-8")
    proc = check("--new", str(copy))
    assert proc.returncode == 1
    assert f"{named}: " in proc.stderr, proc.stderr
