"""The audit of the manual's tables: known disagreements, lost values, impossible tables, errata links.

Expected values are typed in from the manual pages here; the checks of values found by the audit use
a small comparison written below, not the spec engine.
"""
import itertools
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from plcvec.audit import audit_families
from plcvec.errors import SpecError
from plcvec.spec.loader import load_spec

REPO = Path(__file__).resolve().parents[1]
SPEC = REPO / "spec"

# ---------------------------------------------------------------- the manual's tables, typed in
PAIRS = {"A<B": ("A", "B"), "B<C": ("B", "C"), "A<C": ("A", "C")}
# fx5-time-compare-LDTM.txt, "Ex.": (s3) -> continuity of A<B, B<C, A<C (○ = 1, × = 0).
TIME_TABLE = {1: (1, 0, 0), 2: (0, 1, 0), 3: (0, 1, 0), 4: (1, 1, 1), 5: (1, 1, 1), 6: (1, 1, 1), 7: (1, 1, 1), 0: (0, 0, 0)}
# (s3) bit 0 "second", bit 1 "minute", bit 2 "hour"; compared hour first.
TIME_BITS = (("hour", 2), ("minute", 1), ("second", 0))
# fx5-date-compare-LDDT.txt, second table (nonexistent dates), as printed.
DATE_TABLE_2 = {1: (0, 0, 1), 2: (0, 0, 0), 3: (1, 0, 1), 4: (1, 1, 1), 5: (1, 1, 1), 6: (1, 1, 1), 7: (1, 1, 1), 0: (0, 0, 0)}
DATE_BITS = (("year", 2), ("month", 1), ("day", 0))
TIME_TARGETS = {1: "Second data", 2: "Minute data", 3: "Minute and second data", 4: "Hour data",
                5: "Hour and second data", 6: "Hour and minute data", 7: "Hour, minute, and second data", 0: "None"}
DATE_TARGETS = {1: "Day", 2: "Month", 3: "Month, day", 4: "Year", 5: "Year, day", 6: "Year, month", 7: "Year, month, day", 0: "None"}


def less(bits, s3, x, y):
    """x < y on the fields (s3) selects, as a tuple compared most significant first; no field: non-continuity."""
    chosen = [name for name, bit in bits if s3 >> bit & 1]
    return bool(chosen) and tuple(x[n] for n in chosen) < tuple(y[n] for n in chosen)


def cells(table, targets):
    return {(f"{targets[s3]}, {pair}"): (s3, pair, bool(row[i])) for s3, row in table.items() for i, pair in enumerate(PAIRS)}


def satisfied(bits, table_cells, values):
    return all(less(bits, s3, values[PAIRS[pair][0]], values[PAIRS[pair][1]]) == printed
               for s3, pair, printed in table_cells)


def small_assignments(bits):
    """Every assignment of the values 0, 1, 2 to each field of A, B and C: every ordering with ties of three values."""
    names = [n for n, _ in bits]
    for flat in itertools.product(range(3), repeat=3 * len(names)):
        yield {label: dict(zip(names, flat[k * len(names):(k + 1) * len(names)])) for k, label in enumerate("ABC")}


def ordering(values, field):
    """"B < A = C" for one field."""
    ranks = sorted({values[label][field] for label in "ABC"})
    return " < ".join(" = ".join(label for label in "ABC" if values[label][field] == r) for r in ranks)


# ---------------------------------------------------------------- fixtures and helpers
@pytest.fixture(scope="module")
def report():
    return audit_families(load_spec(SPEC))


def finding(report, family, example, kind, cell=None):
    hits = [f for f in report.findings if (f.family, f.example, f.kind) == (family, example, kind) and cell in (None, f.cell)]
    assert len(hits) == 1, f"{family} {example} {kind} {cell}: {len(hits)} findings"
    return hits[0]


def edited_spec(tmp_path, name, old, new):
    folder = tmp_path / "spec"
    shutil.copytree(SPEC, folder)
    path = folder / name
    text = path.read_text(encoding="utf-8")
    assert text.count(old) == 1, f"{name}: {old!r} found {text.count(old)} times"
    path.write_text(text.replace(old, new), encoding="utf-8")
    return folder


# ---------------------------------------------------------------- the disagreements
# (family, example, kind, cell) -> (printed, derived, erratum), each value as the manual writes it.
KNOWN = {
    # Day 29 (B) < 31 (C) is continuity; the table prints ×.
    ("fx5-date-compare", "nonexistent", "cell-disagrees", "Day, B<C"): ("×", "○", "FX5-DT-EXAMPLE2-TABLE"),
    # Month 2 (A) < 3 (B) is continuity; the table prints ×.
    ("fx5-date-compare", "nonexistent", "cell-disagrees", "Month, A<B"): ("×", "○", "FX5-DT-EXAMPLE2-TABLE"),
    # 0003H: bit 0 and bit 1, i.e. (s1)+1 and (s1)+2; the text says "(s1)+2 and (s1)+2".
    ("fx5-date-compare", "s3-table", "cell-disagrees", "Month, day"): ("(s1)+2 and (s1)+2", "(s1)+1 and (s1)+2", "FX5-DT-S3-0003-TEXT"),
    ("fx5-time-compare", "s3-table", "cell-disagrees", "Minute and second data"): ("(s1)+2 and (s1)+2", "(s1)+1 and (s1)+2", "FX5-TM-S3-0003-TEXT"),
    # 14:30:30 + 20:20:20 = 34:50:50, i.e. 10:50:50 after the carry; the sentence says 10:40:50.
    ("fx5-time-add", "carry", "prose-vs-table", "d"): ("10:40:50", "10:50:50", "TADD-CARRY-EXAMPLE-PROSE"),
    # "exceeds 24:00:00" read as written: 23:59:59 + 1 s is exactly 24:00:00, no carry; the example says carry on.
    ("fx5-time-add", "carry-and-zero", "prose-vs-table", "carry"): ("on", "off", "TADD-EXCEEDS-24"),
}


def test_known_disagreements_and_nothing_else(report):
    found = {(f.family, f.example, f.kind, f.cell): (f.printed, f.derived, f.erratum)
             for f in report.findings if f.kind in ("cell-disagrees", "prose-vs-table")}
    assert found == KNOWN
    # 0003H and 8003H in each of the two processing tables, two table cells, two sentences.
    assert report.disagreeing == 8
    assert report.checked >= 3 * 24 + 2 * 16 + 9
    assert f"{report.checked} printed cells recomputed from the rules, 8 disagree" in report.text()


def test_every_example_is_counted(report):
    counted = {(f.family, f.example) for f in report.by_kind("cell-agrees-count")}
    assert counted == {("fx5-time-compare", "abc"), ("fx5-time-compare", "s3-table"), ("fx5-date-compare", "abc"),
                       ("fx5-date-compare", "nonexistent"), ("fx5-date-compare", "s3-table"), ("cp1e-time-compare", "c39"),
                       ("fx5-time-add", "ex1"), ("fx5-time-add", "carry"), ("fx5-time-add", "carry-and-zero"),
                       ("fx5-time-add", "program"), ("fx5-time-add", "over24")}
    assert "22 of 24" in finding(report, "fx5-date-compare", "nonexistent", "cell-agrees-count").message
    assert "16 of 18" in finding(report, "fx5-time-compare", "s3-table", "cell-agrees-count").message


# ---------------------------------------------------------------- lost values
def test_time_example_values_found_satisfy_every_printed_cell(report):
    f = finding(report, "fx5-time-compare", "abc", "values-found")
    values = f.values
    ranges = {"hour": (0, 23), "minute": (0, 59), "second": (0, 59)}
    for label in "ABC":
        for name, (lo, hi) in ranges.items():
            assert lo <= values[label][name] <= hi
    assert satisfied(TIME_BITS, cells(TIME_TABLE, TIME_TARGETS).values(), values)


def test_time_example_orderings_are_exactly_those_that_work(report):
    """Every ordering the audit reports works, and none it leaves out does: brute force with the small comparison."""
    table = list(cells(TIME_TABLE, TIME_TARGETS).values())
    works = {name: set() for name, _ in TIME_BITS}
    for values in small_assignments(TIME_BITS):
        if satisfied(TIME_BITS, table, values):
            for name in works:
                works[name].add(ordering(values, name))
    # What the printed table allows (derived from it by hand): hA < hB < hC, mB < mC <= mA and sC <= sA < sB.
    assert works == {"hour": {"A < B < C"}, "minute": {"B < C < A", "B < A = C"}, "second": {"C < A < B", "A = C < B"}}
    f = finding(report, "fx5-time-compare", "abc", "values-found")
    assert {k: set(v) for k, v in f.orderings.items()} == works


def test_search_does_not_read_the_spec_values(tmp_path):
    """With the reconstructed values replaced by equal ones, the search still finds values that work."""
    folder = edited_spec(tmp_path, "fx5-time-compare.yaml", "B: {hour: 10, minute: 15, second: 45}", "B: {hour: 8, minute: 40, second: 20}")
    report = audit_families(load_spec(folder))
    assert {f.cell for f in report.by_kind("cell-disagrees") if f.family == "fx5-time-compare"} >= {"Hour data, A<B", "Second data, A<B"}
    f = finding(report, "fx5-time-compare", "abc", "values-found")
    assert satisfied(TIME_BITS, cells(TIME_TABLE, TIME_TARGETS).values(), f.values)


# ---------------------------------------------------------------- a table no values can produce
def test_nonexistent_date_table_has_no_values(report):
    f = finding(report, "fx5-date-compare", "nonexistent", "no-values")
    assert f.erratum == "FX5-DT-EXAMPLE2-TABLE"
    assert "Day, B<C" in f.conflicting_cells or "Month, A<B" in f.conflicting_cells
    table = cells(DATE_TABLE_2, DATE_TARGETS)
    assert not any(satisfied(DATE_BITS, table.values(), v) for v in small_assignments(DATE_BITS))
    for conflict in f.conflicts:
        chosen = [table[name] for name in conflict]
        assert not any(satisfied(DATE_BITS, chosen, v) for v in small_assignments(DATE_BITS)), conflict
        for left_out in conflict:  # smallest: without any one of its cells the rest can hold
            rest = [table[name] for name in conflict if name != left_out]
            assert any(satisfied(DATE_BITS, rest, v) for v in small_assignments(DATE_BITS)), (conflict, left_out)
    assert f.corrections
    for correction in f.corrections:
        rest = [c for name, c in table.items() if name not in correction]
        assert any(satisfied(DATE_BITS, rest, v) for v in small_assignments(DATE_BITS)), correction
    # The two cells the erratum names, set aside, leave a table some values produce.
    rest = [c for name, c in table.items() if name not in ("Day, B<C", "Month, A<B")]
    assert any(satisfied(DATE_BITS, rest, v) for v in small_assignments(DATE_BITS))


def test_first_date_table_has_values(report):
    f = finding(report, "fx5-date-compare", "abc", "values-found")
    table = cells({1: (1, 0, 0), 2: (0, 1, 0), 3: (0, 1, 0), 4: (1, 1, 1), 5: (1, 1, 1), 6: (1, 1, 1), 7: (1, 1, 1), 0: (0, 0, 0)},
                  DATE_TARGETS)
    assert satisfied(DATE_BITS, table.values(), f.values)


# ---------------------------------------------------------------- errata links
def test_a_flipped_cell_is_a_new_disagreement_without_erratum(tmp_path):
    folder = edited_spec(tmp_path, "fx5-time-compare.yaml",
                         "{target: Hour data, s3: 0x0004, printed: [true, true, true]}",
                         "{target: Hour data, s3: 0x0004, printed: [false, true, true]}")
    report = audit_families(load_spec(folder))
    f = finding(report, "fx5-time-compare", "abc", "cell-disagrees", "Hour data, A<B")
    assert (f.printed, f.derived, f.erratum) == ("×", "○", None)
    # With hour A < B < C forced by the other Hour cells, A<B cannot be ×: no values produce the table now.
    nv = finding(report, "fx5-time-compare", "abc", "no-values")
    assert nv.erratum is None and "Hour data, A<B" in nv.conflicting_cells
    assert not [f for f in report.by_kind("values-found") if (f.family, f.example) == ("fx5-time-compare", "abc")]
    assert report.disagreeing == 9


def test_no_erratum_is_stale(report, families):
    assert not report.by_kind("erratum-stale")
    cited = {}
    for fam in families.values():
        for erratum in fam.doc["errata"]:
            concerns = erratum.get("concerns", {})
            for part, kind in (("table", "cell-disagrees"), ("prose", "prose-vs-table")):
                for cell in concerns.get(part, []):
                    cited[(fam.name, concerns["example"], kind, cell)] = erratum["id"]
    assert len(cited) == 6
    for (family, example, kind, cell), erratum in cited.items():
        assert finding(report, family, example, kind, cell).erratum == erratum


def test_an_erratum_on_an_agreeing_cell_is_reported_stale(tmp_path):
    folder = edited_spec(tmp_path, "fx5-date-compare.yaml", 'table: ["Day, B<C", "Month, A<B"]}', 'table: ["Day, B<C", "Day, A<C"]}')
    report = audit_families(load_spec(folder))
    stale = report.by_kind("erratum-stale")
    assert [(f.example, f.cell, f.erratum) for f in stale] == [("nonexistent", "Day, A<C", "FX5-DT-EXAMPLE2-TABLE")]
    assert finding(report, "fx5-date-compare", "nonexistent", "cell-disagrees", "Month, A<B").erratum is None


def test_an_erratum_naming_an_unknown_cell_is_a_spec_error(tmp_path):
    folder = edited_spec(tmp_path, "fx5-date-compare.yaml", 'table: ["Day, B<C", "Month, A<B"]}', 'table: ["Day, B<C", "Month, A<D"]}')
    with pytest.raises(SpecError) as info:
        audit_families(load_spec(folder))
    assert "fx5-date-compare.yaml:" in str(info.value) and "'Month, A<D'" in str(info.value)


def test_a_prose_reading_must_name_a_real_alternative(tmp_path):
    folder = edited_spec(tmp_path, "fx5-time-add.yaml", "reading: {TADD-EXACT-24: carry-above-24}", "reading: {TADD-EXACT-24: carry-above}")
    with pytest.raises(SpecError) as info:
        audit_families(load_spec(folder))
    assert "fx5-time-add.yaml:" in str(info.value) and "no alternative 'carry-above'" in str(info.value)


def test_prose_that_agrees_with_its_table_is_no_finding(tmp_path):
    """Correct the sentence's 14:30:30 to the table's 14:20:30: the prose finding goes, and its erratum is stale."""
    folder = edited_spec(tmp_path, "fx5-time-add.yaml", "        s1: {hour: 14, minute: 30, second: 30}",
                         "        s1: {hour: 14, minute: 20, second: 30}")
    report = audit_families(load_spec(folder))
    assert not [f for f in report.by_kind("prose-vs-table") if f.example == "carry"]
    assert [(f.example, f.cell, f.erratum) for f in report.by_kind("erratum-stale")] == [("carry", "d", "TADD-CARRY-EXAMPLE-PROSE")]


# ---------------------------------------------------------------- as a command, deterministic
def test_command_output_is_deterministic():
    outputs = []
    for seed in ("0", "12345"):
        proc = subprocess.run([sys.executable, "-m", "plcvec.audit", "--json"], capture_output=True, text=True, timeout=300,
                              env=dict(os.environ, PYTHONHASHSEED=seed))
        assert proc.returncode == 0, proc.stderr
        outputs.append(proc.stdout)
    assert outputs[0] == outputs[1]
    doc = json.loads(outputs[0])
    assert doc["disagreeing"] == 8 and len(doc["findings"]) == len(audit_families(load_spec(SPEC)).findings)
