"""Each instruction's family, form, condition and execution as values in the export model.

The expectations are read off the manual pages by hand, not from the spec or the model: the FX5
pages name the forms "LDTM□, ANDTM□, ORTM□" with "=", "<>", ">", "<=", "<", ">=" entering □; the
CP1E page lists =DT … >=DT, used as LD, AND and OR; TADDP is TADD's pulse form; HOUR measures while
its input is on, each scan.
"""
import json
import shutil

import pytest

from plcvec.cli import main
from plcvec.errors import PlcvecError
from plcvec.export.model import load_model

SYMBOLS = ["=", "<>", ">", "<=", "<", ">="]            # as the FX5 pages list them
FORMS = {"LD": "LD", "AND": "AND", "OR": "OR"}


def _expected():
    """{instruction name: (family, form, condition, execution)} written from the pages."""
    out = {}
    for family, stem in (("fx5-time-compare", "TM"), ("fx5-date-compare", "DT")):
        for form in FORMS:
            for symbol in SYMBOLS:
                out[f"{form}{stem}{symbol}"] = (family, form, symbol, "every-scan")
    for form in FORMS:
        for symbol in SYMBOLS:
            out[f"{form} {symbol}DT"] = ("cp1e-time-compare", form, symbol, "every-scan")
    out["TADD"] = ("fx5-time-add", None, None, "every-scan")
    out["TADDP"] = ("fx5-time-add", None, None, "rising-edge")
    out["HOUR"] = ("fc6a-hour-meter", None, None, "every-scan")
    return out


@pytest.fixture(scope="module")
def model(repo):
    return load_model(repo / "vectors", repo / "spec")


def test_every_instruction_has_the_metadata_the_pages_give(model):
    got = {i.text: (i.family, i.form, i.condition, i.execution) for i in model.instructions}
    assert got == _expected()


def test_family_instructions_carry_their_family(model):
    for fam in model.families:
        assert {i.family for i in fam.instructions} == {fam.name.text}


def test_structured_text_spellings(model):
    st = {i.text: i.st for i in model.instructions}
    # FX5: "ENO:=LDTM_□(EN,s1,s2,s3);" with "EQ", "NE", "GT", "LE", "LT", "GE" entering □.
    assert st["LDTM<="] == "LDTM_LE" and st["ORDT<>"] == "ORDT_NE" and st["ANDTM>="] == "ANDTM_GE"
    assert st["TADDP"] == "TADDP" and st["TADD"] == "TADD"     # "ENO:=TADDP(EN,s1,s2,d);"
    assert st["HOUR"] == ""                                     # the HOUR page gives no ST form


def test_value_lists_for_templates(model):
    assert [n.text for n in model.forms] == ["LD", "AND", "OR"]
    assert [n.text for n in model.conditions] == ["=", "<>", "<", "<=", ">", ">="]
    assert [n.text for n in model.executions] == ["every-scan", "rising-edge"]
    assert [n.words for n in model.conditions] == [["EQ"], ["NE"], ["LT"], ["LE"], ["GT"], ["GE"]]


def test_vectors_from_another_spec_are_refused(repo, tmp_path):
    vectors = tmp_path / "vectors"
    shutil.copytree(repo / "vectors", vectors)
    path = vectors / "fx5-time-add.json"
    data = json.loads(path.read_text())
    data["spec_sha256"] = "0" * 64
    path.write_text(json.dumps(data))
    with pytest.raises(PlcvecError, match=r"fx5-time-add\.json: generated from another spec"):
        load_model(vectors, repo / "spec")
    assert main(["export", "--lang", "go", "--check", "--vectors", str(vectors), "--root", str(tmp_path)]) == 2


def test_a_condition_that_is_no_comparison_is_an_error(repo, tmp_path):
    spec = tmp_path / "spec"
    shutil.copytree(repo / "spec", spec)
    path = spec / "fx5-time-compare.yaml"
    path.write_text(path.read_text().replace('{symbol: "<=", st: LE, true_when: [lt, eq]',
                                             '{symbol: "<=", st: LE, true_when: [lt, eq, gt]', 1))
    from plcvec.export.model import instruction_metadata
    from plcvec.spec.loader import load_family

    with pytest.raises(PlcvecError, match="none of the six comparisons"):
        instruction_metadata(load_family(path))
