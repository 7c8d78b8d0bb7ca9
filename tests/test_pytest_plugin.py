"""The pytest plugin, as an implementer runs it: in an empty project folder, through pytest itself.

Each test runs its pytest sessions twice: in this process (pytester's in-process run: the plugin's
code, its options, exit statuses and output, without a Python start per session) in the default run,
and as `python -m pytest` processes, as a user types it, under `slow` (CI).
"""
import os
import shlex
import subprocess
import sys

import pytest

from plcvec_verify import Suite

from conftest import REPO

pytest_plugins = ["pytester"]

REFERENCE = ["--plcvec-python", "plcvec_reference.adapter:ReferenceAdapter"]


class Sessions:
    """pytest sessions in an empty folder (`folder`): run(*args, env={...}) -> (exit status, output)."""

    def __init__(self, how, pytester, monkeypatch):
        self.how, self.pytester, self.monkeypatch = how, pytester, monkeypatch
        self.folder = pytester.path

    def run(self, *args, env=None):
        args = ["-p", "no:cacheprovider", "-q", *map(str, args)]
        if self.how == "process":
            proc = subprocess.run([sys.executable, "-m", "pytest", *args], cwd=self.folder, capture_output=True,
                                  text=True, timeout=300, env={**os.environ, **(env or {})})
            return proc.returncode, proc.stdout + proc.stderr
        with self.monkeypatch.context() as m:
            for name, value in (env or {}).items():
                m.setenv(name, value)
            result = self.pytester.runpytest_inprocess(*args)
        return int(result.ret), "\n".join(result.outlines + result.errlines)


@pytest.fixture(params=["in-process", pytest.param("process", marks=pytest.mark.slow)])
def sessions(request, pytester, monkeypatch):
    return Sessions(request.param, pytester, monkeypatch)


@pytest.fixture(scope="module")
def suite():
    return Suite.load(REPO / "vectors")


def test_one_item_per_vector_named_by_id(sessions, suite):
    rc, out = sessions.run(*REFERENCE, "--collect-only")
    assert rc == 0, out
    listed = {line.split("::")[-1] for line in out.splitlines() if "::plcvec::" in line}
    assert listed == set(suite.by_id)


def test_reference_passes_with_keyword_selection(sessions, suite):
    rc, out = sessions.run(*REFERENCE, "-k", "TADDP")
    want = sum("TADDP" in v["id"] or v["instruction"] == "TADDP" for v in suite.vectors)
    assert rc == 0 and f"{want} passed" in out, out


def test_markers_select_by_tag(sessions, suite):
    rc, out = sessions.run(*REFERENCE, "-m", "nonexistent_date")
    want = sum("nonexistent-date" in v["tags"] for v in suite.vectors)
    assert rc == 0 and f"{want} passed" in out, out


def test_a_failing_vector_shows_the_field_diff_and_clauses_and_x_stops(sessions, suite):
    vid = "fx5-time-add/TADD/manual-example/program"
    rc, out = sessions.run("--plcvec-python", "plcvec_reference.adapter:ReferenceAdapter",
                        "--plcvec-choose", "TADD-EXACT-24=carry-above-24", "-k", "manual", "-x")
    assert rc == 1, out
    # Declared carry-at-24 by the reference, so the --plcvec-choose conflict is a usage error on every item.
    assert "but the adapter declares TADD-EXACT-24=carry-at-24" in out
    faulty = shlex.join([sys.executable, str(REPO / 'tests' / 'adapters' / 'faulty.py'), 'wrong-shape', vid])
    rc, out = sessions.run("--plcvec-adapter", faulty, "-k", "fx5-time-add", "-x")
    assert rc == 1 and f"FAILED ::plcvec::{vid}" in out and "stopping after 1 failures" in out, out
    assert "does not match result.schema.json" in out


def test_expectations_file_turns_a_failure_into_xfail(sessions):
    vid = "fx5-time-add/TADD/manual-example/program"
    (sessions.folder / "known.toml").write_text(f'[[known-failure]]\nid = "{vid}"\nreason = "tracked"\n')
    faulty = shlex.join([sys.executable, str(REPO / 'tests' / 'adapters' / 'faulty.py'), 'wrong-shape', vid])
    rc, out = sessions.run("--plcvec-adapter", faulty, "--plcvec-expectations", "known.toml",
                           "-k", "manual-example and TADD")
    assert rc == 0 and "1 xfailed" in out, out


def test_write_expectations_from_the_environment_is_read_back_as_known_failures(sessions):
    """PLCVEC_WRITE_EXPECTATIONS (or --plcvec-write-expectations) writes the run's one failure; the
    file, given back as PLCVEC_KNOWN_FAILURES, turns that failure into xfail and the session passes."""
    vid = "fx5-time-add/TADD/manual-example/program"
    faulty = shlex.join([sys.executable, str(REPO / 'tests' / 'adapters' / 'faulty.py'), 'wrong-shape', vid])
    written = sessions.folder / "written.toml"
    args = ["--plcvec-adapter", faulty, "-k", "manual-example and TADD"]
    rc, out = sessions.run(*args, env={"PLCVEC_WRITE_EXPECTATIONS": str(written)})
    assert rc == 1 and "1 known failures written to" in out, out
    text = written.read_text()
    assert text.count("[[known-failure]]") == 1 and f'id = "{vid}"' in text, text
    rc, out = sessions.run(*args, env={"PLCVEC_KNOWN_FAILURES": str(written)})
    assert rc == 0 and "1 xfailed" in out, out


def test_an_expectations_file_that_cannot_be_written_is_a_usage_error_not_a_traceback(sessions):
    (sessions.folder / "a-file").write_text("")
    target = sessions.folder / "a-file" / "known.toml"
    rc, out = sessions.run(*REFERENCE, "-k", "manual-example and TADD", "--plcvec-write-expectations", target)
    assert rc == 4, out                                 # pytest's usage error, as plcvec verify exits 2
    assert f"--plcvec-write-expectations {target}: " in out, out
    assert "Traceback" not in out and "Error: [Errno" not in out, out


# -- the gate holds under pytest as under `plcvec verify` ------------------------------------

LAZY = REPO / "tests" / "adapters" / "lazy.py"


@pytest.mark.parametrize("args, message", [
    (["--plcvec-tag", "nosuchtag"], "--plcvec-tag nosuchtag: "),
    (["--plcvec-instruction", "TADX"], "--plcvec-instruction TADX: "),
    (["--plcvec-id", "zzz*"], "--plcvec-id zzz*: matches no vector id"),
    (["-m", "nonexistent_dates"], "nonexistent_dates is neither a vector tag nor a registered marker"),
], ids=["tag", "instruction", "id", "marker"])
def test_unknown_names_are_usage_errors(sessions, args, message):
    rc, out = sessions.run(*REFERENCE, *args)
    assert rc == 4 and message in out, out      # pytest's usage error


def test_an_empty_selection_exits_5_unless_allowed(sessions):
    args = [*REFERENCE, "--plcvec-family", "fx5-time-add", "--plcvec-instruction", "LDTM="]
    rc, out = sessions.run(*args)
    assert rc == 5, out
    rc, out = sessions.run(*args, "--plcvec-allow-empty")
    assert rc == 0, out


def test_a_session_in_which_everything_is_skipped_exits_5(sessions, suite):
    n = sum(v["family"] == "fx5-time-add" for v in suite.vectors)
    rc, out = sessions.run("--plcvec-python", f"{LAZY}:SkipsEverything", "--plcvec-family", "fx5-time-add")
    assert rc == 5 and f"{n} skipped" in out and f"SKIPPED {n} of {n} vectors" in out, out
    assert "NOT PASSED (exit 5): nothing passed" in out
    rc, out = sessions.run("--plcvec-python", f"{LAZY}:SkipsEverything", "--plcvec-family", "fx5-time-add",
                        "--plcvec-allow-empty")
    assert rc == 0, out


def test_max_skipped(sessions, suite):
    skipped = sum(v["family"] == "fx5-time-add" and v["instruction"] != "TADD" for v in suite.vectors)
    args = ["--plcvec-python", f"{LAZY}:OnlyTadd", "--plcvec-family", "fx5-time-add"]
    rc, out = sessions.run(*args, "--plcvec-max-skipped", str(skipped))
    assert rc == 0, out
    rc, out = sessions.run(*args, "--plcvec-max-skipped", str(skipped - 1))
    assert rc == 5 and f"more than --plcvec-max-skipped {skipped - 1}" in out, out


def test_infer_turns_failures_a_reading_explains_into_xfail_and_says_which(sessions):
    args = ["--plcvec-python", f"{REPO / 'tests' / 'adapters' / 'undeclared.py'}:Undeclared", "--plcvec-family",
            "fx5-time-add"]
    env = {"PLCVEC_TEST_FOLLOW": "TADD-FLAGS-OFF=set-only"}
    rc, out = sessions.run(*args, "--plcvec-infer", "-rx", env=env)
    assert rc == 0, out
    assert "TADD-FLAGS-OFF=set-only (inferred; followed written-each-execution)" in out
    assert "one choice of alternatives explains every vector" in out
    assert "explained by another reading: --choose TADD-FLAGS-OFF=set-only" in out
    assert " failed" not in out.splitlines()[-1]
    # Without --plcvec-infer the same answers fail, each once, with the roll-up in the summary.
    rc, out = sessions.run(*args, env=env)
    assert rc == 1
    failed = [line for line in out.splitlines() if line.startswith("FAILED ")]
    assert failed and len(failed) == len(set(failed))
    assert f"READINGS: {len(failed)} of {len(failed)} failing vectors pass under other alternatives:" in out
