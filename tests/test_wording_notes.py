"""Accounting is not agreement: wording notes and errata beside them (plcvec.review.accounting, `review --check`).

A wording note files words of a page under a rule they say more or less than; the review lists it beside
the errata with the page's words, the rule and why the rule stands. The facts these tests expect are read
off the manual pages in ../shared/manual by hand or worked out from the page's own values.
"""
import re

import pytest

from conftest import MANUAL_DIR
from review_dom import parse
from test_review import line_of, manual_text, md_plain, review, spec_copy

from plcvec.review.quotes import squash


def _notes(fam):
    return [(i, e) for i, e in enumerate(fam.doc.get("accounting", ())) if e["as"] == "wording"]


@pytest.fixture(scope="module")
def written(real_review):
    """The review of the real spec against the manual: (process, DOM ids, Markdown)."""
    done, out = real_review
    return done, parse((out / "review.html").read_text(encoding="utf-8"))[1], (out / "review.md").read_text(encoding="utf-8")


def test_every_wording_note_quotes_its_own_page_and_names_clauses_it_has(families):
    count = 0
    for fam in families.values():
        page = squash((MANUAL_DIR / fam.doc["manual"]).read_text(encoding="utf-8"))
        for _, note in _notes(fam):
            assert note["texts"] and all(squash(t) in page for t in note["texts"]), (fam.name, note["texts"])
            assert note.get("instead") or (note["clauses"] and set(note["clauses"]) <= set(fam.clauses)), note
            count += 1
    assert count >= 8   # the notes of the re-reading: FX5 (s3) wording, TADD's flag table, HOUR's wrap...


def test_the_review_lists_each_wording_note_after_the_errata(written, families):
    done, ids, md = written
    assert done.returncode == 0, done.stderr
    for name, fam in families.items():
        errata, notes = ids[f"family-{name}-errata"], ids[f"family-{name}-wording"]
        assert errata.parent is notes.parent
        siblings = [c for c in notes.parent.children if not isinstance(c, str)]
        assert siblings.index(errata) < siblings.index(notes)
        for n, (_, note) in enumerate(_notes(fam), 1):
            shown = ids[f"wording-{name}-{n}"]
            assert [q.text() for q in shown.find_all("blockquote")] == [re.sub(r"\s+", " ", t) for t in note["texts"]]
            text = shown.text()
            for piece in (note.get("says"), note.get("rule"), note["why"], note.get("instead")):
                assert piece is None or re.sub(r"\s+", " ", piece) in text
            for cid in note.get("clauses", ()):
                assert cid in text and fam.clauses[cid]["says"] in text
            assert "quote found" in text
    flat = re.sub(r"\s+", " ", md_plain(md))
    assert flat.count("### Wording notes") == len(families)
    for fam in families.values():
        for _, note in _notes(fam):
            assert f"The rule says: {note['rule']}" in flat if note.get("rule") else note["why"] in flat


def test_summary_counts_the_wording_notes(written, families):
    _, ids, _ = written
    total = sum(len(_notes(fam)) for fam in families.values())
    errata = sum(len(fam.doc["errata"]) for fam in families.values())
    rows = [r.text() for r in ids["summary"].find_all("tr")]
    assert any(r.startswith("Interpretations / errata / wording notes") and r.endswith(f"/ {errata} / {total}")
               for r in rows), rows


def _edited(tmp_path, name, old, new):
    """A spec folder holding one family's file with `old` (found once) replaced by `new`: (folder, path)."""
    folder, path = spec_copy(tmp_path, name)
    text = path.read_text(encoding="utf-8")
    assert text.count(old) == 1, old
    path.write_text(text.replace(old, new), encoding="utf-8")
    return folder, path


def _check(folder):
    return review("--check", "--no-write", "--manual-dir", MANUAL_DIR, "--spec-dir", folder)


def _entry_number(path, line):
    """1-based number of the accounting entry a spec line belongs to, counted by hand from the file."""
    lines = path.read_text(encoding="utf-8").split("\n")
    start = lines.index("accounting:")
    return sum(1 for l in lines[start:line] if l.startswith("  - as:"))


def test_check_fails_on_a_wording_note_whose_text_is_not_on_its_page(tmp_path):
    # The note's own text, not clause sm700's quote of the same row.
    old = 'texts: ["| SM700 | Carry | If the result exceeds the maximum value of the time data, 23:59:59, this'
    folder, path = _edited(tmp_path, "fx5-time-add.yaml", old, old.replace("23:59:59", "24:00:00"))
    line = line_of(path, 'texts: ["| SM700 | Carry')
    done = _check(folder)
    assert done.returncode == 1
    assert [l for l in done.stderr.splitlines() if l.startswith(str(path))] == [
        f"{path}:{line}: accounting entry {_entry_number(path, line)} (wording): quote not found in fx5-time-add-TADD.txt: "
        "'| SM700 | Carry | If the result exceeds the maximum value of the time data, 24:00:00, this special relay turns on. |'"]


def test_check_fails_on_a_wording_note_naming_a_clause_that_does_not_exist(tmp_path):
    folder, path = _edited(tmp_path, "fc6a-hour-meter.yaml", "  - as: wording\n    clauses: [wrap]\n",
                           "  - as: wording\n    clauses: [wrap-around]\n")
    done = _check(folder)
    assert done.returncode == 1
    line = line_of(path, "clauses: [wrap-around]") - 1
    assert f"{path}:{line}: wording note: clause 'wrap-around' is not a clause of this family" in done.stderr.splitlines()


def test_check_fails_on_an_erratum_naming_a_clause_that_does_not_exist(tmp_path):
    folder, path = _edited(tmp_path, "fx5-date-compare.yaml", "  - id: FX5-DT-DEVICE-TABLE-HEAD\n    clause: devices\n",
                           "  - id: FX5-DT-DEVICE-TABLE-HEAD\n    clause: device-table\n")
    done = _check(folder)
    assert done.returncode == 2
    assert done.stderr.strip().endswith(f"{path}:{line_of(path, 'clause: device-table')}: unknown clause 'device-table'")
    assert "Traceback" not in done.stderr


def test_check_fails_on_an_erratum_whose_text_is_not_on_its_page(tmp_path):
    # The head row as the time page prints it, with LZ: not what the date page holds.
    old = 'quote: "X, Y, M, L, SM, F, B, SB, S T, ST, C, D, W, SD, SW, R UD\\\\G Z LC K, H'
    folder, path = _edited(tmp_path, "fx5-date-compare.yaml", old, old.replace(" LC K, H", " LC LZ K, H"))
    line = line_of(path, 'quote: "X, Y, M, L, SM, F, B, SB, S T, ST')
    done = _check(folder)
    assert done.returncode == 1
    assert any(l.startswith(f"{path}:{line}: erratum FX5-DT-DEVICE-TABLE-HEAD: quote not found in fx5-date-compare-LDDT.txt")
               for l in done.stderr.splitlines()), done.stderr


def test_a_wording_note_needs_its_clauses_what_the_words_say_and_the_rule(tmp_path):
    folder, path = spec_copy(tmp_path, "fc6a-hour-meter.yaml")
    lines = path.read_text(encoding="utf-8").split("\n")
    del lines[line_of(path, "    rule: D1 counts on from 0:00:00") - 1]
    path.write_text("\n".join(lines), encoding="utf-8")
    done = review("--check", "--no-write", "--spec-dir", folder)
    assert done.returncode == 2
    note = line_of(path, "clauses: [wrap]") - 1
    assert done.stderr.strip().endswith(f"{path}:{note}: accounting.{_entry_number(path, note) - 1}: "
                                        "'rule' is required but missing")


def test_an_older_wording_entry_with_instead_is_still_read(tmp_path):
    folder, path = spec_copy(tmp_path, "fc6a-hour-meter.yaml")
    text = path.read_text(encoding="utf-8")
    start = text.index("  - as: wording\n    clauses: [wrap]\n")
    older = ('  - as: wording\n    why: "Read alone, D1 is set to 0:00:00."\n'
             '    instead: "The cycle is measured again from 0:00:00."\n'
             '    texts: ["the value returns to 0 hours 0 minutes 0 seconds torepeat another measuring cycle"]\n')
    path.write_text(text[:start] + older, encoding="utf-8")
    out = tmp_path / "out"
    done = review("--check", "--manual-dir", MANUAL_DIR, "--spec-dir", folder, "--out", out)
    assert done.returncode == 0, done.stderr
    shown = parse((out / "review.html").read_text(encoding="utf-8"))[1]["wording-fc6a-hour-meter-1"]
    rows = {r.first("th").text(): r.first("td").text() for r in shown.find_all("tr")}
    assert rows["Why"] == "Read alone, D1 is set to 0:00:00."
    assert rows["Instead"] == "The cycle is measured again from 0:00:00."
    assert "The words say" not in rows and "Filed under" not in rows


def _table_rows(page, header):
    """The rows of the printed table whose head row is `header`, as lists of tab-separated cells."""
    lines = (MANUAL_DIR / page).read_text(encoding="utf-8").split("\n")
    at = lines.index(header)
    rows = []
    for line in lines[at + 1:]:
        if "\t" not in line:
            break
        rows.append(line.split("\t"))
    return rows


def test_the_nonexistent_date_rows_that_contradict_their_dates_are_filed_as_the_erratum(families):
    """Worked from the page alone: dates A, B, C as printed, each row's cells against the calendar order."""
    text = manual_text("fx5-date-compare-LDDT.txt")
    dates = {k: tuple(map(int, re.search(rf"Date {k}: (\d+)/(\d+)/(\d+)", text).groups())) for k in "ABC"}
    assert dates == {"A": (2006, 2, 30), "B": (2007, 3, 29), "C": (2008, 2, 31)}
    fields = {"year": 0, "month": 1, "day": 2}
    lines = (MANUAL_DIR / "fx5-date-compare-LDDT.txt").read_text(encoding="utf-8").split("\n")
    second = [i for i, l in enumerate(lines) if l.startswith("\tA<B\tB<C\tA<C")][1]
    wrong = []
    for line in lines[second + 1:second + 9]:
        target, *cells = line.split("\t")
        picked = [fields[f.lower()] for f in target.split(", ")] if target != "None" else []
        for cell, (x, y) in zip(cells, ["AB", "BC", "AC"]):
            holds = bool(picked) and [dates[x][i] for i in picked] < [dates[y][i] for i in picked]
            if (cell == "○") != holds:
                wrong.append(target)
    assert wrong == ["Day", "Month"]
    fam = families["fx5-date-compare"]
    filed = [e for e in fam.doc["accounting"] if e["as"] == "erratum" and e["erratum"] == "FX5-DT-EXAMPLE2-TABLE"]
    assert [squash(t) for e in filed for t in e["texts"]] == [squash("Day × × ○ Month × × ×")]
    for e in fam.doc["accounting"]:
        if e["as"] == "clause":
            assert not any(squash("Day × × ○") in squash(t) or squash("Month × × ×") in squash(t) for t in e["texts"])


def test_the_date_device_table_head_out_of_line_is_an_erratum_and_the_time_one_is_not(families):
    """By the page's cells: the column of the first head row's Word against the second head row's word devices."""
    first = "Operand\tBit\tWord\t\t\tDouble word\t\tIndirect specification\tConstant\t\t\tOthers"

    def heads(page):
        second = _table_rows(page, first)[0]
        return second.index("T, ST, C, D, W, SD, SW, R"), first.split("\t").index("Word")
    assert heads("fx5-time-compare-LDTM.txt") == (2, 2)
    assert heads("fx5-date-compare-LDDT.txt") == (3, 2)
    date, time = families["fx5-date-compare"], families["fx5-time-compare"]
    erratum = next(e for e in date.doc["errata"] if e["id"] == "FX5-DT-DEVICE-TABLE-HEAD")
    assert erratum["clause"] == "devices" and squash(erratum["quote"]).startswith(squash("X, Y, M, L, SM, F, B, SB, S T, ST"))
    assert any(e["as"] == "erratum" and e["erratum"] == erratum["id"] for e in date.doc["accounting"])
    assert not any("DEVICE-TABLE" in e["id"] for e in time.doc["errata"])
