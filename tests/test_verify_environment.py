"""What every runner reads the same way: the PLCVEC_* variables (defaults of plcvec verify's options),
the per-vector bound, and vector folders refused on load as CONTRACT.md says (both forms)."""
from __future__ import annotations

import hashlib
import json
import shutil
import time
from pathlib import Path

import pytest

from plcvec_verify.adapters import InProcess
from plcvec_verify.command import main
from plcvec_verify.errors import VerifyError
from plcvec_verify.runner import run
from plcvec_verify.suite import Selection, Suite
from plcvec_verify.validate import vector_problem
from plcvec_reference.adapter import ReferenceAdapter

from conftest import REPO

REFERENCE = ["--python", "plcvec_reference.adapter:ReferenceAdapter", "-q", "--no-progress"]
TARGET = "fx5-time-add/TADD/manual-example/program"


def verify(monkeypatch, capsys, env: dict, *args) -> tuple[int, str]:
    for name in ("PLCVEC_VECTORS", "PLCVEC_ID", "PLCVEC_FAMILY", "PLCVEC_INSTRUCTION", "PLCVEC_TAG",
                 "PLCVEC_INTERPRETATION", "PLCVEC_SHARD", "PLCVEC_KNOWN_FAILURES", "PLCVEC_WRITE_EXPECTATIONS",
                 "PLCVEC_TIMEOUT"):
        monkeypatch.delenv(name, raising=False)
    for name, value in env.items():
        monkeypatch.setenv(name, value)
    status = main([*REFERENCE, *args])
    out = capsys.readouterr()
    return status, out.out + out.err


TIMEOUT_RULE = "the bound must be a number of seconds above 0 and at most 86400"


@pytest.mark.parametrize("env, status, words", [
    ({"PLCVEC_FAMILY": ","}, 2, ["PLCVEC_FAMILY=,: an empty name is not a filter; known: cp1e-time-compare, "]),
    ({"PLCVEC_FAMILY": "fx5-time-add,"}, 2, ["PLCVEC_FAMILY=fx5-time-add,: an empty name", "fx5-time-compare"]),
    ({"PLCVEC_FAMILY": "no-such-family"}, 2, ["PLCVEC_FAMILY no-such-family: ", "known: cp1e-time-compare"]),
    ({"PLCVEC_TAG": "no-such-tag"}, 2, ["PLCVEC_TAG no-such-tag", "boundary"]),
    ({"PLCVEC_INTERPRETATION": "NOPE"}, 2, ["PLCVEC_INTERPRETATION NOPE", "TADD-EXACT-24"]),
    ({"PLCVEC_ID": "zzz*"}, 2, ["PLCVEC_ID zzz*: matches no vector id"]),
    ({"PLCVEC_SHARD": "half"}, 2, ["PLCVEC_SHARD takes K/N", "'half'"]),
    ({"PLCVEC_SHARD": "3/2"}, 2, ["PLCVEC_SHARD 3/2"]),
    ({"PLCVEC_TIMEOUT": "soon"}, 2, [f"PLCVEC_TIMEOUT=soon: {TIMEOUT_RULE}"]),
    ({"PLCVEC_TIMEOUT": "0"}, 2, [f"PLCVEC_TIMEOUT=0: {TIMEOUT_RULE}"]),
    ({"PLCVEC_TIMEOUT": "-1"}, 2, [f"PLCVEC_TIMEOUT=-1: {TIMEOUT_RULE}"]),
    # Numbers no platform's clock overflows on, written one way in every runner: no exponent, no sign.
    ({"PLCVEC_TIMEOUT": "1e9"}, 2, [f"PLCVEC_TIMEOUT=1e9: {TIMEOUT_RULE}"]),
    ({"PLCVEC_TIMEOUT": "1e12"}, 2, [f"PLCVEC_TIMEOUT=1e12: {TIMEOUT_RULE}"]),
    ({"PLCVEC_TIMEOUT": "86400.5"}, 2, [f"PLCVEC_TIMEOUT=86400.5: {TIMEOUT_RULE}"]),
    ({"PLCVEC_TIMEOUT": "+5"}, 2, [f"PLCVEC_TIMEOUT=+5: {TIMEOUT_RULE}"]),
    ({"PLCVEC_TIMEOUT": "inf"}, 2, [f"PLCVEC_TIMEOUT=inf: {TIMEOUT_RULE}"]),
    ({"PLCVEC_TIMEOUT": "86400", "PLCVEC_FAMILY": "fx5-time-add"}, 0, []),
    ({"PLCVEC_TIMEOUT": "0.5", "PLCVEC_FAMILY": "fx5-time-add"}, 0, []),
    ({"PLCVEC_VECTORS": "/no/such/folder"}, 2, ["/no/such/folder: no such vector folder or file"]),
    ({"PLCVEC_KNOWN_FAILURES": "/no/such/known.toml"}, 2, ["/no/such/known.toml"]),
    ({"PLCVEC_FAMILY": "fx5-time-add", "PLCVEC_ID": "fx5-time-compare/*"}, 5, ["no vector selected"]),
    ({"PLCVEC_ID": f"{TARGET}, fx5-time-add/TADDP/*"}, 0, []),
])
def test_the_variables_are_read_with_the_options_errors(monkeypatch, capsys, env, status, words):
    got, out = verify(monkeypatch, capsys, env)
    assert got == status, out
    for word in words:
        assert word in out
    assert "Traceback" not in out


def test_a_variable_selects_and_an_option_given_wins(monkeypatch, capsys, tmp_path):
    suite = Suite.load(REPO / "vectors")
    tadd = len(Selection(families=("fx5-time-add",)).apply(suite.vectors))
    status, out = verify(monkeypatch, capsys, {"PLCVEC_FAMILY": "fx5-time-add"})
    assert status == 0 and out.startswith(f"{tadd} vectors: {tadd} pass"), out
    status, out = verify(monkeypatch, capsys, {"PLCVEC_FAMILY": "no-such-family"}, "--family", "fx5-time-add")
    assert status == 0 and out.startswith(f"{tadd} vectors"), out
    status, out = verify(monkeypatch, capsys, {"PLCVEC_FAMILY": "fx5-time-add", "PLCVEC_SHARD": "1/2"})
    assert status == 0 and int(out.split()[0]) < tadd
    known = tmp_path / "known.toml"
    known.write_text(f'[[known-failure]]\nid = "{TARGET}"\nreason = "tracked"\n')
    status, out = verify(monkeypatch, capsys, {"PLCVEC_FAMILY": "fx5-time-add", "PLCVEC_KNOWN_FAILURES": str(known)})
    assert status == 1 and "1 stale" in out, out          # the reference passes it: a stale entry
    written = tmp_path / "written.toml"
    status, out = verify(monkeypatch, capsys, {"PLCVEC_FAMILY": "fx5-time-add", "PLCVEC_WRITE_EXPECTATIONS": str(written)},
                         "--choose", "TADD-EXACT-24=carry-above-24", "--python", "tests.test_verify_environment:Undeclaring")
    assert status == 1 and written.is_file() and "[[known-failure]]" in written.read_text(), out


class Undeclaring(ReferenceAdapter):
    def hello(self, request):
        answer = super().hello(request)
        answer["interpretations"] = {}
        return answer


class Looping(ReferenceAdapter):
    def run(self, request):
        if request["id"] == TARGET:
            while True:
                try:
                    time.sleep(0.01)
                except Exception:     # an adapter that swallows everything it can
                    pass
        return super().run(request)


def test_an_adapter_object_that_never_answers_is_bounded_per_vector():
    suite = Suite.load(REPO / "vectors")
    start = time.monotonic()
    report = run(suite, InProcess(Looping(), "Looping", timeout=0.4), Selection(families=("fx5-time-add",)))
    elapsed = time.monotonic() - start
    bad = [r for r in report.results if r.status != "pass"]
    assert [(r.id, r.status) for r in bad] == [(TARGET, "error")]
    assert "gave no answer within 0.4 s (timeout; PLCVEC_TIMEOUT or --timeout sets the bound)" in bad[0].message
    assert f"(while running {TARGET})" in bad[0].message
    assert 0.4 <= elapsed < 5
    # The timer is gone afterwards: nothing fires in the caller's code.
    time.sleep(0.6)


# --- vector folders refused on load -------------------------------------------------------------

def _copy(tmp_path, form: str) -> Path:
    if form == "json":
        return Path(shutil.copytree(REPO / "vectors", tmp_path / "vectors"))
    return Path(shutil.copytree(REPO / "verifiers" / "go" / "vectors", tmp_path / "jsonl"))


def _lines(folder: Path) -> tuple[Path, list]:
    file = folder / "fx5-time-add.jsonl"
    return file, file.read_bytes().split(b"\n")


def _reseal(folder: Path, index_name: str, file: Path) -> None:
    """Record `file`'s new sha256 in the index, so that the damage is the only fault."""
    index = json.loads((folder / index_name).read_text())
    index["families"]["fx5-time-add"]["sha256"] = hashlib.sha256(file.read_bytes()).hexdigest()
    (folder / index_name).write_text(json.dumps(index))


@pytest.mark.parametrize("form", ["json", "jsonl"])
def test_both_forms_load_the_same_vectors(tmp_path, form):
    golden = Suite.load(REPO / "vectors")
    other = Suite.load(_copy(tmp_path, form))
    assert [v["id"] for v in other.vectors] == [v["id"] for v in golden.vectors]
    assert other.suite_version == golden.suite_version and other.spec_sha256 == golden.spec_sha256


@pytest.mark.parametrize("form", ["json", "jsonl"])
def test_a_family_file_whose_sha256_is_not_the_indexed_one_is_refused(tmp_path, form):
    folder = _copy(tmp_path, form)
    index = folder / ("manifest.json" if form == "json" else "index.json")
    name = "fx5-time-add." + form
    data = (folder / name).read_bytes()
    (folder / name).write_bytes(data.replace(b"10:30:10 + 03:10:05", b"10:30:10 + 03:10:06", 1))
    with pytest.raises(VerifyError, match=rf"{name}: its sha256 is not the one {index.name} records"):
        Suite.load(folder)


def test_a_jsonl_file_cut_at_a_line_is_refused_by_its_count_and_hash(tmp_path):
    folder = _copy(tmp_path, "jsonl")
    file, lines = _lines(folder)
    file.write_bytes(b"\n".join(lines[:-3]) + b"\n")
    with pytest.raises(VerifyError, match="fx5-time-add.jsonl: its sha256 is not"):
        Suite.load(folder)
    _reseal(folder, "index.json", file)
    with pytest.raises(VerifyError, match=r"fx5-time-add.jsonl: \d+ vectors, but index.json records \d+"):
        Suite.load(folder)
    file.write_bytes(b"\n".join(lines[:2]))          # no newline at the end: cut inside a line
    with pytest.raises(VerifyError, match=r"fx5-time-add.jsonl:2: the last line does not end"):
        Suite.load(folder)


def test_a_jsonl_line_that_is_not_json_is_named_by_file_and_line(tmp_path):
    file, lines = _lines(_copy(tmp_path, "jsonl"))
    lines[4] = b'{"id": this is not JSON'
    file.write_bytes(b"\n".join(lines))
    with pytest.raises(VerifyError, match=r"fx5-time-add.jsonl:5: not valid JSON"):
        Suite.load(file.parent)


def test_a_device_whose_json_type_changes_within_a_vector_is_refused(tmp_path):
    folder = _copy(tmp_path, "json")
    file = folder / "fx5-time-add.json"
    data = json.loads(file.read_text())
    v = next(v for v in data["vectors"] if v["id"] == TARGET)
    assert v["initial"]["devices"]["SM700"] is False
    v["initial"]["devices"]["SM700"] = 2      # a bit holding 2: a valid word, so the schema lets it by
    file.write_text(json.dumps(data, indent=1))
    _reseal(folder, "manifest.json", file)
    with pytest.raises(VerifyError) as e:
        Suite.load(folder)
    assert f"vector {TARGET}: at initial/devices/SM700: 2 is a word, but at final/devices/SM700" in str(e.value) \
        or f"vector {TARGET}: at final/devices/SM700: false is a bit (true/false), but at initial/devices/SM700" \
        in str(e.value), str(e.value)


def test_every_golden_vector_keeps_each_device_s_type():
    for v in Suite.load(REPO / "vectors").vectors:
        assert vector_problem(v) == "", v["id"]
    v = {"initial": {"devices": {"D1": 1}}, "final": {"devices": {"D1": 1}},
         "steps": [{"set": {"D1": True}, "expect": {}}]}
    assert vector_problem(v) == ("at steps/0/set/D1: true is a bit (true/false), but at initial/devices/D1 "
                                 "the same device holds 1, a word")


def test_the_old_name_of_a_setting_is_read_with_a_warning_naming_the_new_one(monkeypatch, capsys, tmp_path):
    known = tmp_path / "known.toml"
    known.write_text(f'[[known-failure]]\nid = "{TARGET}"\nreason = "tracked"\n')
    monkeypatch.delenv("PLCVEC_EXPECTATIONS", raising=False)
    status, out = verify(monkeypatch, capsys, {"PLCVEC_FAMILY": "fx5-time-add", "PLCVEC_EXPECTATIONS": str(known)})
    # Read: the listed vector passes, so it is a stale known failure and the run fails.
    assert status == 1 and "1 stale" in out, out
    assert ("plcvec: warning: PLCVEC_EXPECTATIONS is the old name of PLCVEC_KNOWN_FAILURES, read as it until "
            "plcvec 0.3.0; set PLCVEC_KNOWN_FAILURES instead") in out
    # Both set: the new name wins and the old one is said to be ignored.
    status, out = verify(monkeypatch, capsys, {"PLCVEC_FAMILY": "fx5-time-add", "PLCVEC_EXPECTATIONS": str(known),
                                               "PLCVEC_KNOWN_FAILURES": str(tmp_path / "none.toml")})
    assert status == 2 and "none.toml" in out, out
    assert ("plcvec: warning: PLCVEC_EXPECTATIONS is ignored: it is the old name of PLCVEC_KNOWN_FAILURES, "
            "which is set too") in out


@pytest.mark.parametrize("name, said", [
    ("PLCVEC_FAMLY", "PLCVEC_FAMLY is not a plcvec setting; did you mean PLCVEC_FAMILY?"),
    ("PLCVEC_KNOWN_FAILURE", "PLCVEC_KNOWN_FAILURE is not a plcvec setting; did you mean PLCVEC_KNOWN_FAILURES?"),
    # A misspelling of the old name points at the new one.
    ("PLCVEC_EXPECTATION", "PLCVEC_EXPECTATION is not a plcvec setting; did you mean PLCVEC_KNOWN_FAILURES?"),
    ("PLCVEC_COLOUR", "PLCVEC_COLOUR is not a plcvec setting; the settings are PLCVEC_VECTORS, PLCVEC_ID, "),
])
def test_a_variable_that_is_no_setting_is_named_with_the_nearest_setting(monkeypatch, capsys, name, said):
    status, out = verify(monkeypatch, capsys, {"PLCVEC_FAMILY": "fx5-time-add", name: "1"})
    assert status == 0, out                 # a warning, not an error: the run goes on
    assert f"plcvec: warning: {said}" in out


def test_the_names_plcvecs_own_tools_use_are_no_misspellings(monkeypatch, capsys):
    status, out = verify(monkeypatch, capsys, {"PLCVEC_FAMILY": "fx5-time-add", "PLCVEC_HOSTILE": "reference",
                                               "PLCVEC_TEST_ANYTHING": "1", "PLCVEC_CACHE_DIR": "/tmp"})
    assert status == 0 and "warning" not in out, out


RUNNER_SOURCES = {"c": ("src/*.c",), "go": ("*.go",), "java": ("library/src/main/java/**/*.java",),
                  "rust": ("src/*.rs",), "typescript": ("src/*.ts",), "python": ("plcvec_verify/*.py",)}


def test_the_timeout_bounds_are_written_once_in_the_table_and_generated_into_every_runner():
    """PLCVEC_TIMEOUT's default and largest bound live in plcvec_verify.settings; a runner that typed
    them itself could drift from the others, so no hand-written runner source holds the numbers."""
    from plcvec_verify import settings

    assert (settings.TIMEOUT_DEFAULT_S, settings.TIMEOUT_MAX_S) == (10, 86400)   # CONTRACT.md, "The environment"
    retyped = []
    for lang, globs in RUNNER_SOURCES.items():
        for pattern in globs:
            for path in (REPO / "verifiers" / lang).glob(pattern):
                text = path.read_text(encoding="utf-8")
                if path.name.endswith("_test.go") or path.name == "settings.py" or "plcvec export" in text[:300]:
                    continue   # the tests, the table itself, and what `plcvec export` wrote from it
                for number, line in enumerate(text.split("#[cfg(test)]")[0].splitlines(), 1):
                    if "86400" in line or "86_400" in line:
                        retyped.append(f"{path.relative_to(REPO)}:{number}")
    assert not retyped, retyped
