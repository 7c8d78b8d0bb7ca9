"""The committed vector set: schema, manifest, ids, determinism, drift check, atomic writing."""
import hashlib
import json
import os
import subprocess
import sys

import pytest

from plcvec.output.golden import family_vectors
from plcvec.spec.loader import load_spec


def test_every_file_matches_the_vector_schema(repo, golden):
    """Each family file against the vector-file schema (Draft 2020-12, as its `$schema` says), through
    the check `Suite.load` makes: it names the vector and field of every error, and it validates a
    file once per content (sha256 of the file and of the schema), which the loads of the same files
    elsewhere in the session share, instead of a second full pass of jsonschema here."""
    from plcvec_verify.errors import VerifyError
    from plcvec_verify.validate import validate_file

    schema = repo / "vectors" / "schema" / "vector-file.schema.json"
    assert json.loads(schema.read_text())["$schema"] == "https://json-schema.org/draft/2020-12/schema"
    assert set(golden) == {p.stem for p in (repo / "vectors").glob("*.json")} - {"manifest"}
    for family in golden:
        path = repo / "vectors" / f"{family}.json"
        raw = path.read_bytes()
        try:
            validate_file(path, raw, json.loads(raw), schema)
        except VerifyError as exc:
            pytest.fail(str(exc), pytrace=False)


def test_manifest_counts_and_hashes(repo, golden):
    manifest = json.loads((repo / "vectors" / "manifest.json").read_text())
    for family, entry in manifest["families"].items():
        data = (repo / "vectors" / entry["file"]).read_bytes()
        assert hashlib.sha256(data).hexdigest() == entry["sha256"]
        assert entry["count"] == len(golden[family]["vectors"]) == golden[family]["count"]
    assert manifest["total"] == sum(len(d["vectors"]) for d in golden.values())


def test_ids_unique_and_sorted(all_vectors, golden):
    ids = [v["id"] for v in all_vectors]
    assert len(ids) == len(set(ids))
    for doc in golden.values():
        family_ids = [v["id"] for v in doc["vectors"]]
        assert family_ids == sorted(family_ids)


def test_instruction_coverage(golden):
    """18 + 18 comparison instructions, TADD and TADDP, HOUR, 18 CP1E instructions."""
    counts = {f: len(d["instructions"]) for f, d in golden.items()}
    assert counts == {"fx5-time-compare": 18, "fx5-date-compare": 18, "fx5-time-add": 2, "fc6a-hour-meter": 1, "cp1e-time-compare": 18}


def test_interpretation_vectors_carry_every_alternative(golden):
    for doc in golden.values():
        alts = {i["id"]: [a["id"] for a in i["alternatives"]] for i in doc["interpretations"]}
        defaults = {i["id"]: i["default"] for i in doc["interpretations"]}
        for v in doc["vectors"]:
            if v["outcome"]["category"] != "implementation-defined":
                assert "alternatives" not in v
                continue
            touched = v["outcome"]["interpretations"]
            combos = {tuple(sorted(a["choices"].items())) for a in v["alternatives"]}
            expected = 1
            for t in touched:
                expected *= len(alts[t])
            assert len(combos) == expected - 1, v["id"]  # every combination but the all-default one
            for a in v["alternatives"]:
                assert set(a["choices"]) == set(touched)
                assert any(a["choices"][t] != defaults[t] for t in touched)


def test_every_interpretation_affects_some_vector(golden):
    for doc in golden.values():
        touched = {i for v in doc["vectors"] if "alternatives" in v for i in v["outcome"]["interpretations"]}
        assert touched == {i["id"] for i in doc["interpretations"]}, doc["family"]


def test_generated_output_is_what_is_committed(repo, generated):
    files, _ = generated
    assert set(files) == {p.name for p in (repo / "vectors").iterdir() if p.is_file()}
    for name, text in files.items():
        assert (repo / "vectors" / name).read_text() == text, f"vectors/{name} is stale: run plcvec generate"


def test_byte_identical_across_hash_seeds(repo, tmp_path, generated):
    """`plcvec generate` under a fixed hash seed writes what this process generated under its own."""
    seed = "12345" if os.environ.get("PYTHONHASHSEED") != "12345" else "54321"   # another seed than ours
    out = tmp_path / seed
    env = dict(os.environ, PYTHONHASHSEED=seed)
    subprocess.run([sys.executable, "-m", "plcvec", "generate", "--out", str(out)], check=True, env=env, capture_output=True)
    assert {p.name: p.read_bytes() for p in out.iterdir()} == {name: text.encode() for name, text in generated[0].items()}


def write_generated(generated, out):
    """The session's golden set written into `out`, as `plcvec generate` writes it."""
    out.mkdir(parents=True)
    for name, text in generated[0].items():
        (out / name).write_text(text, encoding="utf-8")


def test_check_names_the_drifted_file(repo, tmp_path, generated):
    out = tmp_path / "v"
    write_generated(generated, out)
    ok = subprocess.run([sys.executable, "-m", "plcvec", "generate", "--check", "--out", str(out)], capture_output=True, text=True)
    assert ok.returncode == 0
    target = out / "fx5-time-add.json"
    original = target.read_text()
    target.write_text(original.replace('"SM8020": false', '"SM8020": true', 1))
    assert target.read_text() != original  # one expectation really changed
    (out / "leftover.json").write_text("{}")
    bad = subprocess.run([sys.executable, "-m", "plcvec", "generate", "--check", "--out", str(out)], capture_output=True, text=True)
    assert bad.returncode == 1
    assert "fx5-time-add.json: differs" in bad.stderr and "leftover.json" in bad.stderr
    assert "cp1e-time-compare.json" not in bad.stderr


def test_interrupted_generate_leaves_previous_files_intact(repo, tmp_path, monkeypatch, generated):
    from plcvec import cli
    from plcvec.output import atomic

    out = tmp_path / "v"
    write_generated(generated, out)
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    for p in out.glob("*.json"):  # make every file differ so generate must rewrite each
        p.write_bytes(p.read_bytes() + b" ")
    stale = {p.name: p.read_bytes() for p in out.iterdir()}
    real_replace, calls = os.replace, []

    def failing_replace(src, dst):
        calls.append(dst)
        if len(calls) == 2:
            raise KeyboardInterrupt  # the user presses ^C in the middle of the second file
        real_replace(src, dst)

    monkeypatch.setattr(atomic.os, "replace", failing_replace)
    assert cli.main(["generate", "--out", str(out)]) == 130
    after = {p.name: p.read_bytes() for p in out.iterdir()}
    assert set(after) == set(before)  # no temporary file left behind
    for name, data in after.items():
        assert data in (before[name], stale[name]), f"{name} is neither the old nor the new file"
    assert after["manifest.json"] == stale["manifest.json"]  # the manifest is written last


def test_ids_do_not_change_when_vectors_are_added(repo, tmp_path, generated):
    """Adding cases (more random draws, another nonexistent date) renames nothing and changes nothing else."""
    import shutil

    spec = tmp_path / "spec"
    shutil.copytree(repo / "spec", spec)
    date = spec / "fx5-date-compare.yaml"
    text = date.read_text()
    text = text.replace("    - {year: 2025, month: 11, day: 31}\n", "    - {year: 2025, month: 11, day: 31}\n    - {year: 2031, month: 2, day: 29}\n")
    text = text.replace("random_examples: 120", "random_examples: 160")
    date.write_text(text)
    _, old = generated
    (edited,) = [f for f in load_spec(spec) if f.name == "fx5-date-compare"]
    old_v = {v["id"]: v for v in old["fx5-date-compare"]}
    new_v = {v["id"]: v for v in family_vectors(edited)}
    assert set(old_v) < set(new_v)
    assert any("2031-2-29" in i for i in set(new_v) - set(old_v))
    for vid, v in old_v.items():
        assert new_v[vid] == v, vid


@pytest.mark.parametrize("needle", ["random/", "boundary/", "selector/"])
def test_ids_say_what_they_test(all_vectors, needle):
    assert any(needle in v["id"] for v in all_vectors)
