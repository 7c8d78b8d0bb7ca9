"""`plcvec review`: the report a reviewer reads, and the --check that CI runs.

Expected values come from the manual text (../shared/manual), from the spec files, and from the
committed vectors, counted here independently of the review's own code.
"""
import os
import re
import shutil
import subprocess
import sys
from collections import Counter

import pytest

from conftest import MANUAL_DIR, REPO
from review_dom import disagreeing_cells, parse

SPEC = REPO / "spec"


def review(*args, seed="0"):
    """Run `plcvec review` as a user would; returns the finished process."""
    env = dict(os.environ, PYTHONHASHSEED=seed)
    return subprocess.run([sys.executable, "-m", "plcvec", "review", *map(str, args)],
                          capture_output=True, text=True, env=env, timeout=120)


def manual_text(name):
    return re.sub(r"\s+", " ", (MANUAL_DIR / name).read_text(encoding="utf-8"))


def spec_copy(tmp_path, name):
    """A spec folder holding a copy of one family's file: the review of one family is quicker to generate."""
    folder = tmp_path / "spec"
    folder.mkdir()
    shutil.copy(SPEC / name, folder / name)
    return folder, folder / name


def md_plain(text):
    """Markdown text with the review's escapes undone (backslash, pipe, a `<` that could open a tag)."""
    return re.sub(r"\\([\\|])", r"\1", text).replace("&lt;", "<")


def line_of(path, text):
    """1-based line of the first line of `path` holding `text`."""
    for number, line in enumerate(path.read_text(encoding="utf-8").split("\n"), 1):
        if text in line:
            return number
    raise AssertionError(f"{text!r} not in {path}")


@pytest.fixture(scope="module")
def report(real_review):
    """The review of the real spec, checked against the manual: (process, html, markdown, out folder)."""
    done, out = real_review
    return done, (out / "review.html").read_text(encoding="utf-8"), (out / "review.md").read_text(encoding="utf-8"), out


@pytest.fixture(scope="module")
def dom(report):
    return parse(report[1])[1]


def test_check_passes_on_the_real_spec(report):
    done, html, md, out = report
    assert done.returncode == 0, done.stderr
    assert done.stderr == ""
    assert re.search(r"; 0 of [1-9]\d* quotes missing;", done.stdout)  # every quote was checked and found
    assert str(out / "review.html") in done.stdout


@pytest.mark.slow
def test_output_is_deterministic(report, tmp_path):
    """Another run, under another hash seed, gives byte-identical files (slow: a second whole review;
    the default run checks the first one's content)."""
    done = review("--manual-dir", MANUAL_DIR, "--out", tmp_path, seed="12345")
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "review.html").read_bytes() == (report[3] / "review.html").read_bytes()
    assert (tmp_path / "review.md").read_bytes() == (report[3] / "review.md").read_bytes()


def test_html_is_self_contained(report):
    html = report[1]
    assert not re.search(r"""(src|href)\s*=\s*["']?\s*(https?:)?//""", html, re.I)
    assert not re.search(r"<(script|link|iframe|img|object)\b", html, re.I)
    assert "@import" not in html and "url(" not in html
    assert "<style>" in html  # the styling is inline
    # Every in-page link points at an element that exists.
    _, ids = parse(html)
    targets = set(re.findall(r'href="#([^"]+)"', html))
    assert targets and targets <= set(ids), sorted(targets - set(ids))[:5]


@pytest.mark.parametrize("family, clause, manual, quote", [
    ("fx5-time-add", "zero", "fx5-time-add-TADD.txt", "If the result is 0 (0:00:00), the zero flag turns on."),
    ("fx5-date-compare", "sm709.in-range", "fx5-date-compare-LDDT.txt",
     "Even if the data are not recognized as date data, SM709 does not turn on if the data are within the setting range."),
    ("cp1e-time-compare", "mask.set", "cp1e-time-compare-DT.txt",
     "To mask a time value, set the corresponding bit in the control word (C) to 1."),
])
def test_rule_beside_its_verbatim_quote(dom, families, family, clause, manual, quote):
    assert quote in manual_text(manual)  # the quote is the manual's own words
    row = dom[f"clause-{family}-{clause}"]
    rule, words = row.find_all("td")
    says = families[family].clauses[clause]["says"]
    assert clause in rule.text() and says in rule.text()
    assert words.first("blockquote").text() == quote
    assert quote not in rule.text()  # beside the rule, not in it
    assert manual in words.text() and "quote found" in words.text()


def test_interpretation_vector_counts(dom, golden):
    """Each interpretation's count: committed vectors whose outcome or alternatives name it."""
    expected = Counter()
    for name, file in golden.items():
        for v in file["vectors"]:
            named = set(v["outcome"].get("interpretations", []))
            for alt in v.get("alternatives", []):
                named |= set(alt["choices"])
            for iid in named:
                expected[(name, iid)] += 1
    checked = 0
    for name, file in golden.items():
        for interp in file["interpretations"]:
            block = dom[f"interp-{name}-{interp['id']}"]
            badge = re.search(r"(\d+) vectors affected", block.text())
            assert badge and int(badge.group(1)) == expected[(name, interp["id"])], interp["id"]
            checked += 1
    assert checked >= 18 and sum(expected.values()) > 0


def test_coverage_totals_match_the_committed_vectors(dom, golden, families):
    cited = Counter(ref for file in golden.values() for v in file["vectors"] for ref in v["clauses"])
    for name, fam in families.items():
        for cid in fam.clauses:
            row = dom[f"coverage-{name}-{cid}"]
            cells = [td.text() for td in row.find_all("td")]
            assert int(cells[4]) == cited[f"{name}#{cid}"], (name, cid, cells)
            assert int(cells[1]) + int(cells[2]) + int(cells[3]) == int(cells[4])


def test_clauses_no_vector_can_show_are_listed_with_the_reason(dom, families):
    why = {(n, e["clause"]): e["why"] for n, f in families.items() for e in f.doc.get("coverage", {}).get("no_vectors", [])}
    assert why, "the spec lists no clause under coverage.no_vectors"
    for (name, cid), reason in why.items():
        row = dom[f"coverage-{name}-{cid}"]
        assert "uncovered" not in row.attrs["class"] and reason in row.text()


def test_audit_findings_of_the_manual_tables(dom):
    """The two printed cells of the FX5 nonexistent-date table that the rule contradicts, and TADD's prose."""
    # Day 29 (B) < 31 (C) and month 2 (A) < 3 (B): the rule gives continuity where the manual prints ×.
    assert disagreeing_cells(dom, "fx5-date-compare", "nonexistent") == {"Day, B<C": ("×", "○"), "Month, A<B": ("×", "○")}
    for anchor, node in dom.items():
        if anchor.startswith("audit-fx5-date-compare-nonexistent-cell-disagrees"):
            assert "FX5-DT-EXAMPLE2-TABLE" in node.text() and "problem" not in node.attrs["class"]
    prose = [n for a, n in dom.items() if a.startswith("audit-fx5-time-add-carry-prose-vs-table")]
    assert len(prose) == 1
    # The page's sentence adds 20:20:20 to 14:30:30; its table holds 14:20:30.
    text = prose[0].text()
    assert "14:30:30" in text and "14:20:30" in text
    s = (14 * 3600 + 30 * 60 + 30 + 20 * 3600 + 20 * 60 + 20) % 86400
    assert prose[0].first("td", "derived").text() == f"{s // 3600}:{s // 60 % 60:02d}:{s % 60:02d}"


def test_markdown_has_the_same_rules_and_findings(report, dom, families):
    md = report[2]
    sections = re.split(r'<a id="(family-[^"]+|coverage-definitions)"></a>', md)
    by_family = dict(zip(sections[1::2], sections[2::2]))
    for name, fam in families.items():
        for cid, clause in fam.clauses.items():
            row = dom[f"clause-{name}-{cid}"]
            quote = row.first("blockquote").text()
            line = next((l for l in by_family[f"family-{name}"].split("\n") if l.startswith(f"| `{cid}` | ")), None)
            assert line is not None, (name, cid)
            plain = md_plain(line)
            assert clause["says"].split("<")[0] in plain
            assert re.sub(r"\s+", " ", quote).split("<")[0] in plain
    findings = [s.text() for a, n in dom.items() if a.startswith("audit-")
                for s in n.find_all("span", "finding") + n.find_all("span", "extra")]
    assert len(findings) >= 10
    flat = re.sub(r"\s+", " ", md_plain(md))
    for message in findings:
        assert message in flat


def test_script_in_the_spec_is_escaped(tmp_path):
    folder, path = spec_copy(tmp_path, "fx5-time-add.yaml")
    text = path.read_text(encoding="utf-8")
    old = "says: A result of 0:00:00 turns the zero flag on."
    assert text.count(old) == 1
    path.write_text(text.replace(old, 'says: "<script>alert(1)</script> & a result of 0:00:00"'), encoding="utf-8")
    done = review("--spec-dir", folder, "--out", tmp_path / "out")
    assert done.returncode == 0, done.stderr
    html = (tmp_path / "out" / "review.html").read_text(encoding="utf-8")
    assert "<script>" not in html
    assert "&lt;script&gt;alert(1)&lt;/script&gt; &amp; a result" in html
    md = (tmp_path / "out" / "review.md").read_text(encoding="utf-8")
    assert "<script>" not in md


def test_check_fails_on_an_altered_quote(tmp_path):
    folder, path = spec_copy(tmp_path, "fx5-time-add.yaml")
    line = line_of(path, 'quote: "If the result is 0 (0:00:00), the zero flag turns on."}')
    lines = path.read_text(encoding="utf-8").split("\n")
    lines[line - 1] = lines[line - 1].replace("turns on.", "turns off.")
    path.write_text("\n".join(lines), encoding="utf-8")
    done = review("--check", "--manual-dir", MANUAL_DIR, "--spec-dir", folder, "--out", tmp_path / "out")
    assert done.returncode == 1
    problems = [l for l in done.stderr.splitlines() if "quote" in l]
    assert problems == [f"{path}:{line}: clause zero: quote not found in fx5-time-add-TADD.txt: "
                        "'If the result is 0 (0:00:00), the zero flag turns off.'"]
    html = (tmp_path / "out" / "review.html").read_text(encoding="utf-8")  # the report is still written
    assert "missing: not found in fx5-time-add-TADD.txt" in parse(html)[1]["clause-fx5-time-add-zero"].text()


def test_check_fails_on_an_uncovered_clause(tmp_path):
    folder, path = spec_copy(tmp_path, "fx5-time-compare.yaml")
    text = path.read_text(encoding="utf-8")
    added = ("  - id: review-test-unexercised\n    says: A clause no rule parameter, case or coverage entry names.\n"
             "    source: {section: Operation error, quote: \"There is no operation error.\"}\n")
    path.write_text(text.replace("clauses:\n", "clauses:\n" + added, 1), encoding="utf-8")
    line = line_of(path, "- id: review-test-unexercised")
    done = review("--check", "--no-write", "--manual-dir", MANUAL_DIR, "--spec-dir", folder)
    assert done.returncode == 1
    assert f"{path}:{line}: clause review-test-unexercised: no vector exercises it" in done.stderr
    assert len([l for l in done.stderr.splitlines() if l.startswith(str(path))]) == 1


def test_check_fails_when_a_clause_said_to_have_no_vectors_is_cited(tmp_path):
    folder, path = spec_copy(tmp_path, "fx5-time-compare.yaml")
    text = path.read_text(encoding="utf-8")
    old = "  no_vectors:\n"
    assert text.count(old) == 1
    # `order` is cited by every comparison that reaches a selected field.
    path.write_text(text.replace(old, old + "    - {clause: order, why: said so for this test}\n"), encoding="utf-8")
    done = review("--check", "--no-write", "--spec-dir", folder)
    assert done.returncode == 1
    assert re.search(r"clause order: listed under coverage.no_vectors, yet \d+ vectors cite it", done.stderr)


def test_check_fails_on_a_disagreement_no_erratum_records(tmp_path):
    folder, path = spec_copy(tmp_path, "fx5-date-compare.yaml")
    lines = path.read_text(encoding="utf-8").split("\n")
    start = line_of(path, "- id: FX5-DT-EXAMPLE2-TABLE") - 1
    end = start + 1
    while lines[end].startswith("    "):
        end += 1
    del lines[start:end]  # the erratum that records the two misprinted cells
    path.write_text("\n".join(lines), encoding="utf-8")
    done = review("--check", "--no-write", "--spec-dir", folder)
    assert done.returncode == 1
    unrecorded = [l for l in done.stderr.splitlines() if "no erratum of the spec records it" in l]
    assert any("Day, B<C" in l for l in unrecorded) and any("Month, A<B" in l for l in unrecorded)
    assert all(l.startswith(f"{path}:") for l in unrecorded)


@pytest.mark.parametrize("argument, message", [
    ("missing-folder", "not a folder"),
    ("a-file.txt", "not a folder"),
])
def test_bad_manual_dir_is_one_plain_line(tmp_path, argument, message):
    (tmp_path / "a-file.txt").write_text("x")
    done = review("--check", "--manual-dir", tmp_path / argument, "--out", tmp_path / "out")
    assert done.returncode == 2
    assert done.stderr.count("\n") == 1 and "Traceback" not in done.stderr
    assert done.stderr.startswith("plcvec: --manual-dir ") and message in done.stderr
    assert not (tmp_path / "out").exists()


def test_bad_spec_dir_is_one_plain_line(tmp_path):
    done = review("--spec-dir", tmp_path, "--out", tmp_path / "out")
    assert done.returncode == 2 and "Traceback" not in done.stderr
    assert done.stderr.strip() == f"plcvec: {tmp_path}: no *.yaml spec files in this folder"
