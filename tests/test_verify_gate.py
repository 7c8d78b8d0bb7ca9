"""The CI gate cannot be passed by accident: reports anyone can read, names that exist, a selection
that is not empty, an implementation that does more than skip.
"""
import os
import stat
import sys

import pytest

from plcvec_verify.command import main as verify_main

from conftest import REPO

REFERENCE = ["--python", "plcvec_reference.adapter:ReferenceAdapter"]
FAULTY = REPO / "tests" / "adapters" / "faulty.py"


@pytest.mark.parametrize("umask", [0o022, 0o002, 0o077], ids=oct)
def test_reports_are_written_with_the_umask_like_any_other_file(tmp_path, umask):
    """A report made 0600 cannot be read by a CI uploader running as another user."""
    # wrong-shape on one vector: a failing run, so --write-expectations has something to write.
    vid = "fx5-time-add/TADD/manual-example/program"
    adapter = f"{sys.executable} {FAULTY} wrong-shape {vid}"
    files = [tmp_path / "r.jsonl", tmp_path / "r.xml", tmp_path / "known.toml"]
    old = os.umask(umask)
    try:
        rc = verify_main(["--adapter", adapter, "--family", "fx5-time-add", "-q", "--no-progress",
                          "--jsonl", str(files[0]), "--junit", str(files[1]), "--write-expectations", str(files[2])])
    finally:
        os.umask(old)
    assert rc == 1
    want = 0o666 & ~umask
    assert {f.name: oct(stat.S_IMODE(f.stat().st_mode)) for f in files} == {f.name: oct(want) for f in files}
    assert vid in files[2].read_text()
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".")] == []   # no temporary left behind
