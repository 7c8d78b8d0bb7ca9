"""The one failure text: the shared cases of verifiers/parity/text/ give exactly the expected text.

Every runner's tests run the same cases (TEXT.md, "The shared cases"); this is Python's. The
expected text was written from TEXT.md's rules and the case files, not from a run.
"""
from __future__ import annotations

import json
import re
from pathlib import Path

from plcvec_verify.adapters import InProcess
from plcvec_verify.describe import declaration
from plcvec_verify.known import KnownFailures
from plcvec_verify.reports import summary_text
from plcvec_verify.runner import run
from plcvec_verify.suite import Suite

ROOT = Path(__file__).resolve().parent.parent
TEXT = ROOT / "verifiers" / "parity" / "text"


class Replay:
    """An implementation that declares the cases' hello and answers each vector from the cases."""

    def __init__(self, cases: dict):
        self.cases = cases

    def hello(self, request):
        return json.loads(json.dumps(self.cases["hello"]))

    def run(self, request):
        return json.loads(json.dumps(self.cases["answers"][request["id"]]))


def machine_free(text: str) -> str:
    """The run's text without what depends on the machine: the header line and the time."""
    lines = text.split("\n")
    header = next(i for i, line in enumerate(lines) if line.startswith("plcvec verify: "))
    del lines[header]
    lines = [re.sub(r" in [0-9]+\.[0-9]{2} s$", "", line) for line in lines]
    return "\n".join(lines)


def shared_run(known=None):
    cases = json.loads((TEXT / "answers.json").read_text())
    return run(Suite.load(TEXT / "vectors"), InProcess(Replay(cases), "text-cases"), known=known)


def test_the_shared_cases_give_the_expected_text_byte_for_byte():
    report = shared_run()
    got = machine_free(summary_text(report))
    want = (TEXT / "expected.txt").read_text()
    assert got == want


def test_the_shared_cases_with_their_known_failures_give_the_expected_text(monkeypatch):
    # The file is given as the shared cases name it: `known.toml`, from its own folder.
    monkeypatch.chdir(TEXT)
    report = shared_run(KnownFailures.load("known.toml"))
    got = machine_free(summary_text(report))
    assert got == (TEXT / "expected-known.txt").read_text()


def test_the_declaration_is_written_as_each_python_entry_point_takes_it():
    # TEXT.md, "The declaration in each runner": the table's two rows for Python's entry points.
    changes = {"TADD-FLAGS-OFF": "set-only", "FX5-SM709-SCOPE": "all-words"}
    assert declaration(changes) == "--choose FX5-SM709-SCOPE=all-words --choose TADD-FLAGS-OFF=set-only"
    assert declaration(changes, "pytest") == ("--plcvec-choose FX5-SM709-SCOPE=all-words "
                                              "--plcvec-choose TADD-FLAGS-OFF=set-only")


def test_the_shared_cases_cover_what_text_md_promises():
    """The expected text holds each kind of line the cases are there to pin down."""
    want = (TEXT / "expected.txt").read_text()
    for line in ("    step 0 result: expected true, got false",                       # a wrong contact result
                 "    step 1 D202: expected 2, got 3 (before the step: 2)",            # the implementation's own value
                 "    step 1 D300: expected 0, got 1 (before the step: 1)",            # carried over, not written
                 "    step 0 D7777: expected <not in the vector>, got 1",              # a write outside the vector
                 "    step 0 SD0: expected 0, got 1 (the step must leave it unchanged)",
                 "    step 0 P_ER: expected false, got <not reported> (before the step: false)",
                 "    step 0 SM8020: expected true, got 1 (before the step: false)",   # a bit as the number 1
                 "    steps: expected 1 steps, got 0 steps",
                 "    judged by: FX5-SM709-SCOPE=selected-fields",
                 "    the implementation reported an error: comparator fault at s2",
                 "READINGS: 3 of 14 failing vectors pass under other alternatives:",
                 "NOT EXPLAINED by any reading: 11 failing vectors, by the clauses they cite:",
                 "SKIPPED 3 of 19 vectors (15.8%):",
                 # devices a declared alternative leaves unjudged: named, not compared; a stray write still is
                 "    not judged under HOUR-D1-OUT-OF-RANGE=undefined: D200, D201, D202, M10, M8004",
                 "    step 0 D999: expected <not in the vector>, got 1",
                 "cpu_writes: SD0, SM0"):
        assert line + "\n" in want, line
    # A declared cpu_writes device written outside the vector passes; each failure is printed once.
    assert "fx5-time-add/TADD/manual-example/carry\n" not in want
    assert want.count("FAIL fx5-time-add/TADD/manual-example/ex1\n") == 1


def test_a_failure_block_is_printed_once_per_run():
    text = summary_text(shared_run())
    blocks = re.findall(r"^(?:FAIL|ERROR) (.+)$", text, flags=re.M)
    assert len(blocks) == len(set(blocks)) == 14


def test_the_shared_cases_are_the_golden_vectors():
    """Every runner judges the shared cases, the C library's compiled-in golden tables included, so their
    vectors must be the golden ones: a spec change to one of them fails here until text_cases.py is
    run and expected.txt is brought up to date by hand."""
    import subprocess
    import sys

    done = subprocess.run([sys.executable, str(ROOT / "verifiers" / "parity" / "text_cases.py"), "--check"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr
