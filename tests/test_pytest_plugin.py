"""The pytest plugin, as an implementer runs it: in an empty project folder, through pytest itself."""
import shlex
import subprocess
import sys

import pytest

from plcvec_verify import Suite

from conftest import REPO

REFERENCE = ["--plcvec-python", "plcvec_reference.adapter:ReferenceAdapter"]


def pytest_in(tmp_path, *args):
    proc = subprocess.run([sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-q", *args],
                          cwd=tmp_path, capture_output=True, text=True, timeout=300)
    return proc.returncode, proc.stdout + proc.stderr


@pytest.fixture(scope="module")
def suite():
    return Suite.load(REPO / "vectors")


def test_one_item_per_vector_named_by_id(tmp_path, suite):
    rc, out = pytest_in(tmp_path, *REFERENCE, "--collect-only")
    assert rc == 0, out
    listed = {line.split("::")[-1] for line in out.splitlines() if "::plcvec::" in line}
    assert listed == set(suite.by_id)


def test_reference_passes_with_keyword_selection(tmp_path, suite):
    rc, out = pytest_in(tmp_path, *REFERENCE, "-k", "TADDP")
    want = sum("TADDP" in v["id"] or v["instruction"] == "TADDP" for v in suite.vectors)
    assert rc == 0 and f"{want} passed" in out, out


def test_markers_select_by_tag(tmp_path, suite):
    rc, out = pytest_in(tmp_path, *REFERENCE, "-m", "nonexistent_date")
    want = sum("nonexistent-date" in v["tags"] for v in suite.vectors)
    assert rc == 0 and f"{want} passed" in out, out


def test_a_failing_vector_shows_the_field_diff_and_clauses_and_x_stops(tmp_path, suite):
    vid = "fx5-time-add/TADD/manual-example/program"
    rc, out = pytest_in(tmp_path, "--plcvec-python", "plcvec_reference.adapter:ReferenceAdapter",
                        "--plcvec-choose", "TADD-EXACT-24=carry-above-24", "-k", "manual", "-x")
    assert rc == 1, out
    # Declared carry-at-24 by the reference, so the --plcvec-choose conflict is a usage error on every item.
    assert "but the adapter declares TADD-EXACT-24=carry-at-24" in out
    faulty = shlex.join([sys.executable, str(REPO / 'tests' / 'adapters' / 'faulty.py'), 'wrong-shape', vid])
    rc, out = pytest_in(tmp_path, "--plcvec-adapter", faulty, "-k", "fx5-time-add", "-x")
    assert rc == 1 and f"FAILED ::plcvec::{vid}" in out and "stopping after 1 failures" in out, out
    assert "does not match result.schema.json" in out


def test_expectations_file_turns_a_failure_into_xfail(tmp_path):
    vid = "fx5-time-add/TADD/manual-example/program"
    (tmp_path / "known.toml").write_text(f'[[known-failure]]\nid = "{vid}"\nreason = "tracked"\n')
    faulty = shlex.join([sys.executable, str(REPO / 'tests' / 'adapters' / 'faulty.py'), 'wrong-shape', vid])
    rc, out = pytest_in(tmp_path, "--plcvec-adapter", faulty, "--plcvec-expectations", "known.toml",
                        "-k", "manual-example and TADD")
    assert rc == 0 and "1 xfailed" in out, out



def test_write_expectations_from_the_environment_is_read_back_as_known_failures(tmp_path):
    """PLCVEC_WRITE_EXPECTATIONS (or --plcvec-write-expectations) writes the run's one failure; the
    file, given back as PLCVEC_KNOWN_FAILURES, turns that failure into xfail and the session passes."""
    import os

    vid = "fx5-time-add/TADD/manual-example/program"
    faulty = shlex.join([sys.executable, str(REPO / 'tests' / 'adapters' / 'faulty.py'), 'wrong-shape', vid])
    env = {**os.environ, "PLCVEC_WRITE_EXPECTATIONS": str(tmp_path / "written.toml")}
    args = [sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-q", "--plcvec-adapter", faulty,
            "-k", "manual-example and TADD"]
    proc = subprocess.run(args, cwd=tmp_path, capture_output=True, text=True, timeout=300, env=env)
    out = proc.stdout + proc.stderr
    assert proc.returncode == 1 and "1 known failures written to" in out, out
    written = (tmp_path / "written.toml").read_text()
    assert written.count("[[known-failure]]") == 1 and f'id = "{vid}"' in written, written
    env = {**os.environ, "PLCVEC_KNOWN_FAILURES": str(tmp_path / "written.toml")}
    proc = subprocess.run(args, cwd=tmp_path, capture_output=True, text=True, timeout=300, env=env)
    assert proc.returncode == 0 and "1 xfailed" in proc.stdout, proc.stdout + proc.stderr


def test_an_expectations_file_that_cannot_be_written_is_a_usage_error_not_a_traceback(tmp_path):
    (tmp_path / "a-file").write_text("")
    rc, out = pytest_in(tmp_path, *REFERENCE, "-k", "manual-example and TADD",
                        "--plcvec-write-expectations", str(tmp_path / "a-file" / "known.toml"))
    assert rc == 4, out                                 # pytest's usage error, as plcvec verify exits 2
    assert f"--plcvec-write-expectations {tmp_path / 'a-file' / 'known.toml'}: " in out, out
    assert "Traceback" not in out and "Error: [Errno" not in out, out

# -- the gate holds under pytest as under `plcvec verify` ------------------------------------

LAZY = REPO / "tests" / "adapters" / "lazy.py"


@pytest.mark.parametrize("args, message", [
    (["--plcvec-tag", "nosuchtag"], "--plcvec-tag nosuchtag: "),
    (["--plcvec-instruction", "TADX"], "--plcvec-instruction TADX: "),
    (["--plcvec-id", "zzz*"], "--plcvec-id zzz*: matches no vector id"),
    (["-m", "nonexistent_dates"], "nonexistent_dates is neither a vector tag nor a registered marker"),
], ids=["tag", "instruction", "id", "marker"])
def test_unknown_names_are_usage_errors(tmp_path, args, message):
    rc, out = pytest_in(tmp_path, *REFERENCE, *args)
    assert rc == 4 and message in out, out      # pytest's usage error


def test_an_empty_selection_exits_5_unless_allowed(tmp_path):
    args = [*REFERENCE, "--plcvec-family", "fx5-time-add", "--plcvec-instruction", "LDTM="]
    rc, out = pytest_in(tmp_path, *args)
    assert rc == 5, out
    rc, out = pytest_in(tmp_path, *args, "--plcvec-allow-empty")
    assert rc == 0, out


def test_a_session_in_which_everything_is_skipped_exits_5(tmp_path, suite):
    n = sum(v["family"] == "fx5-time-add" for v in suite.vectors)
    rc, out = pytest_in(tmp_path, "--plcvec-python", f"{LAZY}:SkipsEverything", "--plcvec-family", "fx5-time-add")
    assert rc == 5 and f"{n} skipped" in out and f"SKIPPED {n} of {n} vectors" in out, out
    assert "NOT PASSED (exit 5): nothing passed" in out
    rc, out = pytest_in(tmp_path, "--plcvec-python", f"{LAZY}:SkipsEverything", "--plcvec-family", "fx5-time-add",
                        "--plcvec-allow-empty")
    assert rc == 0, out


def test_max_skipped(tmp_path, suite):
    skipped = sum(v["family"] == "fx5-time-add" and v["instruction"] != "TADD" for v in suite.vectors)
    args = ["--plcvec-python", f"{LAZY}:OnlyTadd", "--plcvec-family", "fx5-time-add"]
    rc, out = pytest_in(tmp_path, *args, "--plcvec-max-skipped", str(skipped))
    assert rc == 0, out
    rc, out = pytest_in(tmp_path, *args, "--plcvec-max-skipped", str(skipped - 1))
    assert rc == 5 and f"more than --plcvec-max-skipped {skipped - 1}" in out, out


def test_infer_turns_failures_a_reading_explains_into_xfail_and_says_which(tmp_path):
    env_follow = "TADD-FLAGS-OFF=set-only"
    proc = subprocess.run([sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-q", "--plcvec-python",
                           f"{REPO / 'tests' / 'adapters' / 'undeclared.py'}:Undeclared", "--plcvec-family",
                           "fx5-time-add", "--plcvec-infer", "-rx"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=300, env={**__import__("os").environ, "PLCVEC_TEST_FOLLOW": env_follow})
    out = proc.stdout + proc.stderr
    assert proc.returncode == 0, out
    assert "TADD-FLAGS-OFF=set-only (inferred; followed written-each-execution)" in out
    assert "one choice of alternatives explains every vector" in out
    assert "explained by another reading: --choose TADD-FLAGS-OFF=set-only" in out
    assert " failed" not in out.splitlines()[-1]
    # Without --plcvec-infer the same answers fail, each once, with the roll-up in the summary.
    proc = subprocess.run([sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-q", "--plcvec-python",
                           f"{REPO / 'tests' / 'adapters' / 'undeclared.py'}:Undeclared", "--plcvec-family",
                           "fx5-time-add"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=300, env={**__import__("os").environ, "PLCVEC_TEST_FOLLOW": env_follow})
    out = proc.stdout + proc.stderr
    assert proc.returncode == 1
    failed = [line for line in out.splitlines() if line.startswith("FAILED ")]
    assert failed and len(failed) == len(set(failed))
    assert f"READINGS: {len(failed)} of {len(failed)} failing vectors pass under other alternatives:" in out
