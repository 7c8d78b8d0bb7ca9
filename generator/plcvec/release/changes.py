"""The CHANGES file of a release: `plcvec diff` against the previous release, and the version rule.

The previous release is named by a folder (a vector folder, a checkout, or an unpacked release), a
release archive (.tar.gz or .zip, read in memory), or a git revision, as `plcvec diff` takes them.
The rule of verifiers/CONTRACT.md ("Suite version") is checked here: a release whose vectors differ
from the previous one in a way its version number does not admit is refused.
"""
import io
import json
import tarfile
import zipfile
from pathlib import Path

from plcvec.errors import PlcvecError
from plcvec.output import diff

ARCHIVES = (".tar.gz", ".tgz", ".zip")
MAX_MEMBER = 256 << 20     # a member larger than this is not a vector file


class _Archive:
    """The vector folder inside a release archive, read into memory (nothing is unpacked to disk)."""

    def __init__(self, path, files, prefix):
        self.path, self.files, self.prefix = path, files, prefix

    def label(self, name):
        return f"{self.path}:{self.prefix}{name}"

    def read(self, name):
        return self.files.get(self.prefix + name)


def _archive_members(path):
    try:
        if path.name.endswith(".zip"):
            with zipfile.ZipFile(path) as z:
                return {i.filename: z.read(i) for i in z.infolist() if not i.is_dir() and i.file_size <= MAX_MEMBER}
        with tarfile.open(path, "r:*") as tar:
            return {m.name: tar.extractfile(m).read() for m in tar.getmembers() if m.isfile() and m.size <= MAX_MEMBER}
    except (OSError, tarfile.TarError, zipfile.BadZipFile, EOFError) as exc:
        raise PlcvecError(f"--previous {path}: not a readable release archive ({exc})") from None


def _from_archive(path):
    files = _archive_members(path)
    # The bundle's own vector folder, not one nested deeper (parity/text/vectors holds the shared cases).
    manifests = sorted((n for n in files if n == "vectors/manifest.json" or n.endswith("/vectors/manifest.json")),
                       key=lambda n: (n.count("/"), n))
    if not manifests:
        raise PlcvecError(f"--previous {path}: no vectors/manifest.json inside; is it a plcvec release archive?")
    return diff.load_source(_Archive(path, files, manifests[0][:-len("manifest.json")]), path.name)


def load_previous(arg):
    """The previous release's vector set (with its manifest), from a folder, an archive or a git revision."""
    path = Path(arg)
    if path.is_file() and path.name.endswith(ARCHIVES):
        return _from_archive(path)
    found = diff.load_set(arg)
    if found.single:
        raise PlcvecError(f"--previous {arg}: a single family file; name the release's folder, archive or revision")
    return found


# ---------------------------------------------------------------------------------------------- versions
def parse_version(text, where):
    parts = str(text).split(".")
    if len(parts) != 3 or not all(p.isdigit() for p in parts):
        raise PlcvecError(f"{where}: suite version {text!r} is not MAJOR.MINOR.PATCH")
    return tuple(int(p) for p in parts)


def required_bump(report, old_schema, new_schema):
    """What CONTRACT.md asks of the version for this difference: "major", "minor", "patch" or None."""
    if old_schema.split(".")[0] != new_schema.split(".")[0]:
        return "major"
    t = report["totals"]
    if t["added"] or t["removed"] or t["expectation"] or t["inputs"]:
        return "minor"
    if not report["identical"] or old_schema != new_schema:
        return "patch"
    return None


def check_version(version, previous_version, bump):
    """A PlcvecError unless `version` moved at least as far past `previous_version` as `bump` asks."""
    new, old = parse_version(version, "this release"), parse_version(previous_version, "the previous release")
    if new < old:
        raise PlcvecError(f"suite version {version} is older than the previous release's {previous_version}")
    enough = {"major": new[0] > old[0], "minor": new[:2] > old[:2], "patch": new > old, None: True}[bump]
    if not enough:
        raise PlcvecError(f"suite version {version} after {previous_version}: the vectors changed in a way that needs a "
                          f"{bump} version (verifiers/CONTRACT.md, Suite version); raise the version and regenerate")


# ---------------------------------------------------------------------------------------------- the changelog
def changelog_entry(changelog: str, version: str, where: str = "CHANGES.md") -> str:
    """The section of the project's CHANGES.md for `version` (from its `## [version]` heading to the
    next `## ` heading); a PlcvecError when there is none: no release without its changelog entry."""
    lines = changelog.split("\n")
    start = next((i for i, line in enumerate(lines) if line.startswith(f"## [{version}]")), None)
    if start is None:
        raise PlcvecError(f"{where}: no entry for {version} (a heading `## [{version}] - DATE`); every release "
                          "says what it changed (verifiers/CONTRACT.md, Compatibility policy)")
    end = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("## ")), len(lines))
    return "\n".join(lines[start:end]).strip("\n") + "\n"


# ---------------------------------------------------------------------------------------------- the text
def changes_text(version, current, previous=None, previous_arg=None, changelog=None):
    """The bundle's CHANGES.md: the project's changelog as it is (`changelog`, checked to hold this
    version's entry), then the difference from the previous release by vector id, or the statement
    that there is none."""
    head = []
    if changelog is not None:
        changelog_entry(changelog, version)
        head = [changelog.rstrip("\n"), "", f"# The vectors of {version}, by id", ""]
    text, report = _vector_changes(version, current, previous, previous_arg)
    return "\n".join(head) + text, report


def _vector_changes(version, current, previous=None, previous_arg=None):
    title = f"# plcvec-vectors {version}"
    if previous is None:
        lines = [title, "", "The first release: no previous release was given (`plcvec release --previous`), so every",
                 "vector is new. Vectors per family:", ""]
        lines += [f"- {name}: {len(fam['vectors'])}" for name, fam in sorted(current.families.items())]
        lines.append(f"\nTotal: {current.count()} vectors.")
        return "\n".join(lines) + "\n", None
    report = diff.compare(previous, current)
    old_version = previous.manifest.get("suite_version") or previous.manifest.get("generator_version", "?")
    lines = [title, "", f"Changes since {old_version} ({previous_arg}), by vector id, as `plcvec diff` reports them:",
             "", "```", diff.render_text(report).rstrip("\n"), "```"]
    return "\n".join(lines) + "\n", report
