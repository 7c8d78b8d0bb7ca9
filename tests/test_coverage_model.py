"""The coverage model: the greedy pairwise construction, the classes each execution falls in (from
its inputs and the engine's record, under every reading), the golden set meeting every requirement,
and `plcvec review --check` naming a requirement no vector meets.

Expected classes come from the manual's ranges and rules (hour 0 to 23; an AND with the preceding
logic off is not executed under one reading and is under another), never from the classifier.
"""
import itertools
import os
import shutil
import subprocess
import sys

import pytest

from plcvec.cases.build import VectorBuilder
from plcvec.cases.clock_add_cases import AddCases
from plcvec.cases.masked_compare_cases import CompareCases
from plcvec.coverage.model import model_of
from plcvec.coverage.pairwise import Dimension, cover, required_pairs, row_pairs

from conftest import REPO


# -- the greedy construction, on its own ------------------------------------------------------------
def all_pairs(dims):
    """Every pair of classes of two dimensions, enumerated independently of the module."""
    return {((a.id, x), (b.id, y)) for i, a in enumerate(dims) for b in dims[i + 1:] for x in a.classes for y in b.classes}


def test_every_pair_is_covered_and_rows_are_few():
    dims = [Dimension("a", ("0", "1")), Dimension("b", ("0", "1")), Dimension("c", ("0", "1"))]
    assert required_pairs(dims) == all_pairs(dims)
    result = cover(dims, required_pairs(dims))
    covered = set().union(*(row_pairs(r, dims) for r, _ in result.rows))
    assert covered >= all_pairs(dims) and not result.missing
    # Three binary dimensions need at least 4 rows (the 4 pairs of a and b); the full product has 8.
    assert 4 <= len(result.rows) <= 6


def test_pairwise_is_much_smaller_than_the_product():
    dims = [Dimension(f"d{i}", tuple(str(c) for c in range(4))) for i in range(6)]
    result = cover(dims, required_pairs(dims))
    covered = set().union(*(row_pairs(r, dims) for r, _ in result.rows))
    assert covered >= all_pairs(dims)
    assert 16 <= len(result.rows) <= 40 < 4 ** 6


def test_deterministic():
    dims = [Dimension("x", ("p", "q", "r")), Dimension("y", ("1", "2")), Dimension("z", ("u", "v", "w"))]
    first = cover(dims, required_pairs(dims)).rows
    assert first == cover(dims, required_pairs(dims)).rows


def test_already_covered_pairs_are_not_asked_for_again():
    dims = [Dimension("a", ("0", "1")), Dimension("b", ("0", "1"))]
    result = cover(dims, required_pairs(dims), covered={(("a", "0"), ("b", "0")), (("a", "1"), ("b", "1"))})
    assert sorted(tuple(sorted(r.items())) for r, _ in result.rows) == [(("a", "0"), ("b", "1")), (("a", "1"), ("b", "0"))]


def test_a_conditional_dimension_is_absent_outside_its_condition():
    dims = [Dimension("form", ("LD", "AND")), Dimension("logic", ("on", "off"), ("form", ("AND",))),
            Dimension("cond", ("=", "<"))]
    req = required_pairs(dims)
    assert (("form", "LD"), ("logic", "on")) not in req and (("form", "AND"), ("logic", "off")) in req
    assert (("logic", "on"), ("cond", "<")) in req
    result = cover(dims, req)
    for row, _ in result.rows:
        assert (row["logic"] is None) == (row["form"] == "LD"), row
    assert set().union(*(row_pairs(r, dims) for r, _ in result.rows)) >= req


def test_excluded_pairs_are_not_required():
    dims = [Dimension("a", ("0", "1")), Dimension("b", ("0", "1"))]
    ruled_out = (("a", "1"), ("b", "1"))
    assert required_pairs(dims, lambda p: p == ruled_out) == all_pairs(dims) - {ruled_out}


def test_rows_keep_out_the_pairs_excluded():
    dims = [Dimension("a", ("0", "1", "2")), Dimension("b", ("0", "1")), Dimension("c", ("0", "1", "2"))]
    ruled_out = {(("b", "1"), ("c", "2")), (("a", "0"), ("c", "0"))}
    excluded = ruled_out.__contains__
    req = required_pairs(dims, excluded)
    result = cover(dims, req, excluded=excluded)
    shown = [row_pairs(r, dims) for r, _ in result.rows]
    assert set().union(*shown) >= req and not result.missing
    assert not any(pairs & ruled_out for pairs in shown), [r for r, _ in result.rows]


def test_a_pair_no_row_can_show_is_returned_as_missing():
    dims = [Dimension("a", ("0", "1")), Dimension("b", ("0", "1"))]
    impossible = (("a", "1"), ("b", "1"))

    def realize(row):   # an input that cannot hold a=1 with b=1 shows a=1, b=0 instead
        shown = dict(row, b="0") if (row["a"], row["b"]) == ("1", "1") else row
        return row_pairs(shown, dims), shown
    result = cover(dims, required_pairs(dims), realize=realize)
    assert result.missing == [impossible]
    assert all(payload != {"a": "1", "b": "1"} for _, payload in result.rows)


# -- the classes of real executions ------------------------------------------------------------------
@pytest.fixture(scope="module")
def time_compare(families):
    fam = families["fx5-time-compare"]
    builder = VectorBuilder(fam)
    return builder, CompareCases(fam, builder)


def classes(builder, vector, dimension):
    return {dict(cell)[dimension] for cell in builder.cells[vector["id"]]}


def test_hour_24_is_above_its_range_and_nothing_is_compared(time_compare):
    builder, c = time_compare
    s1 = c.ops.words(c.ops.values(hour=24))   # "within the range 0 to 23"
    v = c.case("LD", "=", "test/hour-24", tags=["model"], description="t", s1=s1, s2=c.ops.words(c.ops.values()),
               sel=0x0004)
    assert classes(builder, v, "data") == {"s1.hour.above"}
    assert classes(builder, v, "selector") == {"hour"}
    assert classes(builder, v, "ordering") == {"none"}   # SM709 under every reading: hour is compared
    assert classes(builder, v, "logic") == {None}        # LD has no preceding logic


def test_cells_come_from_every_reading(time_compare):
    builder, c = time_compare
    a, b = c.pair_with("hour", "lt")
    v = c.case("AND", "<", "test/and-off", tags=["model"], description="t", s1=c.ops.words(a), s2=c.ops.words(b),
               sel=0x0007, rlo_in=False)
    # and-skipped: not executed, nothing compared; always-executed: compared, (s1) < (s2).
    assert classes(builder, v, "ordering") == {"none", "lt"}
    assert classes(builder, v, "logic") == {"off"}


def test_dummy_operand_is_classed_as_dummy(time_compare):
    builder, c = time_compare
    v = c.case("LD", "=", "test/dummy", tags=["model"], description="t", s1=c.ops.words(c.ops.values()),
               s2=c.ops.words(c.ops.values(minute=60)), sel=0x8007, clock=c.ops.values())
    assert classes(builder, v, "data") == {"dummy-s2.minute.above"}
    assert classes(builder, v, "source") == {"current-clock"}
    assert classes(builder, v, "ordering") == {"eq"}


def test_exact_wrap_of_the_manual_example(families):
    fam = families["fx5-time-add"]
    builder = VectorBuilder(fam)
    c = AddCases(fam, builder)
    # "If 1 second is added to 23:59:59, the result will be 0:00:00."
    v = c.case("TADD", "test/23:59:59+1", tags=["model"], description="t",
               values={"s1": {"hour": 23, "minute": 59, "second": 59}, "s2": {"hour": 0, "minute": 0, "second": 1}})
    assert classes(builder, v, "sum") == {"exact-wrap"}
    assert classes(builder, v, "en") == {"rising"}
    assert classes(builder, v, "aliasing") == {"distinct"}


# -- the golden set and the check ----------------------------------------------------------------------
def test_every_family_has_a_model_with_its_manual_table_as_a_product(families):
    for name, fam in families.items():
        model = model_of(fam)
        assert model is not None, name
        assert model.spec["strength"] == "pairwise"
        assert len(model.dims) >= 5, name
    for name in ("fx5-time-compare", "fx5-date-compare", "cp1e-time-compare"):
        dims = [p["dimensions"] for p in families[name].doc["coverage"]["model"]["products"]]
        assert ["form", "logic", "condition", "ordering"] in dims, name


def test_model_vectors_have_ids_from_their_row(golden):
    for name, f in golden.items():
        model_ids = [v["id"] for v in f["vectors"] if "model" in v["tags"]]
        assert model_ids, name
        for vid in model_ids:
            assert "/model/" in vid and "=" in vid.split("/model/")[1], vid


def review(*args):
    env = dict(os.environ, PYTHONHASHSEED="0")
    return subprocess.run([sys.executable, "-m", "plcvec", "review", *map(str, args)],
                          capture_output=True, text=True, env=env, timeout=600)


def test_review_check_names_a_combination_no_vector_exercises(tmp_path):
    folder = tmp_path / "spec"
    folder.mkdir()
    text = (REPO / "spec" / "fx5-time-compare.yaml").read_text(encoding="utf-8")
    # Drop the exclusion of orderings for a selector that compares nothing: those pairs become required,
    # and no input can show them (the manual: "the operation result will be non-continuity").
    lines = text.split("\n")
    i = next(k for k, l in enumerate(lines) if "classes: {ordering: [lt, eq, gt], selector:" in l)
    del lines[i:i + 2]
    (folder / "fx5-time-compare.yaml").write_text("\n".join(lines), encoding="utf-8")
    done = review("--spec-dir", folder, "--check", "--no-write")
    assert done.returncode == 1, done.stderr
    assert "coverage model: no vector exercises selector=none × ordering=lt (pair of classes" in done.stderr
    assert "9 problems" in done.stderr   # none, reserved, reserved+fields, each with lt, eq, gt
    assert "fx5-time-compare.yaml:" in done.stderr and "Traceback" not in done.stderr


def test_a_date_past_its_month_end_is_nonexistent(families):
    """The manual's 2006/02/30 and a 31 June, each field in range: nonexistent, whether or not listed."""
    fam = families["fx5-date-compare"]
    builder = VectorBuilder(fam)
    c = CompareCases(fam, builder)
    for key, date in (("feb-30", {"year": 2006, "month": 2, "day": 30}), ("jun-31", {"year": 2029, "month": 6, "day": 31})):
        v = c.case("LD", "=", f"test/{key}", tags=["model"], description="t", s1=c.ops.words(date),
                   s2=c.ops.words(date), sel=0x0007)
        assert classes(builder, v, "data") == {"nonexistent"}, key
        assert classes(builder, v, "ordering") == {"eq"}, key   # compared as it is, no SM709
    v = c.case("LD", "=", "test/jun-30", tags=["model"], description="t", s1=c.ops.words({"year": 2029, "month": 6, "day": 30}),
               s2=c.ops.words({"year": 2029, "month": 6, "day": 30}), sel=0x0007)
    assert classes(builder, v, "data") == {"valid"}
