"""Regression cases (spec/regressions/<family>.yaml): a case becomes a golden vector whose expectation is
the engine's (and the reference's), its id does not move when cases are added, a malformed case is a
file:line error with exit 2, and the case `plcvec fuzz` prints for a disagreement becomes a vector
the buggy adapter fails and the reference passes.
"""
import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import fuzz_planted
from plcvec.cli import main
from plcvec.errors import SpecError
from plcvec.spec.loader import load_spec, spec_hash
from plcvec_reference import run_vector
from plcvec_reference.adapter import ReferenceAdapter
from plcvec_verify import InProcess, Suite, run

REPO = Path(__file__).resolve().parents[1]
PLANTED = f"{Path(fuzz_planted.__file__).resolve()}:EveryScan"

# TADD 1:02:03 + 4:05:06 into D300: 5:07:09, no carry, not zero.
ADD_CASE = """\
- note: "a plain addition, written for this test"
  instruction: TADD
  operands: {s1: {device: D100}, s2: {device: D200}, d: {device: D300}}
  devices: {D100: 1, D101: 2, D102: 3, D200: 4, D201: 5, D202: 6, D300: 0, D301: 0, D302: 0,
            SD0: 0, SD8067: 0, SM700: false, SM8020: false, SM8022: false}
  steps:
    - {en: true}
"""
OTHER_CASE = ADD_CASE.replace("D202: 6", "D202: 7").replace("a plain addition", "another addition")


@pytest.fixture
def spec(tmp_path):
    """A spec folder with a copy of the family the tests edit (fx5-time-add) and no regression cases:
    what is generated from it is that family alone."""
    folder = tmp_path / "spec"
    (folder / "regressions").mkdir(parents=True)
    shutil.copy(REPO / "spec" / "fx5-time-add.yaml", folder)
    return folder


def write_cases(spec, family, text):
    path = spec / "regressions" / f"{family}.yaml"
    path.write_text(text)
    return path


def generate(spec, *extra):
    out = spec.parent / "vectors"
    assert main(["generate", "--spec-dir", str(spec), "--out", str(out), *extra]) == 0
    return out


def regression_vectors(out, family):
    data = json.loads((out / f"{family}.json").read_text())
    return {v["id"]: v for v in data["vectors"] if "regression" in v["tags"]}


def test_a_case_becomes_a_vector_with_the_engines_expectation(spec):
    write_cases(spec, "fx5-time-add", ADD_CASE)
    out = generate(spec)
    (vector,) = regression_vectors(out, "fx5-time-add").values()
    assert vector["id"].startswith("fx5-time-add/TADD/regression/")
    assert vector["tags"] == ["regression"] and vector["description"] == "a plain addition, written for this test"
    assert vector["steps"][0]["en"] is True and vector["outcome"] == {"category": "value"}
    # The expectation, worked out by hand and by the independent reference implementation.
    assert vector["steps"][0]["expect"]["devices"] == {"D300": 5, "D301": 7, "D302": 9}
    expects, final = run_vector(vector)
    assert expects == [s["expect"] for s in vector["steps"]] and final == vector["final"]["devices"]
    header = json.loads((out / "fx5-time-add.json").read_text())
    assert "regression" in header["tags"]


def test_the_spec_hash_and_check_cover_the_regression_files(spec):
    write_cases(spec, "fx5-time-add", ADD_CASE)
    before = spec_hash(load_spec(spec))
    generate(spec)
    write_cases(spec, "fx5-time-add", ADD_CASE.replace("written for this test", "reworded"))
    assert spec_hash(load_spec(spec)) != before
    assert main(["generate", "--spec-dir", str(spec), "--out", str(spec.parent / "vectors"), "--check"]) == 1


def test_the_id_is_stable_when_another_case_is_added(spec):
    write_cases(spec, "fx5-time-add", ADD_CASE)
    first = regression_vectors(generate(spec), "fx5-time-add")
    write_cases(spec, "fx5-time-add", OTHER_CASE + ADD_CASE)   # the new case first
    second = regression_vectors(generate(spec), "fx5-time-add")
    assert len(second) == 2
    for vid, vector in first.items():
        assert second[vid] == vector
    # The id is of the inputs, not of the note.
    write_cases(spec, "fx5-time-add", ADD_CASE.replace("written for this test", "reworded"))
    assert set(regression_vectors(generate(spec), "fx5-time-add")) == set(first)


# -- malformed cases ----------------------------------------------------------------------------

BROKEN = [
    # (family file, what replaces what in ADD_CASE, expected line, words of the message)
    ("fx5-time-add", ("instruction: TADD", "instruction: TSUB"), 2, "instruction 'TSUB' is not one of"),
    ("fx5-time-add", ("d: {device: D300}", "x: {device: D300}"), 3, "'x' is not an operand of TADD"),
    ("fx5-time-add", ("s1: {device: D100}", "s1: {constant: 5}"), 3, "cannot be a constant"),
    ("fx5-time-add", ("D100: 1,", "D-100: 1,"), 4, "D-100"),
    ("fx5-time-add", ("D100: 1,", "D100: 70000,"), 4, "70000"),
    ("fx5-time-add", ("{en: true}", "{en: true, set: {D999: 1}}"), 7, "step 0 sets D999"),
    ("fx5-time-add", ("{en: true}", "{en: true, expect: {devices: {}}}"), 7, "unknown key 'expect'"),
    ("fx5-time-add", ("  steps:\n    - {en: true}\n", ""), 1, "'steps' is required"),
    ("fx5-time-add", ("  instruction: TADD\n", "  instruction: TADD\n  instruction: TADD\n"), 3, "duplicate key"),
    ("fx5-time-add", ("{en: true}", "{en: true"), 7, "YAML syntax error"),
    ("no-such-family", ("", ""), 1, "no spec family 'no-such-family'"),
]


@pytest.mark.parametrize("family, edit, line, message", BROKEN, ids=[b[3] for b in BROKEN])
def test_a_malformed_case_is_reported_at_its_line(spec, family, edit, line, message):
    assert edit[0] in ADD_CASE
    path = write_cases(spec, family, ADD_CASE.replace(*edit, 1))
    with pytest.raises(SpecError) as caught:
        load_spec(spec)
    assert (caught.value.path, caught.value.line) == (str(path), line), str(caught.value)
    assert message in caught.value.message


def test_a_duplicate_case_names_the_first(spec):
    path = write_cases(spec, "fx5-time-add", ADD_CASE + ADD_CASE.replace("a plain addition", "again"))
    with pytest.raises(SpecError) as caught:
        load_spec(spec)
    assert (caught.value.path, caught.value.line) == (str(path), 8)
    assert "the same inputs as the case on line 1" in caught.value.message


def test_a_case_that_cannot_run_is_reported_by_generate(spec, capsys):
    """A device the instruction reads is missing: only running the case shows it."""
    path = write_cases(spec, "fx5-time-add", ADD_CASE.replace("D201: 5, ", ""))
    assert main(["generate", "--spec-dir", str(spec), "--out", str(spec.parent / "vectors")]) == 2
    err = capsys.readouterr().err
    assert f"{path}:4: this case cannot be run" in err and "D201" in err and "Traceback" not in err


def test_lint_exits_2_without_a_traceback(spec):
    path = write_cases(spec, "fx5-time-add", ADD_CASE.replace("instruction: TADD", "instruction: TSUB"))
    proc = subprocess.run([sys.executable, "-m", "plcvec", "lint", "--spec-dir", str(spec)],
                          capture_output=True, text=True, cwd=REPO)
    assert proc.returncode == 2
    assert f"{path}:2: instruction 'TSUB'" in proc.stderr and "Traceback" not in proc.stderr


# -- from plcvec fuzz to a golden vector ----------------------------------------------------------

def fuzz_every_scan(spec, capsys, *extra):
    code = main(["fuzz", "--spec-dir", str(spec), "--python", PLANTED, "--examples", "1000", *extra])
    out = capsys.readouterr().out
    assert code == 1, out
    return out


def printed_stanza(out):
    lines = out.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("- note: "))
    return "\n".join(lines[start:]) + "\n"


def test_the_fuzz_stanza_becomes_a_vector_the_bug_fails_and_the_reference_passes(spec, capsys):
    out = fuzz_every_scan(spec, capsys)
    stanza = printed_stanza(out)
    assert "found by plcvec fuzz --seed 0" in stanza and "TADDP" in stanza
    write_cases(spec, "fx5-time-add", stanza)
    vectors = generate(spec)
    (vid,) = regression_vectors(vectors, "fx5-time-add")
    assert f"the golden vector {vid}," in out
    suite = Suite.load(vectors)
    from plcvec_verify import Selection

    only = Selection(ids=(vid,))
    assert run(suite, InProcess(fuzz_planted.EveryScan()), only).exit_code == 1
    assert run(suite, InProcess(ReferenceAdapter()), only).exit_code == 0


def test_fuzz_regression_appends_the_case_once(spec, capsys):
    out = fuzz_every_scan(spec, capsys, "--regression")
    path = spec / "regressions" / "fx5-time-add.yaml"
    text = path.read_text()
    assert f"Appended to {path}" in out and text.startswith("# ") and text.endswith(printed_stanza(out))
    assert load_spec(spec)[[f.name for f in load_spec(spec)].index("fx5-time-add")].regressions.cases
    # The same case again: refused, and the file is left as it was.
    assert main(["fuzz", "--spec-dir", str(spec), "--python", PLANTED, "--examples", "1000", "--regression"]) == 2
    err = capsys.readouterr().err
    assert "the same inputs as the case on line 3" in err
    assert path.read_text() == text
    assert not [p for p in path.parent.iterdir() if p.name.startswith(".")]   # no temporary file left
