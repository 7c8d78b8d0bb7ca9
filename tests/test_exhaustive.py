"""The exhaustive tier: complete, well-formed, and in agreement with the golden builder."""
import json

import jsonschema
import pytest

from plcvec.cases.build import VectorBuilder
from plcvec.output.exhaustive import stream_exhaustive


@pytest.fixture(scope="module")
def cp1e_tier(families, tmp_path_factory):
    """The whole exhaustive tier of cp1e-time-compare under the default choices: (count, file)."""
    out = tmp_path_factory.mktemp("exhaustive")
    count, _ = stream_exhaustive([families["cp1e-time-compare"]], out)
    return count, out / "cp1e-time-compare.exhaustive.jsonl"


def test_every_selector_value_for_every_condition(families, repo, cp1e_tier):
    fam = families["cp1e-time-compare"]
    count, path = cp1e_tier
    assert count == 65536 * 6
    schema = json.loads((repo / "vectors" / "schema" / "vector-file.schema.json").read_text())
    validator = jsonschema.Draft202012Validator(schema["$defs"]["vector"])
    builder = VectorBuilder(fam)
    ids, sampled, prefix = set(), 0, '{"id": "'
    with open(path, encoding="utf-8") as lines:
        header = json.loads(next(lines))
        assert header["choices"] == fam.default_choices()
        for n, line in enumerate(lines):
            assert line.startswith(prefix) and line.endswith("}\n"), n
            vid = line[len(prefix):line.index('"', len(prefix))]
            ids.add(vid)
            if n % 997:
                continue
            # A spread sample, checked against the builder that makes the golden set.
            v = json.loads(line)
            # Text as the canonical writer gives it (keys inside values sorted, ", " and ": "),
            # nothing left of the templates the lines are built from.
            assert json.dumps(v, ensure_ascii=False, separators=(", ", ": ")) + "\n" == line, vid
            validator.validate(v)
            assert v["id"] == vid
            instr = builder.instructions[v["instruction"]]
            expects, final, outcome, _ = builder.run(instr, v["initial"]["operands"], v["initial"]["devices"],
                                                     [{k: s[k] for k in s if k != "expect"} for s in v["steps"]], (),
                                                     fam.default_choices())
            assert [s["expect"] for s in v["steps"]] == expects, v["id"]
            assert v["final"]["devices"] == final and v["outcome"] == outcome, v["id"]
            sampled += 1
    assert n + 1 == count and len(ids) == count and sampled == count // 997 + 1


def test_a_slice_of_selector_values_is_those_lines_of_the_whole_tier(families, tmp_path, cp1e_tier):
    _, whole = cp1e_tier
    wanted = [0x0000, 0x0011, 0x003F, 0x0040, 0xFFFF]
    stream_exhaustive([families["cp1e-time-compare"]], tmp_path, selectors=wanted)
    part = (tmp_path / "cp1e-time-compare.exhaustive.jsonl").read_text(encoding="utf-8").splitlines(keepends=True)
    with open(whole, encoding="utf-8") as lines:
        expected = [next(lines)] + [line for n, line in enumerate(lines) if n // 6 in wanted]
    assert part == expected


def test_choose_changes_the_expectations(families, tmp_path):
    fam = families["cp1e-time-compare"]
    # C = 003FH masks all six fields: an error by default, equal data under the alternative.
    stream_exhaustive([fam], tmp_path / "a", selectors=[0x003F])
    stream_exhaustive([fam], tmp_path / "b", choices={"CP1E-ALL-MASKED": "equal"}, selectors=[0x003F])
    a = (tmp_path / "a" / "cp1e-time-compare.exhaustive.jsonl").read_text().splitlines()
    b = (tmp_path / "b" / "cp1e-time-compare.exhaustive.jsonl").read_text().splitlines()
    assert json.loads(a[0])["choices"]["CP1E-ALL-MASKED"] == "error"
    assert json.loads(b[0])["choices"]["CP1E-ALL-MASKED"] == "equal"
    line = next(i for i, l in enumerate(a) if '"id": "cp1e-time-compare/LD =DT/exhaustive/003FH"' in l)
    assert json.loads(a[line])["outcome"]["category"] == "error"
    assert json.loads(b[line])["steps"][0]["expect"]["result"] is True


def test_bad_choice_is_a_clear_error(capsys):
    from plcvec import cli

    assert cli.main(["exhaustive", "--out", "/nonexistent-never-written", "--choose", "CP1E-ALL-MASKED=maybe"]) == 2
    err = capsys.readouterr().err
    assert "CP1E-ALL-MASKED has no alternative 'maybe'" in err and "Traceback" not in err
