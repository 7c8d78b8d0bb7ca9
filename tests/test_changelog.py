"""The changelog people upgrade by: CHANGES.md has an entry for the version every package carries, in
the shape it promises, every package points to it, and no vector id of an earlier release goes away
unnoticed (verifiers/CONTRACT.md, "Compatibility policy")."""
import json
import re
import subprocess
import tomllib

import pytest

from plcvec import __version__
from plcvec.release.changes import changelog_entry

from conftest import REPO

CHANGES = (REPO / "CHANGES.md").read_text(encoding="utf-8")
HEADINGS = ("Breaking", "Added", "Changed", "Deprecated", "Fixed")
# The releases whose vector ids the policy keeps: each earlier release's commit.
RELEASES = {"0.1.0": "9ebc6da"}


def test_the_version_every_package_carries_has_its_entry():
    entry = changelog_entry(CHANGES, __version__)
    assert re.match(rf"## \[{re.escape(__version__)}\] - \d{{4}}-\d{{2}}-\d{{2}}\n", entry)
    found = re.findall(r"^### (.+)$", entry, re.M)
    assert found and set(found) <= set(HEADINGS), found
    assert found == [h for h in HEADINGS if h in found], "the headings in Keep a Changelog's order"


def test_every_release_heading_is_a_version_with_a_link():
    versions = re.findall(r"^## \[(\d+\.\d+\.\d+)\]", CHANGES, re.M)
    assert versions[0] == __version__, "the newest entry first, and it is this version's"
    assert versions == sorted(versions, key=lambda v: tuple(map(int, v.split("."))), reverse=True)
    for v in versions:
        assert re.search(rf"^\[{re.escape(v)}\]: https://", CHANGES, re.M), f"no link for [{v}]"


def test_a_package_version_that_moved_without_an_entry_fails():
    """What CI holds every package to: the check above, made on a changelog that lacks the version."""
    with pytest.raises(Exception, match="no entry for"):
        changelog_entry(CHANGES.replace(f"## [{__version__}]", "## [0.0.0]"), __version__)


def test_every_package_points_to_the_changelog():
    pyproject = tomllib.loads((REPO / "pyproject.toml").read_text(encoding="utf-8"))
    assert pyproject["project"]["urls"]["Changelog"] == pyproject["tool"]["plcvec"]["home"] + "/blob/main/CHANGES.md"
    for readme in [REPO / "README.md", *sorted((REPO / "verifiers").glob("*/README.md"))]:
        if readme.parent.name == "parity":
            continue
        text = readme.read_text(encoding="utf-8")
        assert re.search(r"\]\((\.\./)*CHANGES\.md\)|/blob/main/CHANGES\.md\)", text), \
            f"{readme.relative_to(REPO)}: no link to CHANGES.md"


def _ids_at(rev: str) -> set:
    names = subprocess.run(["git", "ls-tree", "--name-only", f"{rev}:vectors"], cwd=REPO, capture_output=True,
                           text=True)
    if names.returncode != 0:
        pytest.skip(f"the history holds no {rev} (a shallow clone)")
    ids = set()
    for name in names.stdout.split():
        if name.endswith(".json") and name != "manifest.json":
            data = json.loads(subprocess.run(["git", "show", f"{rev}:vectors/{name}"], cwd=REPO,
                                             capture_output=True, text=True, check=True).stdout)
            ids |= {v["id"] for v in data["vectors"]}
    return ids


@pytest.mark.parametrize("version", sorted(RELEASES))
def test_no_vector_id_of_a_release_goes_away_unnoticed(version):
    """Every id of an earlier release is still a vector, or merged into one (the manifest's `merged`,
    which runners name in their stale message), or named in CHANGES.md as removed."""
    manifest = json.loads((REPO / "vectors" / "manifest.json").read_text(encoding="utf-8"))
    current = set()
    for entry in manifest["families"].values():
        current |= {v["id"] for v in json.loads((REPO / "vectors" / entry["file"]).read_text())["vectors"]}
    merged = {old for fam in manifest["merged"].values() for old in fam}
    gone = sorted(i for i in _ids_at(RELEASES[version]) - current - merged if f"`{i}`" not in CHANGES)
    assert not gone, f"{len(gone)} ids of {version} neither kept, merged nor named in CHANGES.md: {gone[:5]}"
