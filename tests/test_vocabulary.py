"""verifiers/VOCABULARY.md names files that exist: every backticked path in its map lies under one of
its runner's folders, and every path in its table of circle checks lies in the repository. A file
moved or renamed without the page following fails here."""
import re
from pathlib import Path

from conftest import REPO

PAGE = REPO / "verifiers" / "VOCABULARY.md"
RUNNERS = ["Python", "C", "Rust", "Go", "Java", "TypeScript"]
# A path, not a name: a file of one of the runners' languages, or a folder (trailing slash).
PATH = re.compile(r"^[\w.\-/]+(\.(py|c|h|rs|go|java|ts|sh)|/)$")
TICKED = re.compile(r"`([^`]+)`")


def tables(text: str) -> dict[str, list[list[str]]]:
    """Each table of the page by its header's first two cells ("runner/check"): its rows as cells."""
    out, rows, key = {}, None, None
    for line in text.splitlines() + [""]:
        if line.startswith("|"):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if rows is None:
                rows, key = [], "/".join(cells[:2])
            elif not set("".join(cells)) <= set("-: "):
                rows.append(cells)
        elif rows is not None:
            out[key], rows = rows, None
    return out


def paths_in(cell: str) -> list[str]:
    return [t for t in TICKED.findall(cell) if PATH.match(t)]


def missing(text: str, repo: Path) -> list[str]:
    """The page's paths that are not in the tree at `repo`, each with the runner and row it is in."""
    t = tables(text)
    roots = {row[0]: paths_in(row[1]) for row in t["runner/paths start at"]}
    out = [f"{runner}: root {root}" for runner, rs in roots.items() for root in rs if not (repo / root).is_dir()]
    for row in t["concept/Python"]:
        assert len(row) == 1 + len(RUNNERS), f"row {row[0]!r} has {len(row)} cells"
        for runner, cell in zip(RUNNERS, row[1:]):
            for p in paths_in(cell):
                if not any((repo / root / p).exists() for root in roots[runner]):
                    out.append(f"{runner}, {row[0]}: {p}")
    for row in t["runner/check"]:   # the circle checks: paths from the repository's root
        out += [f"{row[0]}, circles: {p}" for p in paths_in(row[1] + row[2]) if "/" in p and not (repo / p).exists()]
    return out


def test_every_file_the_page_names_exists():
    text = PAGE.read_text(encoding="utf-8")
    t = tables(text)
    assert [row[0] for row in t["runner/paths start at"]] == RUNNERS
    assert [row[0] for row in t["runner/check"]] == RUNNERS
    assert len(t["concept/Python"]) == 18
    assert sum(len(paths_in(c)) for row in t["concept/Python"] for c in row[1:]) > 100
    assert missing(text, REPO) == []


def test_a_missing_file_is_named(tmp_path):
    (tmp_path / "py").mkdir()
    (tmp_path / "py" / "suite.py").write_text("")
    (tmp_path / ".ci").mkdir()
    page = "\n".join([
        "| runner | paths start at |", "|---|---|",
        *[f"| {r} | `py/` |" for r in RUNNERS], "",
        "| concept | " + " | ".join(RUNNERS) + " |", "|---" * 7 + "|",
        "| loading | `suite.py`: `Suite.load` | `gone.c` | none | `sub/` | `Suite.java` | `suite.py` |", "",
        "| runner | check | run by |", "|---|---|---|",
        "| Python | `.ci/circles.py` | `.ci/lang/x.sh` |", "",
    ])
    assert missing(page, tmp_path) == ["C, loading: gone.c", "Go, loading: sub/", "Java, loading: Suite.java",
                                       "Python, circles: .ci/circles.py", "Python, circles: .ci/lang/x.sh"]
