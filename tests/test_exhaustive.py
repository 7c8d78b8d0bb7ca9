"""The exhaustive tier: complete, well-formed, and in agreement with the golden builder."""
import json

import jsonschema

from plcvec.cases.build import VectorBuilder
from plcvec.output.exhaustive import stream_exhaustive


def test_every_selector_value_for_every_condition(families, repo, tmp_path):
    fam = families["cp1e-time-compare"]
    count, _ = stream_exhaustive([fam], tmp_path)
    assert count == 65536 * 6
    lines = (tmp_path / "cp1e-time-compare.exhaustive.jsonl").read_text().splitlines()
    header = json.loads(lines[0])
    assert header["choices"] == fam.default_choices()
    schema = json.loads((repo / "vectors" / "schema" / "vector-file.schema.json").read_text())
    validator = jsonschema.Draft202012Validator(schema["$defs"]["vector"])
    builder = VectorBuilder(fam)
    ids = set()
    for line in lines[1::997]:  # a spread sample, checked against the builder that makes the golden set
        v = json.loads(line)
        validator.validate(v)
        ids.add(v["id"])
        instr = builder.instructions[v["instruction"]]
        expects, final, outcome, _ = builder.run(instr, v["initial"]["operands"], v["initial"]["devices"],
                                                 [{k: s[k] for k in s if k != "expect"} for s in v["steps"]], (), fam.default_choices())
        assert [s["expect"] for s in v["steps"]] == expects, v["id"]
        assert v["final"]["devices"] == final and v["outcome"] == outcome, v["id"]
    all_ids = {json.loads(line)["id"] for line in lines[1:]}
    assert len(all_ids) == count


def test_choose_changes_the_expectations(families, tmp_path):
    fam = families["cp1e-time-compare"]
    stream_exhaustive([fam], tmp_path / "a")
    stream_exhaustive([fam], tmp_path / "b", choices={"CP1E-ALL-MASKED": "equal"})
    a = (tmp_path / "a" / "cp1e-time-compare.exhaustive.jsonl").read_text().splitlines()
    b = (tmp_path / "b" / "cp1e-time-compare.exhaustive.jsonl").read_text().splitlines()
    # C = 003FH masks all six fields: an error by default, equal data under the alternative.
    line = next(i for i, l in enumerate(a) if '"id": "cp1e-time-compare/LD =DT/exhaustive/003FH"' in l)
    assert json.loads(a[line])["outcome"]["category"] == "error"
    assert json.loads(b[line])["steps"][0]["expect"]["result"] is True


def test_bad_choice_is_a_clear_error(capsys):
    from plcvec import cli

    assert cli.main(["exhaustive", "--out", "/nonexistent-never-written", "--choose", "CP1E-ALL-MASKED=maybe"]) == 2
    err = capsys.readouterr().err
    assert "CP1E-ALL-MASKED has no alternative 'maybe'" in err and "Traceback" not in err
