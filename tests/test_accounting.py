"""Every sentence of the pages accounted for (plcvec.review.accounting and `review --check`).

Line numbers and sentences are read off the manual pages in ../shared/manual by hand.
"""
from conftest import MANUAL_DIR
from test_review import line_of, review, spec_copy

from plcvec.review.accounting import unaccounted, units


def test_units_are_sentences_and_table_rows():
    text = "Heading\n\nOne sentence. Another one.\n| a | b |\nrow\twith tab. Not split.\nglued.Sentence\n"
    got = [(u.line, u.text) for u in units("page.txt", text)]
    assert got == [(1, "Heading"), (3, "One sentence."), (3, "Another one."), (4, "| a | b |"),
                   (5, "row\twith tab. Not split."), (6, "glued."), (6, "Sentence")]


def test_a_quote_of_half_a_sentence_accounts_for_it_a_shared_word_does_not():
    text = "The zero flag turns on when the result is zero.\nThe carry flag turns on.\n"
    _, left = unaccounted("p.txt", text, ["The zero flag turns on when"])
    assert [u.line for u in left] == [2]
    _, left = unaccounted("p.txt", text, ["zero flag"])
    assert [u.line for u in left] == [1, 2]
    _, left = unaccounted("p.txt", text, ["result is zero. The carry flag turns on."])   # across lines
    assert [u.line for u in left] == [1]


def _drop_entry(path, text):
    """Remove the accounting entry whose texts line holds `text` (its `- as:` line to the next entry)."""
    lines = path.read_text(encoding="utf-8").split("\n")
    at = next(i for i, l in enumerate(lines) if text in l)
    start = max(i for i in range(at + 1) if lines[i].startswith("  - as:"))
    end = next((i for i in range(at + 1, len(lines)) if lines[i].startswith("  - as:")), len(lines))
    path.write_text("\n".join(lines[:start] + lines[end:]), encoding="utf-8")


def test_check_names_a_sentence_nobody_accounts_for_as_file_and_line(tmp_path):
    folder, path = spec_copy(tmp_path, "fx5-time-compare.yaml")
    _drop_entry(path, 'texts: ["FX5S FX5UJ FX5U FX5UC"]')
    done = review("--check", "--no-write", "--manual-dir", MANUAL_DIR, "--spec-dir", folder)
    assert done.returncode == 1
    page = MANUAL_DIR / "fx5-time-compare-LDTM.txt"
    # Line 7 of the page holds the CPU models, which nothing else quotes.
    assert done.stderr.splitlines()[0] == (f"{page}:7: no clause, interpretation, erratum or accounting entry "
                                           "accounts for 'FX5S FX5UJ FX5U FX5UC'")
    assert "1 of 103 sentences and table rows unaccounted for" in done.stdout


def test_every_page_is_accounted_for_and_each_text_is_on_its_page(real_review):
    done, _ = real_review
    assert done.returncode == 0, done.stderr
    assert " 0 of 4" in done.stdout and "sentences and table rows unaccounted for" in done.stdout


def test_a_text_not_on_the_page_is_a_missing_quote(tmp_path):
    folder, path = spec_copy(tmp_path, "fc6a-hour-meter.yaml")
    text = path.read_text(encoding="utf-8")
    path.write_text(text.replace('texts: ["Source device S1 can be designated by a data register or constant."]',
                                 'texts: ["Source device S1 can be designated by a timer."]'), encoding="utf-8")
    line = line_of(path, "Source device S1 can be designated by a timer.")
    done = review("--check", "--no-write", "--manual-dir", MANUAL_DIR, "--spec-dir", folder)
    assert done.returncode == 1
    assert f"{path}:{line}: accounting entry 2 (clause): quote not found in fc6a-hour-meter-HOUR.txt" in done.stderr


def test_hour_d2_row_is_recorded_as_its_erratum(families):
    fam = families["fc6a-hour-meter"]
    d2 = [e for e in fam.doc["accounting"] if any(t.startswith("D2 (Destination 2)") for t in e["texts"])]
    assert len(d2) == 1 and d2[0]["as"] == "erratum"
    assert d2[0]["erratum"] in {e["id"] for e in fam.doc["errata"]}


def test_cp1e_heading_that_lost_lt_dt_is_recorded_as_its_erratum(families):
    """The heading prints "=DT , <>DT , , <=DT , >DT , >=DT" (five names and an empty place); the function
    text's six flags and "18 possible combinations" (three forms) make six instructions, <DT among them."""
    fam = families["cp1e-time-compare"]
    heading = [e for e in fam.doc["accounting"] if "=DT , <>DT , , <=DT , >DT , >=DT" in e["texts"]]
    assert len(heading) == 1 and heading[0]["as"] == "erratum"
    erratum = next(e for e in fam.doc["errata"] if e["id"] == heading[0]["erratum"])
    assert erratum["quote"] == "=DT , <>DT , , <=DT , >DT , >=DT" and "<DT" in erratum["vectors_follow"]
    # The vectors follow the function text: <DT is an instruction in each of the three forms.
    symbols = {c["symbol"] for c in fam.doc["instructions"]["conditions"]}
    assert "<DT" in symbols and len(symbols) == 6 and len(fam.doc["instructions"]["forms"]) == 3
