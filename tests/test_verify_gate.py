"""The CI gate cannot be passed by accident: reports anyone can read, names that exist, a selection
that is not empty, an implementation that does more than skip.
"""
import json
import os
import shlex
import stat
import subprocess
import sys

import pytest

from plcvec_reference.adapter import ReferenceAdapter
from plcvec_verify import InProcess, Selection, Suite, VerifyError, run
from plcvec_verify.command import main as verify_main
from plcvec_verify.gate import NOTHING_TESTED

from conftest import REPO

REFERENCE = ["--python", "plcvec_reference.adapter:ReferenceAdapter"]
FAULTY = REPO / "tests" / "adapters" / "faulty.py"
LAZY = REPO / "tests" / "adapters" / "lazy.py"


@pytest.mark.parametrize("umask", [0o022, 0o002, 0o077], ids=oct)
def test_reports_are_written_with_the_umask_like_any_other_file(tmp_path, umask):
    """A report made 0600 cannot be read by a CI uploader running as another user."""
    # wrong-shape on one vector: a failing run, so --write-expectations has something to write.
    vid = "fx5-time-add/TADD/manual-example/program"
    adapter = shlex.join([sys.executable, str(FAULTY), "wrong-shape", vid])
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


# -- names that do not exist are usage errors -------------------------------------------------

@pytest.fixture(scope="module")
def suite():
    return Suite.load(REPO / "vectors")


@pytest.fixture(scope="module")
def golden_files():
    """The vector files read directly, not through the verifier: where expected names come from."""
    manifest = json.loads((REPO / "vectors" / "manifest.json").read_text())
    return {family: json.loads((REPO / "vectors" / e["file"]).read_text()) for family, e in manifest["families"].items()}


@pytest.mark.parametrize("option, value, kind", [
    ("--family", "nope", "family"),
    ("--instruction", "TADX", "instruction"),
    ("--tag", "nosuchtag", "tag"),
    ("--interpretation", "NO-SUCH-READING", "interpretation"),
])
def test_an_unknown_name_is_a_usage_error_listing_the_known_ones(capsys, golden_files, option, value, kind):
    rc = verify_main([*REFERENCE, option, value, "--no-progress"])
    err = capsys.readouterr().err
    assert rc == 2, err
    assert f"{option} {value}: " in err and f"has no such {kind}; known: " in err
    known = {"family": set(golden_files),
             "instruction": {i for f in golden_files.values() for i in f["instructions"]},
             "tag": {t for f in golden_files.values() for t in f["tags"]},
             "interpretation": {i["id"] for f in golden_files.values() for i in f["interpretations"]}}[kind]
    listed = err.split("known: ", 1)[1].strip()
    assert all(name in listed for name in known), (known, listed)


def test_an_id_glob_that_matches_nothing_is_a_usage_error(capsys):
    rc = verify_main([*REFERENCE, "--id", "zzz*", "--no-progress"])
    err = capsys.readouterr().err
    assert rc == 2 and "--id zzz*: matches no vector id" in err
    # A glob that matches, with another filter that leaves nothing: an empty selection, not a usage error.
    assert verify_main([*REFERENCE, "--id", "fx5-time-add/*", "--tag", "nonexistent-date", "-q"]) == NOTHING_TESTED


def test_the_library_refuses_unknown_names_too(suite):
    with pytest.raises(VerifyError, match="--tag no-such-tag: .* has no such tag; known: .*boundary"):
        run(suite, InProcess(ReferenceAdapter()), Selection(tags=("no-such-tag",)))


# -- a run that tests nothing fails ----------------------------------------------------------

def test_an_empty_selection_exits_5_unless_allowed(capsys, golden_files):
    # Both names exist, but no fx5-time-add vector is an LDTM= vector.
    args = [*REFERENCE, "--family", "fx5-time-add", "--instruction", "LDTM=", "--no-progress"]
    assert "LDTM=" not in golden_files["fx5-time-add"]["instructions"]
    assert verify_main(args) == NOTHING_TESTED
    out, err = capsys.readouterr()
    assert "no vector selected" in err and "NOT PASSED (exit 5): no vector selected" in out
    assert verify_main([*args, "--allow-empty"]) == 0


def test_an_empty_vector_file_exits_5(tmp_path, golden_files, capsys):
    data = dict(golden_files["fx5-time-add"], vectors=[])
    path = tmp_path / "fx5-time-add.json"
    path.write_text(json.dumps(data))
    assert verify_main([*REFERENCE, "--vectors", str(path), "-q"]) == NOTHING_TESTED
    assert "no vector selected" in capsys.readouterr().err


@pytest.mark.parametrize("how", [
    ["--python", f"{LAZY}:SupportsNothing"],
    ["--python", f"{LAZY}:SkipsEverything"],
    ["--adapter", shlex.join([sys.executable, str(LAZY), "SkipsEverything"])],
], ids=["supports-nothing", "skips-everything", "skips-everything-as-a-process"])
def test_an_adapter_that_skips_everything_exits_5_and_says_so(tmp_path, capsys, golden_files, how):
    n = len(golden_files["fx5-time-add"]["vectors"])
    jsonl = tmp_path / "r.jsonl"
    rc = verify_main([*how, "--family", "fx5-time-add", "--no-progress", "--jsonl", str(jsonl)])
    out, err = capsys.readouterr()
    assert rc == NOTHING_TESTED, out + err
    assert f"SKIPPED {n} of {n} vectors (100.0%):" in out
    assert f"nothing passed ({n} skipped)" in err
    assert out.rstrip().endswith(f"{n} vectors: 0 pass, 0 fail, {n} skip" + out.rstrip().rsplit(" skip", 1)[1])
    summary = json.loads(jsonl.read_text().splitlines()[-1])
    assert summary["exit_code"] == NOTHING_TESTED and "nothing passed" in summary["shortfall"]
    assert verify_main([*how, "--family", "fx5-time-add", "-q", "--allow-empty"]) == 0


def test_max_skipped_as_a_count_and_as_a_share(capsys, golden_files):
    vectors = golden_files["fx5-time-add"]["vectors"]
    skipped = sum(v["instruction"] != "TADD" for v in vectors)   # OnlyTadd supports TADD alone
    assert 0 < skipped < len(vectors)
    share = 100 * skipped / len(vectors)
    assert share != int(share)
    base = ["--python", f"{LAZY}:OnlyTadd", "--family", "fx5-time-add", "-q"]
    assert verify_main(base) == 0                                          # no limit: skips are allowed
    assert verify_main([*base, "--max-skipped", str(skipped)]) == 0       # at the limit
    assert verify_main([*base, "--max-skipped", str(skipped - 1)]) == NOTHING_TESTED
    assert f"{skipped} of {len(vectors)} vectors skipped ({share:.1f}%), more than --max-skipped {skipped - 1}" \
        in capsys.readouterr().err
    assert verify_main([*base, "--max-skipped", f"{int(share) + 1}%"]) == 0
    assert verify_main([*base, "--max-skipped", f"{int(share)}%"]) == NOTHING_TESTED
    # --allow-empty does not lift a --max-skipped limit.
    assert verify_main([*base, "--max-skipped", "0", "--allow-empty"]) == NOTHING_TESTED


@pytest.mark.parametrize("value", ["many", "-1", "101%", "5.5"])
def test_a_bad_max_skipped_is_a_usage_error(capsys, value):
    assert verify_main([*REFERENCE, "--family", "fx5-time-add", "-q", "--max-skipped", value]) == 2
    assert "--max-skipped" in capsys.readouterr().err


def test_failures_outrank_a_shortfall(suite):
    """A run with an error exits 1, not 5, even though nothing in it passes."""
    family = Selection(families=("fx5-time-add",))
    one = family.apply(suite.vectors)[0]["id"]

    class ErrorsOnOneSkipsTheRest(ReferenceAdapter):
        def run(self, request):
            return {"error": "boom"} if request["id"] == one else {"skip": "later"}
    report = run(suite, InProcess(ErrorsOnOneSkipsTheRest()), family)
    assert report.counts["pass"] == 0 and report.shortfall and report.exit_code == 1


def test_help_documents_the_exit_statuses():
    proc = subprocess.run([sys.executable, "-m", "plcvec", "verify", "--help"], capture_output=True, text=True,
                          timeout=120)
    assert proc.returncode == 0
    assert "exit status:" in proc.stdout and f"  {NOTHING_TESTED}    nothing tested" in proc.stdout
    assert "--allow-empty" in proc.stdout and "--max-skipped" in proc.stdout
    contract = (REPO / "verifiers" / "CONTRACT.md").read_text()
    assert f"**{NOTHING_TESTED}** nothing tested" in contract


def test_every_test_the_fault_tables_name_exists():
    """PROTOCOL.md's fault tables name a test per row; a renamed or deleted test must not leave a
    row pointing at nothing."""
    import re

    text = (REPO / "verifiers" / "PROTOCOL.md").read_text()
    section = text[text.index("## What the runner does when an adapter misbehaves"):text.index("## Writing an adapter")]
    rows = [line for line in section.splitlines() if line.startswith("| ") and not line.startswith("| fault")
            and not line.startswith("| case") and not line.startswith("|---")]
    assert len(rows) > 20
    current = None
    for row in rows:
        cell = row.rstrip(" |").rsplit("|", 1)[1]
        names = re.findall(r"`([^`]+)`", cell)
        assert names, f"no test named in: {row}"
        for name in names:
            file, _, rest = name.partition("::")
            if file.startswith("…") or not rest:      # "…[mode]": the previous row's test
                file, rest = current[0], current[1] + name.lstrip("…")
            elif not file.endswith(".py"):
                file, rest = current[0], name.lstrip(":")
            test, _, params = rest.partition("[")
            source = (REPO / "tests" / file).read_text()
            assert f"def {test}(" in source, f"{file}::{test} (named in PROTOCOL.md) does not exist"
            for param in filter(None, params.rstrip("]").split(", ")):
                assert f'"{param}"' in source or f"signal.{param}" in source, f"{file}::{test}[{param}]"
            current = (file, test)


# -- vector files are checked against their schema when loaded ---------------------------------

def _damaged_file(tmp_path, damage):
    """A copy of fx5-time-add.json with `damage(data)` applied; returns its path and the vector id."""
    data = json.loads((REPO / "vectors" / "fx5-time-add.json").read_text())
    vid = damage(data)
    path = tmp_path / "fx5-time-add.json"
    path.write_text(json.dumps(data))
    return path, vid


def _word_70000(data):
    """A word of 70000 written by a step, consistently in `expect` and `final`, so that only the
    value is wrong (before validation this read as "the per-step changes do not add up")."""
    v = next(v for v in data["vectors"] if v["steps"][0]["expect"]["devices"])
    dev = next(d for d, x in sorted(v["steps"][0]["expect"]["devices"].items()) if type(x) is int)
    v["steps"][0]["expect"]["devices"][dev] = 70000
    v["final"]["devices"][dev] = 70000
    _word_70000.where = f"steps/0/expect/devices/{dev}"
    return v["id"]


def _extra_key(data):
    data["vectors"][3]["comment"] = "edited by hand"
    return data["vectors"][3]["id"]


def _bad_device_name(data):
    data["vectors"][4]["initial"]["devices"]["D-1"] = 0
    return data["vectors"][4]["id"]


@pytest.mark.parametrize("damage, where, message", [
    (_word_70000, None, "70000 is greater than the maximum of 65535"),
    (_extra_key, "(the vector)", "Additional properties are not allowed ('comment' was unexpected)"),
    (_bad_device_name, "initial/devices", "'D-1' does not match"),
], ids=["word-70000", "unknown-key", "bad-device-name"])
def test_a_value_the_schema_refuses_is_named_with_its_vector_and_path(tmp_path, damage, where, message):
    path, vid = _damaged_file(tmp_path, damage)
    with pytest.raises(VerifyError) as e:
        Suite.load(path)
    text = str(e.value)
    where = where or _word_70000.where
    assert f"{path}: does not match vector-file.schema.json" in text
    assert f"vector {vid}: at {where}: {message}" in text, text
    assert "do not add up" not in text


def test_a_schema_error_in_the_cli_exits_2_without_a_traceback(tmp_path):
    path, vid = _damaged_file(tmp_path, _word_70000)
    proc = subprocess.run([sys.executable, "-m", "plcvec", "verify", *REFERENCE, "--vectors", str(path)],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 2 and f"vector {vid}: at {_word_70000.where}: 70000 is greater" in proc.stderr
    assert "Traceback" not in proc.stderr


def test_the_header_is_checked_too(tmp_path):
    def bad_tags(data):
        data["tags"] = ["boundary"]          # a {tag: meaning} object in the schema
    path, _ = _damaged_file(tmp_path, bad_tags)
    with pytest.raises(VerifyError, match="header: at tags: .* is not of type 'object'"):
        Suite.load(path)


def test_a_file_is_validated_once_per_content(tmp_path, monkeypatch):
    """Validation costs far more than loading, so a valid file is remembered by its sha256: in the
    process and, for the next process, in the cache folder. Changed bytes are validated again; a
    file that fails is never remembered."""
    from plcvec_verify import validate

    monkeypatch.setenv("PLCVEC_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setattr(validate, "_VALID", set())
    validations = []
    real = validate._against_schema
    monkeypatch.setattr(validate, "_against_schema", lambda *args: validations.append(1) or real(*args))
    # A family file cut to its first vectors: what is remembered is the same, validating it is quicker.
    data = json.loads((REPO / "vectors" / "fx5-time-add.json").read_text(encoding="utf-8"))
    data["vectors"] = data["vectors"][:25]
    data["count"] = len(data["vectors"])
    path = tmp_path / "fx5-time-add.json"
    path.write_text(json.dumps(data, indent=2), encoding="utf-8")

    Suite.load(path)
    Suite.load(path)
    assert len(validations) == 1
    validate._VALID.clear()                  # as in a new process: only the cache folder is left
    Suite.load(path)
    assert len(validations) == 1 and len(list((tmp_path / "cache").rglob("*"))) == 2   # folder + marker
    path.write_bytes(path.read_bytes() + b"\n")
    Suite.load(path)
    assert len(validations) == 2

    (tmp_path / "bad").mkdir()
    bad = tmp_path / "bad" / path.name
    _bad_device_name(data)                   # vector 4, within the cut
    bad.write_text(json.dumps(data), encoding="utf-8")
    for _ in range(2):
        with pytest.raises(VerifyError, match="'D-1' does not match"):
            Suite.load(bad)
    assert len(validations) == 4


def test_without_a_schema_the_file_is_refused(tmp_path, monkeypatch):
    from plcvec_verify import locate

    def nowhere():
        raise VerifyError("no vector folder")
    monkeypatch.setattr(locate, "default_vectors", nowhere)
    path = tmp_path / "fx5-time-add.json"
    path.write_bytes((REPO / "vectors" / "fx5-time-add.json").read_bytes())
    with pytest.raises(VerifyError, match=f"{path}: no vector-file.schema.json to check it against"):
        Suite.load(path)
