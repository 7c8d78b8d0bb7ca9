"""Every fact traceable: page quotes, citations of other documents, and claims marked derived.

The claims the pages do not state are named by hand here (the field order of multi-field comparison,
TADDP's rising edge, CP1E's Error Flag, the CS/CJ function codes), not read from the spec.
"""
import re

import pytest

from conftest import REPO
from test_review import line_of, review, spec_copy

SPEC = REPO / "spec"


def test_no_quote_names_a_file_the_project_does_not_hold(families):
    manuals = {fam.doc["manual"] for fam in families.values()}
    for fam in families.values():
        text = fam.path.read_text(encoding="utf-8")
        assert "NOTES.md" not in text, fam.path
        for name in re.findall(r"\bfile: ([^,}\s]+)", text):
            assert name in manuals, (fam.path, name)


@pytest.mark.parametrize("family", ["fx5-time-compare", "fx5-date-compare", "cp1e-time-compare"])
def test_the_multi_field_order_is_marked_derived(families, family):
    clause = families[family].clauses["order"]
    assert clause.get("derived"), "the pages give no order among the fields: the clause must say it is derived"
    assert "equal" in clause["derived"]     # the reasoning says how a lower field decides


def test_taddp_rising_edge_cites_the_pulse_execution_description(families):
    fam = families["fx5-time-add"]
    cites = fam.clauses["pulse"].get("cites", [])
    documents = {d["id"]: d for d in fam.doc["documents"]}
    assert cites and all(documents[c["document"]]["title"].startswith("MELSEC iQ-F FX5 Programming Manual")
                         for c in cites)
    assert any("rising edge" in c["states"] for c in cites)


def test_the_cp1e_error_flag_cites_omron_s_definition(families):
    fam = families["cp1e-time-compare"]
    source = fam.clauses["error-flag"]["source"]
    document = {d["id"]: d for d in fam.doc["documents"]}[source["document"]]
    assert document["publisher"] == "OMRON" and "P_ER" in source["states"]
    assert "error-flag" in fam.doc["coverage"]["every_vector"]     # every CP1E vector lists P_ER


def test_review_lists_derived_claims_and_other_documents_apart(real_review):
    done, out = real_review
    assert done.returncode == 0, done.stderr
    md = (out / "review.md").read_text(encoding="utf-8")
    derived = md.split("## Claims the pages do not state", 1)[1].split("\n## ", 1)[0]
    for family in ("fx5-time-compare", "fx5-date-compare", "cp1e-time-compare"):
        assert f"**{family}, clause order**" in derived
    assert "Reasoning: The page says which fields (s3) selects" in derived
    others = md.split("## Facts from other documents", 1)[1].split("\n## ", 1)[0]
    assert "(JY997D16601)" in others and "(W474)" in others and "(W480)" in others
    assert "FNC 162 TADD" in others


def _rewrite(path, old, new):
    text = path.read_text(encoding="utf-8")
    assert old in text
    path.write_text(text.replace(old, new, 1), encoding="utf-8")


def test_check_fails_on_a_quote_of_a_file_the_project_does_not_hold(tmp_path):
    folder, path = spec_copy(tmp_path, "fx5-time-add.yaml")
    _rewrite(path, 'source: {section: Processing details, quote: "If the result is 0 (0:00:00), the zero flag turns on."}',
             'source: {file: NOTES.md, section: Facts, quote: "If the result is 0 (0:00:00), the zero flag turns on."}')
    line = line_of(path, "file: NOTES.md")
    done = review("--check", "--no-write", "--spec-dir", folder)
    assert done.returncode == 1
    assert f"{path}:{line}: clause zero: cites 'NOTES.md', a file the project does not hold" in done.stderr


def test_check_fails_on_a_citation_of_an_unlisted_document(tmp_path):
    folder, path = spec_copy(tmp_path, "fx5-time-add.yaml")
    _rewrite(path, "source: {document: fx3-programming,", "source: {document: fx3-programing,")
    line = line_of(path, "document: fx3-programing,")
    done = review("--check", "--no-write", "--spec-dir", folder)
    assert done.returncode == 1
    assert f"{path}:{line}: clause same-device: cites document 'fx3-programing', which `documents` does not list" \
        in done.stderr
