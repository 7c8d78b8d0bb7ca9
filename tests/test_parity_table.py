"""The shared table of faults and its runner: the table loads, each damage makes the fault it names
(and only that one), a row is judged as its verdict says; and the README snippet extractor refuses
an unmarked block."""
import hashlib
import importlib.util
import json
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import REPO

ON = "fx5-time-add/TADD/manual-example/program"


def _module(path: Path, name: str):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


parity = _module(REPO / "verifiers" / "parity" / "run.py", "parity_run")
snippets = _module(REPO / ".ci" / "readme_snippets.py", "readme_snippets")


def test_table_loads_and_every_vector_it_names_exists():
    rows = parity.load_table()
    assert len({r.id for r in rows}) == len(rows) >= 40
    ids = set()
    for family in (REPO / "vectors").glob("*.json"):
        if family.name != "manifest.json":
            ids |= {v["id"] for v in json.loads(family.read_text())["vectors"]}
    for r in rows:
        assert r.on is None or r.on in ids, r.id
        # The settings, plus the one misspelling and the hostile's choice the rows about them set.
        assert set(r.env) <= {"PLCVEC_ID", "PLCVEC_FAMILY", "PLCVEC_INSTRUCTION", "PLCVEC_TAG",
                              "PLCVEC_INTERPRETATION", "PLCVEC_SHARD", "PLCVEC_KNOWN_FAILURES",
                              "PLCVEC_TIMEOUT", "PLCVEC_TAGG", "PLCVEC_HOSTILE_CHOICE"}, r.id
    # Every damage the runner knows is used by some row, and every verdict appears.
    assert {r.damage for r in rows if r.damage} == set(parity.DAMAGES)
    assert {r.verdict for r in rows} == set(parity.STATUS)


def test_table_refuses_a_bad_row(tmp_path):
    bad = tmp_path / "faults.toml"
    bad.write_text('[[fault]]\nid = "x"\nwhat = "y"\nverdict = "green"\n')
    with pytest.raises(parity.TableError, match="verdict must be one of"):
        parity.load_table(bad)
    bad.write_text('[[fault]]\nid = "x"\nwhat = "y"\nverdict = "pass"\ncolour = 1\n')
    with pytest.raises(parity.TableError, match="unknown key"):
        parity.load_table(bad)
    bad.write_text('[[fault]]\nid = "x"\nwhat = "y"\nverdict = "pass"\n[fault.except.go]\nverdict = "fail"\n')
    with pytest.raises(parity.TableError, match="why"):
        parity.load_table(bad)


@pytest.fixture(scope="module")
def folders(tmp_path_factory):
    return parity.Folders(tmp_path_factory.mktemp("damaged"))


def _sealed(folder) -> bool:
    entry = json.loads(folder.index.read_text())["families"][folder.family]
    return entry["sha256"] == hashlib.sha256(folder.file.read_bytes()).hexdigest()


@pytest.mark.parametrize("form", ["json", "jsonl"])
def test_structural_damages_are_the_only_fault(folders, form):
    f = folders.get("unknown-key", form, ON)
    header, vectors = f.read()
    assert [v.get("surprise") for v in vectors if v["id"] == ON] == [1]
    assert _sealed(f)
    f = folders.get("duplicate-id", form, ON)
    _, vectors = f.read()
    assert [v["id"] for v in vectors].count(ON) == 2 and _sealed(f)
    assert json.loads(f.index.read_text())["families"][f.family]["count"] == len(vectors)
    f = folders.get("bit-holds-2", form, ON)
    _, vectors = f.read()
    target = next(v for v in vectors if v["id"] == ON)
    golden = next(v for v in json.loads((REPO / "vectors" / "fx5-time-add.json").read_text())["vectors"] if v["id"] == ON)
    # One device changed, from a bit to the number 2, and the vector still holds that device as a bit
    # after the step: the fault is a bit holding 2, not a word holding 2.
    changed = {d: x for d, x in target["initial"]["devices"].items() if (type(x), x) != (type(golden["initial"]["devices"][d]), golden["initial"]["devices"][d])}
    assert len(changed) == 1 and list(changed.values()) == [2], changed
    (device,) = changed
    assert type(golden["initial"]["devices"][device]) is bool and type(target["final"]["devices"][device]) is bool
    f = folders.get("sha-mismatch", form, ON)
    assert not _sealed(f)
    f = folders.get("empty-family", form, ON)
    assert f.read()[1] == [] and _sealed(f)


@pytest.mark.parametrize("form", ["json", "jsonl"])
def test_byte_damages(folders, form):
    f = folders.get("non-utf8", form, ON)
    data = f.file.read_bytes()
    with pytest.raises(UnicodeDecodeError):
        data.decode("utf-8")
    assert _sealed(f)  # only the byte is wrong: a runner must notice it itself
    f = folders.get("cut-at-line", form, ON)
    assert f.file.read_bytes().endswith(b"\n") and not _sealed(f)
    assert ON.encode() not in f.file.read_bytes()
    f = folders.get("not-json", form, ON)
    assert b'{"id": this is not JSON' in f.file.read_bytes()


def test_a_row_is_judged_by_its_verdict(tmp_path, monkeypatch):
    """A stand-in entry shows the judging: exit status class, names, a trace for a usage error."""
    entry = tmp_path / "verifiers" / "go" / "faults-entry"
    entry.parent.mkdir(parents=True)
    entry.write_text("#!/bin/sh\necho \"vector $PLCVEC_HOSTILE_ON failed\"\nexit ${CODE:-1}\n")
    entry.chmod(0o755)
    monkeypatch.setattr(parity, "REPO", tmp_path)
    row = parity.Row(id="r", what="w", verdict="fail", names=["{on}"], hostile="panic", on=ON)
    scratch = tmp_path / "s"
    assert parity.run_row("go", row, None, scratch, 30).ok
    monkeypatch.setenv("CODE", "0")
    out = parity.run_row("go", row, None, scratch, 30)
    assert not out.ok and "expected non-zero" in out.why
    row.names = ["something else"]
    monkeypatch.setenv("CODE", "1")
    assert "does not name" in parity.run_row("go", row, None, scratch, 30).why
    entry.write_text("#!/bin/sh\necho 'goroutine 1 [running]:'\nexit 2\n")
    usage = parity.Row(id="u", what="w", verdict="usage")
    assert "stack trace" in parity.run_row("go", usage, None, scratch, 30).why
    entry.write_text("#!/bin/sh\nsleep 30\n")
    assert "hang" in parity.run_row("go", usage, None, scratch, 1).why


def test_readme_snippets_refuse_an_unmarked_block(tmp_path):
    md = tmp_path / "README.md"
    md.write_text("# x\n\n<!-- snippet: a/run.sh -->\n```sh\necho hi\n```\n\n```sh\nls\n```\n")
    found, problems = snippets.blocks(md)
    assert [b.kind for b in found] == ["snippet", None]
    assert problems == [f"{md}:8: a fenced block with no <!-- snippet: PATH --> or "
                        "<!-- snippet-skip: REASON --> marker on the line before it"]
    md.write_text("<!-- snippet: ../out.sh -->\n```sh\nx\n```\n<!-- snippet-skip: -->\n```\ny\n```\n")
    _, problems = snippets.blocks(md)
    assert "leaves the output folder" in problems[0] and "gives no reason" in problems[1]


def test_readme_snippets_extract(tmp_path):
    md = tmp_path / "README.md"
    md.write_text("<!-- snippet: go/main.go -->\n\n````go\npackage main\n```\n````\n"
                  "<!-- snippet-skip: output -->\n```\nok\n```\n")
    out = tmp_path / "out"
    r = subprocess.run([sys.executable, str(REPO / ".ci" / "readme_snippets.py"), "extract", str(md),
                        "--out", str(out)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert (out / "go" / "main.go").read_text() == "package main\n```\n"


def _tree(root: Path) -> dict:
    """{relative path: bytes, or the target of a symbolic link} of every file under root."""
    return {str(p.relative_to(root)): (("link", str(p.readlink())) if p.is_symlink() else p.read_bytes())
            for p in sorted(root.rglob("*")) if p.is_symlink() or p.is_file()}


def test_a_shared_cache_makes_each_folder_once_and_every_run_gets_the_same_bytes(tmp_path, monkeypatch):
    made = []
    damage = parity.damage
    monkeypatch.setattr(parity, "damage", lambda folder, kind: (made.append(kind), damage(folder, kind))[1])
    alone = parity.Folders(tmp_path / "alone")
    first = parity.Folders(tmp_path / "first", parity.Cache(tmp_path / "cache"))
    second = parity.Folders(tmp_path / "second", parity.Cache(tmp_path / "cache"))
    for kind in ("unknown-key", "cut-mid-line", "missing-file"):
        want = _tree(alone.get(kind, "json", ON).root)
        assert _tree(first.get(kind, "json", ON).root) == want, kind
        assert _tree(second.get(kind, "json", ON).root) == want, kind
    # Made alone, then once for the two runs that share the cache.
    assert made == ["unknown-key", "unknown-key", "cut-mid-line", "cut-mid-line", "missing-file", "missing-file"]
    # Each run has a copy of its own: what one run's runner does to its folder, the other's never sees.
    copy = second.get("unknown-key", "json", ON)
    copy.file.write_text("changed")
    assert first.get("unknown-key", "json", ON).file.read_text() != "changed"
    # A pipe is made anew in each run, never copied (a copy would block reading it).
    assert first.get("fifo", "json", ON).file.is_fifo() and second.get("fifo", "json", ON).file.is_fifo()
    assert made[-2:] == ["fifo", "fifo"]


def test_a_cache_folder_another_run_is_still_making_is_waited_for_within_a_bound(tmp_path, monkeypatch):
    import fcntl
    cache = parity.Cache(tmp_path / "cache")
    lock = open(cache.root / ".unknown-key-json-x.lock", "w")
    fcntl.flock(lock, fcntl.LOCK_EX)   # the other run, still making it
    monkeypatch.setattr(parity, "CACHE_BOUND_S", 0.3)
    with pytest.raises(parity.TableError, match="another run has been making it"):
        cache.copy("unknown-key-json-x", tmp_path / "dest", lambda folder: folder.mkdir())
    lock.close()
    cache.copy("unknown-key-json-x", tmp_path / "dest", lambda folder: folder.mkdir())
    assert (tmp_path / "dest").is_dir()


def test_a_cache_is_keyed_by_the_vectors_it_was_made_from(tmp_path, monkeypatch):
    before = parity.Cache(tmp_path / "cache").root
    manifest = tmp_path / "repo" / "vectors" / "manifest.json"
    manifest.parent.mkdir(parents=True)
    manifest.write_text((REPO / "vectors" / "manifest.json").read_text() + " ")
    monkeypatch.setattr(parity, "REPO", tmp_path / "repo")
    assert parity.Cache(tmp_path / "cache").root != before


def test_an_unusable_cache_folder_is_a_usage_error_naming_it(tmp_path, capsys):
    (tmp_path / "file").write_text("")
    assert parity.main(["--lang", "python", "--cache", str(tmp_path / "file" / "cache")]) == 2
    assert f"--cache {tmp_path / 'file' / 'cache'}:" in capsys.readouterr().err
