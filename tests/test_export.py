"""`plcvec export`: names, literals, the JSON Lines copy, rendering, --check and stale files."""
import json
import os
import shutil
import subprocess
import textwrap

import pytest

from plcvec.cli import main
from plcvec.export import names, targets
from plcvec.export.literals import c_str, go_str, java_str, rust_str, ts_str
from plcvec.export.model import load_model


# -- identifiers ----------------------------------------------------------------------------------

@pytest.mark.parametrize("text, words", [
    ("LDTM<=", ["LDTM", "LE"]),            # the FX5 manual's own ST name is LDTM_LE
    ("ORDT<>", ["ORDT", "NE"]),
    ("ANDTM>=", ["ANDTM", "GE"]),
    ("LD <DT", ["LD", "LT", "DT"]),
    ("OR =DT", ["OR", "EQ", "DT"]),
    ("FX5-SM709-SCOPE", ["FX5", "SM709", "SCOPE"]),
    ("manual-example", ["manual", "example"]),
])
def test_identifier_words(text, words):
    assert names.identifier_words(text) == words


def test_identifier_styles():
    words = names.identifier_words("FX5-SM709-SCOPE")
    assert names.upper_snake(words) == "FX5_SM709_SCOPE"
    assert names.lower_snake(words) == "fx5_sm709_scope"
    assert names.pascal(words) == "Fx5Sm709Scope"
    assert names.camel(words) == "fx5Sm709Scope"
    assert names.upper_snake("24-hour") == "_24_HOUR"      # no identifier starts with a digit
    with pytest.raises(ValueError):
        names.identifier_words("--")


def test_digest_depends_on_the_content_alone():
    assert names.digest("a|b") == names.digest("a|b") != names.digest("a|c")
    assert len(names.digest("x")) == 8 and len(names.digest("x", 12)) == 12
    assert names.digest("abc") == "ba7816bf"          # the first 8 hex digits of SHA-256("abc")


def test_every_exported_name_is_distinct_in_every_style(repo):
    """Two spec names that collapse to one identifier would make a generated enum fail to compile."""
    model = load_model(repo / "vectors")
    groups = {"instructions": model.instructions, "tags": model.tags,
              "interpretations": [i.name for i in model.interpretations],
              "families": [f.name for f in model.families], "devices": model.devices}
    groups.update({f"clauses of {f.name.text}": f.clauses for f in model.families})
    groups.update({f"alternatives of {i.name.text}": i.alternatives for i in model.interpretations})
    for what, group in groups.items():
        for style in (names.upper_snake, names.pascal, names.lower_snake):
            idents = [style(n) for n in group]
            assert len(set(idents)) == len(idents), (what, style.__name__, idents)


# -- string literals, read back by each language's own compiler -----------------------------------

TRICKY = 'a"b\\c\n\t\r??=?\x01 é ≤ □ 😀 \u2028 end'
TOOLS = {"c": "gcc", "go": "go", "rust": "rustc", "java": "javac", "ts": "node"}


def _need(tool):
    if shutil.which(tool) is None:
        if os.environ.get("CI"):
            pytest.fail(f"{tool} is not installed, and CI must run this test")
        pytest.skip(f"{tool} is not installed")


def _run(cmd, cwd):
    proc = subprocess.run(cmd, cwd=cwd, capture_output=True, timeout=300)
    assert proc.returncode == 0, proc.stderr.decode(errors="replace")
    return proc.stdout


@pytest.mark.parametrize("lang", sorted(TOOLS))
def test_literal_reads_back_exactly(lang, tmp_path):
    """Each quoting, compiled and printed as UTF-8 bytes, gives back exactly the original text."""
    _need(TOOLS[lang])
    expected = TRICKY.encode("utf-8")
    if lang == "c":
        (tmp_path / "t.c").write_text(textwrap.dedent(f"""
            #include <stdio.h>
            #include <string.h>
            static const char s[] = {c_str(TRICKY)};
            int main(void) {{ fwrite(s, 1, strlen(s), stdout); return 0; }}
        """))
        _run(["gcc", "-std=c11", "-Wall", "-Werror", "-trigraphs", "-o", "t", "t.c"], tmp_path)
        out = _run(["./t"], tmp_path)
    elif lang == "go":
        (tmp_path / "t.go").write_text(f'package main\nimport "os"\nfunc main() {{ os.Stdout.WriteString({go_str(TRICKY)}) }}\n')
        out = _run(["go", "run", "t.go"], tmp_path)
    elif lang == "rust":
        (tmp_path / "t.rs").write_text(f'use std::io::Write;\nfn main() {{ std::io::stdout().write_all({rust_str(TRICKY)}.as_bytes()).unwrap(); }}\n')
        _run(["rustc", "-o", "t", "t.rs"], tmp_path)
        out = _run(["./t"], tmp_path)
    elif lang == "java":
        (tmp_path / "T.java").write_text(
            "public class T { public static void main(String[] a) throws Exception {"
            f" System.out.write({java_str(TRICKY)}.getBytes(java.nio.charset.StandardCharsets.UTF_8)); System.out.flush(); }} }}\n")
        _run(["javac", "T.java"], tmp_path)
        out = _run(["java", "-cp", ".", "T"], tmp_path)
    else:
        (tmp_path / "t.mjs").write_text(f"process.stdout.write(Buffer.from({ts_str(TRICKY)}, 'utf8'));\n")
        out = _run(["node", "t.mjs"], tmp_path)
    assert out == expected


# -- the model and the JSON Lines copy ------------------------------------------------------------

def test_jsonl_copy_holds_every_vector_unchanged(repo, golden):
    model = load_model(repo / "vectors")
    assert [f.name.text for f in model.families] == list(golden)
    for fam in model.families:
        lines = fam.jsonl.splitlines()
        header = json.loads(lines[0])
        original = golden[fam.name.text]
        assert header == {k: v for k, v in original.items() if k != "vectors"}
        assert [json.loads(line) for line in lines[1:]] == original["vectors"]
        assert header["count"] == len(lines) - 1


def test_devices_and_clauses_are_every_one_the_vectors_name(repo, golden):
    model = load_model(repo / "vectors")
    named = set()
    for data in golden.values():
        for v in data["vectors"]:
            named.update(v["initial"]["devices"])
            named.update(o["device"] for o in v["initial"]["operands"].values() if "device" in o)
            named.update(d for alt in v.get("alternatives", ()) for d in alt["final"]["devices"])
    assert {"D100", "SM709", "P_ER", "M8004"} <= named
    assert [d.text for d in model.devices] == sorted(named)
    for fam in model.families:
        used = {c for v in golden[fam.name.text]["vectors"] for c in v["clauses"]}
        assert [c.text for c in fam.clauses] == sorted(used)


def test_shared_interpretation_is_listed_once(repo, golden):
    model = load_model(repo / "vectors")
    ids = [i.name.text for i in model.interpretations]
    assert len(ids) == len(set(ids))
    expected = {i["id"]: sorted(f for f, data in golden.items() if any(j["id"] == i["id"] for j in data["interpretations"]))
                for data in golden.values() for i in data["interpretations"]}
    assert {i.name.text: sorted(i.families) for i in model.interpretations} == expected


# -- rendering and the command ---------------------------------------------------------------------

@pytest.fixture
def toy_language(tmp_path, monkeypatch):
    """A language of two templates, in a template folder of its own."""
    templates = tmp_path / "templates"
    lang = templates / "toy"
    lang.mkdir(parents=True)
    (lang / "export.yaml").write_text(textwrap.dedent("""
        root: verifiers/toy
        vectors: vectors
        generated: [gen]
        files:
          - {template: names.j2, output: gen/names.txt}
          - {template: family.j2, output: "gen/{family}.txt", each: family}
    """))
    (lang / "names.j2").write_text(
        "// {{ note }}\n{% for i in suite.instructions %}{{ i | upper_snake }} = {{ i.text | c_str }}\n{% endfor %}")
    (lang / "family.j2").write_text("{{ family.name | pascal }} {{ family.vectors | length }}\n")
    monkeypatch.setattr(targets, "TEMPLATES", templates)
    # The contract every export writes its reference tables into, between their markers.
    contract = tmp_path / "out" / "verifiers" / "CONTRACT.md"
    contract.parent.mkdir(parents=True)
    contract.write_text("# Contract\n\n<!-- plcvec:reference-tables -->\n<!-- /plcvec:reference-tables -->\nEnd.\n")
    return tmp_path / "out"


def test_export_writes_checks_and_removes_stale_files(repo, golden, toy_language, capsys):
    out = toy_language
    args = ["export", "--lang", "toy", "--vectors", str(repo / "vectors"), "--root", str(out)]
    assert main(args + ["--check"]) == 1                      # nothing there yet
    assert main(args) == 0
    names_txt = (out / "verifiers/toy/gen/names.txt").read_text()
    assert "LDTM_LE = \"LDTM<=\"" in names_txt and "LD_LE_DT = \"LD <=DT\"" in names_txt
    for fam, data in golden.items():
        assert (out / f"verifiers/toy/gen/{fam}.txt").read_text().split()[1] == str(len(data["vectors"]))
        assert (out / f"verifiers/toy/vectors/{fam}.jsonl").is_file()
    index = json.loads((out / "verifiers/toy/vectors/index.json").read_text())
    assert index["total"] == sum(len(d["vectors"]) for d in golden.values())
    assert main(args + ["--check"]) == 0
    capsys.readouterr()

    (out / "verifiers/toy/gen/names.txt").write_text("edited by hand\n")
    (out / "verifiers/toy/gen/old.txt").write_text("left from a family that is gone\n")
    assert main(args + ["--check"]) == 1
    err = capsys.readouterr().err
    assert "gen/names.txt: differs" in err and "gen/old.txt: not produced by the export" in err
    assert main(args) == 0
    assert not (out / "verifiers/toy/gen/old.txt").exists()
    assert main(args + ["--check"]) == 0


def test_export_is_byte_identical_across_runs(repo, toy_language):
    model = load_model(repo / "vectors")
    assert targets.render("toy", model).files == targets.render("toy", load_model(repo / "vectors")).files


def test_template_error_names_template_and_line(repo, toy_language, capsys):
    (targets.TEMPLATES / "toy" / "family.j2").write_text("line one\n{{ family.no_such_field }}\n")
    assert main(["export", "--lang", "toy", "--vectors", str(repo / "vectors"), "--root", str(toy_language)]) == 2
    err = capsys.readouterr().err
    assert "family.j2:2" in err and "no_such_field" in err


def test_unknown_language_is_a_usage_error(repo, toy_language, capsys):
    assert main(["export", "--lang", "cobol", "--vectors", str(repo / "vectors"), "--root", str(toy_language)]) == 2
    assert "cobol: no such language (known: toy)" in capsys.readouterr().err


def test_missing_vector_folder_is_named(tmp_path, toy_language, capsys):
    assert main(["export", "--lang", "toy", "--vectors", str(tmp_path / "nope"), "--root", str(toy_language)]) == 2
    assert "nope: no such vector folder" in capsys.readouterr().err


# -- the vector folder is refused as `plcvec verify` refuses it -------------------------------------

def _damaged_copy(repo, tmp_path, damage):
    """A copy of the golden folder with one damage to fx5-time-add.json (resealed in manifest.json,
    its sha256 and count, unless the damage is the seal itself)."""
    import hashlib

    folder = tmp_path / "vectors"
    shutil.copytree(repo / "vectors", folder)
    path = folder / "fx5-time-add.json"
    data = json.loads(path.read_text(encoding="utf-8"))
    target = next(v for v in data["vectors"] if v["id"] == "fx5-time-add/TADD/manual-example/program")
    if damage == "duplicate-id":
        data["vectors"].insert(data["vectors"].index(target) + 1, json.loads(json.dumps(target)))
    elif damage == "unknown-key":
        target["surprise"] = 1
    elif damage == "bit-holds-2":
        bit = next(d for d, v in target["initial"]["devices"].items() if v is False or v is True)
        target["initial"]["devices"][bit] = 2
    elif damage == "major-version":
        data["schema_version"] = "2.0.0"
    path.write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    manifest = json.loads((folder / "manifest.json").read_text())
    entry = manifest["families"]["fx5-time-add"]
    entry["sha256"] = "0" * 64 if damage == "sha-mismatch" else hashlib.sha256(path.read_bytes()).hexdigest()
    if "count" in entry:
        entry["count"] = len(data["vectors"])
    (folder / "manifest.json").write_text(json.dumps(manifest, indent=1))
    return folder


@pytest.mark.parametrize("damage, says", [
    ("duplicate-id", "vector id fx5-time-add/TADD/manual-example/program appears twice"),
    ("unknown-key", "'surprise' was unexpected"),
    # Refused by the loader's own device-type check, or (when the validity cache already knows the
    # file's bytes) by export's: either way the vector and the device are named.
    ("bit-holds-2", ("vector fx5-time-add/TADD/manual-example/program:", "SM700", "holds 2")),
    ("major-version", "fx5-time-add.json: schema_version 2.0.0 is not 1.x"),
    ("sha-mismatch", "fx5-time-add.json: its sha256 is not the one manifest.json records"),
])
def test_export_refuses_a_damaged_folder_and_writes_nothing(repo, tmp_path, toy_language, damage, says, capsys):
    folder = _damaged_copy(repo, tmp_path, damage)
    assert main(["export", "--lang", "toy", "--vectors", str(folder), "--root", str(toy_language)]) == 2
    captured = capsys.readouterr()
    for part in (says,) if isinstance(says, str) else says:
        assert part in captured.err
    assert "Traceback" not in captured.err
    # Nothing half-written: the root holds only the contract the fixture put there, unchanged.
    assert [p for p in toy_language.rglob("*") if p.is_file()] == [toy_language / "verifiers" / "CONTRACT.md"]
    assert (toy_language / "verifiers" / "CONTRACT.md").read_text().endswith("-->\n<!-- /plcvec:reference-tables -->\nEnd.\n")


def test_device_types_problem_names_both_places():
    from plcvec.export.validate import device_types_problem

    vector = {"initial": {"devices": {"SM700": 2, "D0": 5}}, "steps": [{"expect": {"devices": {"D0": 6}}}],
              "final": {"devices": {"SM700": False, "D0": 6}}}
    assert device_types_problem(vector) == ("SM700 is a word in initial (2) and a bit in final (false): a device "
                                            "holds one type throughout a vector")
    vector["initial"]["devices"]["SM700"] = True
    assert device_types_problem(vector) == ""
