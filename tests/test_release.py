"""`plcvec release`: what the bundle holds, that two runs give the same bytes, and the version rule."""
import gzip
import hashlib
import io
import json
import os
import re
import shutil
import subprocess
import sys
import tarfile
import zipfile
from pathlib import Path

import pytest

from plcvec import __version__
from plcvec.errors import PlcvecError
from plcvec.release import bundle, changes

from conftest import REPO

NAME = f"plcvec-vectors-{__version__}"
FAMILY = "fx5-time-add"


def release(out, *args, hashseed):
    env = dict(os.environ, PYTHONHASHSEED=str(hashseed))   # set and dict order must not leak into the bytes
    return subprocess.run([sys.executable, "-m", "plcvec", "release", "--out", str(out), *args],
                          capture_output=True, text=True, cwd=REPO, env=env, timeout=900)


@pytest.fixture(scope="module")
def previous(tmp_path_factory):
    """An older release's vector folder: one vector of FAMILY missing, another with a different result."""
    folder = tmp_path_factory.mktemp("previous") / "vectors"
    shutil.copytree(REPO / "vectors", folder)
    path = folder / f"{FAMILY}.json"
    data = json.loads(path.read_text(encoding="utf-8"))
    dropped = data["vectors"].pop(0)
    changed = data["vectors"][0]
    changed["final"]["devices"] = {k: (v + 1 if isinstance(v, int) and not isinstance(v, bool) else v)
                                   for k, v in changed["final"]["devices"].items()}
    path.write_text(json.dumps(data), encoding="utf-8")
    manifest = json.loads((folder / "manifest.json").read_text(encoding="utf-8"))
    manifest["suite_version"] = manifest["generator_version"] = "0.0.1"
    (folder / "manifest.json").write_text(json.dumps(manifest), encoding="utf-8")
    return folder, dropped["id"], changed["id"]


@pytest.fixture(scope="module")
def released(tmp_path_factory, previous):
    """One release, the folder it was written to (test_two_runs_give_identical_archives makes another)."""
    out = tmp_path_factory.mktemp("release1")
    _release_checked(out, previous[0], hashseed=1, jobs=1)
    return out


def _release_checked(out, previous_folder, hashseed, jobs):
    proc = release(out, "--previous", str(previous_folder), "--jobs", str(jobs), hashseed=hashseed)
    assert proc.returncode == 0, proc.stderr
    assert "Traceback" not in proc.stderr


def members(out):
    with tarfile.open(out / f"{NAME}.tar.gz") as tar:
        return {m.name: tar.extractfile(m).read() for m in tar.getmembers()}, tar.getmembers()


@pytest.mark.slow
def test_two_runs_give_identical_archives(released, previous, tmp_path):
    """A second whole release (slow: the default run checks one release's content, this its bytes
    again), with another hash seed and another number of worker processes: neither may change a byte."""
    _release_checked(tmp_path, previous[0], hashseed=2, jobs=2)
    for name in (f"{NAME}.tar.gz", f"{NAME}.zip", f"plcvec-c-{__version__}.tar.gz"):
        assert (released / name).read_bytes() == (tmp_path / name).read_bytes(), name


def test_archives_carry_no_time_or_owner(released):
    raw = (released / f"{NAME}.tar.gz").read_bytes()
    assert raw[:2] == b"\x1f\x8b" and raw[4:8] == b"\0\0\0\0"        # gzip MTIME field (RFC 1952): 0
    assert not raw[3] & 0x08                                          # FLG.FNAME: no file name stored
    _, infos = members(released)
    assert [i.name for i in infos] == sorted(i.name for i in infos)
    assert {(i.mtime, i.uid, i.gid, i.uname, i.gname, i.mode) for i in infos} == {(315532800, 0, 0, "", "", 0o644)}
    with zipfile.ZipFile(released / f"{NAME}.zip") as z:
        assert {i.date_time for i in z.infolist()} == {(1980, 1, 1, 0, 0, 0)}
        assert sorted(z.namelist()) == sorted(members(released)[0])


def test_bundle_holds_every_part_and_the_sums_match(released):
    files, _ = members(released)
    root = NAME + "/"
    manifest = json.loads((REPO / "vectors" / "manifest.json").read_text(encoding="utf-8"))
    expected = {"CHANGES.md", "CONTRACT.md", "PROTOCOL.md", "SHA256SUMS", "review/review.html", "review/review.md",
                "vectors/manifest.json", "vectors/vectors.csv", "vectors/schema/vector-file.schema.json"}
    expected |= {f"vectors/{e['file']}" for e in manifest["families"].values()}
    expected |= {f"jsonl/{name}.jsonl" for name in manifest["families"]}
    names = {n[len(root):] for n in files}
    assert expected <= names
    assert any(n.startswith("protocol/") and n.endswith(".schema.json") for n in names)
    # The committed files, byte for byte, and the documents as they are.
    for name in ("vectors/manifest.json", "vectors/vectors.csv", f"vectors/{FAMILY}.json"):
        assert files[root + name] == (REPO / name).read_bytes(), name
    assert files[root + "CONTRACT.md"] == (REPO / "verifiers" / "CONTRACT.md").read_bytes()
    # SHA256SUMS: every other file once, in sha256sum's format.
    listed = {}
    for line in files[root + "SHA256SUMS"].decode().splitlines():
        digest, name = line.split("  ", 1)
        listed[name] = digest
    assert set(listed) == names - {"SHA256SUMS"}
    for name, digest in listed.items():
        assert hashlib.sha256(files[root + name]).hexdigest() == digest, name


def test_bundle_carries_its_licence_readme_index_and_outer_sums(released):
    files, _ = members(released)
    root = NAME + "/"
    assert files[root + "LICENSE"] == (REPO / "LICENSE").read_bytes()
    readme = files[root + "README.md"].decode()
    assert "--vectors jsonl" in readme and "PLCVEC_VECTORS" in readme and "MIT" in readme
    # jsonl/index.json: every family file with its count of vector lines and its sha256.
    index = json.loads(files[root + "jsonl/index.json"])
    manifest = json.loads((REPO / "vectors" / "manifest.json").read_text(encoding="utf-8"))
    assert set(index["families"]) == set(manifest["families"])
    for name, entry in index["families"].items():
        data = files[root + "jsonl/" + entry["file"]]
        assert entry["sha256"] == hashlib.sha256(data).hexdigest()
        assert entry["count"] == data.count(b"\n") - 1 == manifest["families"][name]["count"]
    assert index["total"] == sum(e["count"] for e in manifest["families"].values())
    assert index["spec_sha256"] == manifest["spec_sha256"]
    # SHA256SUMS beside the archives: both archives, checkable before unpacking.
    outer = dict(reversed(line.split("  ", 1)) for line in (released / "SHA256SUMS").read_text().splitlines())
    assert set(outer) == {f"{NAME}.tar.gz", f"{NAME}.zip", f"plcvec-c-{__version__}.tar.gz"}
    for name, digest in outer.items():
        assert hashlib.sha256((released / name).read_bytes()).hexdigest() == digest


def test_the_c_source_archive_is_the_tracked_c_folder_and_the_licence(released):
    """What the C README's FetchContent downloads: every tracked file of verifiers/c, the LICENSE, no more."""
    name = f"plcvec-c-{__version__}"
    with tarfile.open(released / f"{name}.tar.gz") as tar:
        files = {m.name: tar.extractfile(m).read() for m in tar.getmembers()}
    tracked = subprocess.run(["git", "ls-files", "--", "verifiers/c"], cwd=REPO, capture_output=True, text=True,
                             check=True).stdout.split()
    assert set(files) == {f"{name}/{t[len('verifiers/c/'):]}" for t in tracked} | {f"{name}/LICENSE"}
    assert files[f"{name}/CMakeLists.txt"] == (REPO / "verifiers" / "c" / "CMakeLists.txt").read_bytes()
    assert files[f"{name}/LICENSE"] == (REPO / "LICENSE").read_bytes()


def test_jsonl_is_the_header_then_one_canonical_vector_per_line(released):
    files, _ = members(released)
    family = json.loads((REPO / "vectors" / f"{FAMILY}.json").read_text(encoding="utf-8"))
    lines = files[f"{NAME}/jsonl/{FAMILY}.jsonl"].decode("utf-8").split("\n")
    assert lines[-1] == ""
    lines = lines[:-1]
    assert len(lines) == 1 + len(family["vectors"])
    header = {k: v for k, v in family.items() if k != "vectors"}
    assert json.loads(lines[0]) == header
    for line, vector in zip(lines[1:], family["vectors"]):
        assert json.loads(line) == vector
        assert line == json.dumps(vector, sort_keys=True, separators=(",", ":"), ensure_ascii=False)


def test_changes_lists_what_differs_from_the_previous_release(released, previous):
    _, dropped, changed = previous
    files, _ = members(released)
    text = files[f"{NAME}/CHANGES.md"].decode("utf-8")
    assert f"# plcvec-vectors {__version__}" in text and "since 0.0.1" in text
    assert f"  + {dropped}\n" in text                      # absent before: added now
    assert f"  ~ {changed} (expectation)\n" in text
    assert f"{FAMILY}: 1 added, 1 expectation changed" in text


def test_a_release_archive_can_be_the_previous_release(released):
    found = changes.load_previous(str(released / f"{NAME}.tar.gz"))
    current = changes.load_previous(str(REPO / "vectors"))
    assert found.manifest["suite_version"] == found.manifest["generator_version"] == __version__
    assert {n: set(f["vectors"]) for n, f in found.families.items()} == \
        {n: set(f["vectors"]) for n, f in current.families.items()}
    zipped = changes.load_previous(str(released / f"{NAME}.zip"))
    assert zipped.count() == current.count()


def test_a_damaged_archive_is_named(tmp_path):
    bad = tmp_path / "old.tar.gz"
    bad.write_bytes(gzip.compress(b"not a tar"))
    with pytest.raises(PlcvecError, match="old.tar.gz"):
        changes.load_previous(str(bad))
    empty = tmp_path / "empty.zip"
    with zipfile.ZipFile(empty, "w") as z:
        z.writestr("README", "x")
    with pytest.raises(PlcvecError, match="no vectors/manifest.json"):
        changes.load_previous(str(empty))


def _report(**counts):
    totals = dict.fromkeys(("added", "removed", "expectation", "inputs", "metadata"), 0)
    totals.update(counts)
    return {"totals": totals, "identical": not any(totals.values())}


@pytest.mark.parametrize("counts, bump", [
    ({"added": 1}, "minor"), ({"removed": 2}, "minor"), ({"expectation": 1}, "minor"), ({"inputs": 1}, "minor"),
    ({"metadata": 3}, "patch"), ({}, None)])
def test_the_bump_contract_md_asks_for(counts, bump):
    assert changes.required_bump(_report(**counts), "1.0.0", "1.0.0") == bump
    assert changes.required_bump(_report(**counts), "1.0.0", "2.0.0") == "major"


@pytest.mark.parametrize("new, old, bump, ok", [
    ("0.2.0", "0.1.0", "minor", True), ("0.1.1", "0.1.0", "minor", False), ("1.0.0", "0.9.3", "minor", True),
    ("0.1.1", "0.1.0", "patch", True), ("0.1.0", "0.1.0", "patch", False), ("0.1.0", "0.1.0", None, True),
    ("0.9.0", "1.0.0", None, False), ("1.0.0", "0.5.0", "major", True), ("0.6.0", "0.5.0", "major", False)])
def test_the_version_must_move_far_enough(new, old, bump, ok):
    if ok:
        changes.check_version(new, old, bump)
    else:
        with pytest.raises(PlcvecError, match="version"):
            changes.check_version(new, old, bump)


def test_first_release_says_so(tmp_path):
    from plcvec.output import diff

    current = diff.load_set(str(REPO / "vectors"))
    text, report = changes.changes_text("9.9.9", current)
    assert report is None
    assert "The first release" in text and f"Total: {current.count()} vectors." in text


def test_the_bundles_changes_carry_the_projects_changelog_and_its_vectors(released):
    """CHANGES.md in the bundle is the project's CHANGES.md as it is, this version's entry included,
    then the vectors that changed since the previous release, by id."""
    with tarfile.open(released / f"{NAME}.tar.gz") as tar:
        text = tar.extractfile(f"{NAME}/CHANGES.md").read().decode()
    project = bundle.relinked("CHANGES.md", (REPO / "CHANGES.md").read_text(encoding="utf-8"))
    assert text.startswith(project.rstrip("\n") + "\n")
    assert f"## [{__version__}]" in text
    assert f"# The vectors of {__version__}, by id" in text


def test_a_version_without_its_changelog_entry_is_refused():
    with pytest.raises(PlcvecError, match=r"no entry for 9\.9\.9"):
        changes.changelog_entry("# Changes\n\n## [0.2.0] - 2026-11-27\n\n### Added\n- x\n", "9.9.9")
    entry = changes.changelog_entry("# Changes\n\n## [0.2.0] - 2026-11-27\n\n### Added\n- x\n\n## [0.1.0]\n- y\n", "0.2.0")
    assert entry == "## [0.2.0] - 2026-11-27\n\n### Added\n- x\n"


def _slug(heading: str) -> str:
    """GitHub's anchor of a Markdown heading: lower case, punctuation dropped, spaces as hyphens."""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


def test_every_link_in_the_bundles_markdown_resolves_inside_it(released):
    """A consumer of the bundle alone meets no dead link: every relative link of every Markdown file
    names a file or folder the bundle holds, and every #anchor a heading of its target."""
    with tarfile.open(released / f"{NAME}.tar.gz") as tar:
        files = {m.name[len(NAME) + 1:]: m for m in tar.getmembers()}
        texts = {name: tar.extractfile(m).read().decode() for name, m in files.items()
                 if name.endswith(".md") and m.isfile()}
    folders = {str(Path(n).parent.as_posix()) + "/" for n in files} | {p for n in files for p in
                                                                          [str(q.as_posix()) + "/" for q in Path(n).parents]}
    dead = []
    for name, text in texts.items():
        text = re.sub(r"```.*?```", "", text, flags=re.S)           # links in code are not links
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            if re.match(r"[a-z]+:", target):                         # https://, mailto: leave the bundle
                continue
            path, _, anchor = target.partition("#")
            where = (Path(name).parent / path).as_posix() if path else name
            where = os.path.normpath(where)
            if path and where not in files and where + "/" not in folders:
                dead.append(f"{name}: {target}")
                continue
            if anchor:
                target_text = texts.get(where, "")
                anchors = {_slug(h) for h in re.findall(r"^#+ (.+)$", target_text, re.M)}
                anchors |= set(re.findall(r'<a id="([^"]+)"', target_text))
                if anchor not in anchors:
                    dead.append(f"{name}: {target} (no such heading)")
    assert not dead, dead
    assert "parity/TEXT.md" in files and "parity/text/expected.txt" in files
    assert "jsonl/schema/vector-file.schema.json" in files
