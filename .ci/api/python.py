#!/usr/bin/env python3
"""The Python runner's public API (plcvec_verify) against the previous release, as griffe sees it.

    python3 .ci/api/python.py                  # this tree against the previous release
    python3 .ci/api/python.py --new DIR        # another copy of verifiers/python against it

Every change griffe calls breaking must be listed under **Breaking** in CHANGES.md's entry for this
version, with its object in backticks (`plcvec_verify.compare.Problem`), and the version must move
as CONTRACT.md's compatibility policy says; otherwise exit 1 naming each unlisted change. Exit 2 when
the previous release cannot be read. A name the previous release had that is now an import of a name
that no longer exists (a re-export left behind by a move) counts as removed: griffe's comparison does
not follow it.
"""
from __future__ import annotations

import argparse
import fcntl
import re
import subprocess
import sys
import time
from contextlib import contextmanager
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
PACKAGE = "plcvec_verify"
# The previous release, by its commit (a shallow clone without it cannot make the check: exit 2).
PREVIOUS = ("0.1.0", "9ebc6da")


def breaking_section(version: str) -> str:
    """The Breaking part of CHANGES.md's entry for `version` ('' when it has none)."""
    sys.path.insert(0, str(REPO / "generator"))
    from plcvec.release.changes import changelog_entry

    entry = changelog_entry((REPO / "CHANGES.md").read_text(encoding="utf-8"), version)
    m = re.search(r"^### Breaking\n(.*?)(?=^### |\Z)", entry, re.S | re.M)
    return m.group(1) if m else ""


def unlisted(breakages, section: str) -> list[str]:
    """The breakages whose object (module.Name: the top-level name of its path) is not in backticks in
    the Breaking section."""
    out = []
    for b in breakages:
        parts = b.obj.path.split(".")
        # plcvec_verify.compare.Problem.__init__ -> plcvec_verify.compare.Problem
        name = ".".join(parts[:3]) if len(parts) >= 3 else b.obj.path
        if f"`{name}`" not in section:
            out.append(f"{name}: {b.kind.value} ({b.obj.path})")
    return out


def _modules(module):
    yield module
    for sub in module.modules.values():
        yield from _modules(sub)


def dangling_reexports(old, new) -> list[str]:
    """Names of the previous release that are now an import of a name that no longer exists (a module
    moved, its old home importing it back for its users, then the moved name renamed): griffe's
    comparison does not follow such an import, and Python would fail on it at import time."""
    import griffe

    out = []
    for module in _modules(new):
        for name, member in module.members.items():
            if not member.is_alias or not member.target_path.startswith(PACKAGE + "."):
                continue
            try:
                member.final_target
            except (griffe.AliasResolutionError, griffe.CyclicAliasError):
                if _resolves(old, f"{module.path}.{name}"[len(PACKAGE) + 1:]):
                    out.append(f"{module.path}.{name}")
    return out


def _resolves(package, path: str) -> bool:
    """Whether `path` names an object of `package` that griffe can follow to its definition (not one the
    previous release lacked, nor one griffe cannot see either way, such as `A, B = 1, 2`)."""
    import griffe

    try:
        member = package[path]
        if member.is_alias:
            member.final_target
    except (KeyError, griffe.AliasResolutionError, griffe.CyclicAliasError):
        return False
    return True


def unlisted_names(paths, section: str) -> list[str]:
    return [f"{p}: public object was removed (it imports {p.rpartition('.')[2]} from where it no longer is)"
            for p in paths if f"`{p}`" not in section]


LOCK_WAIT_S = 300


@contextmanager
def _one_at_a_time():
    """griffe.load_git checks the commit out on a branch named after it (griffe-<ref>): two checks at
    once in one clone (the tests, in parallel) collide on that branch. A lock in the clone's git folder
    makes the second wait for the first, for LOCK_WAIT_S at most."""
    git_dir = subprocess.run(["git", "rev-parse", "--absolute-git-dir"], cwd=REPO, capture_output=True,
                             text=True, check=True).stdout.strip()
    with open(Path(git_dir) / "plcvec-api-check.lock", "w") as lock:
        deadline = time.monotonic() + LOCK_WAIT_S
        while True:
            try:
                fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
                break
            except BlockingIOError:
                if time.monotonic() > deadline:
                    raise RuntimeError(f"another API check held {lock.name} for {LOCK_WAIT_S} s") from None
                time.sleep(0.1)
        yield


def main(argv=None) -> int:
    import griffe

    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--new", default=str(REPO / "verifiers" / "python"), help="the folder holding plcvec_verify")
    args = p.parse_args(argv)
    sys.path.insert(0, str(REPO / "generator"))
    from plcvec import __version__

    version, commit = PREVIOUS
    try:
        with _one_at_a_time():
            old = griffe.load_git(PACKAGE, ref=commit, repo=REPO, search_paths=["verifiers/python"])
    except Exception as exc:   # a clone without the commit: nothing to compare against is no pass
        print(f"api check (python): cannot read {PACKAGE} at {version} ({commit}): {exc}", file=sys.stderr)
        return 2
    new = griffe.load(PACKAGE, search_paths=[args.new], try_relative_path=False)
    found = list(griffe.find_breaking_changes(old, new))
    missing = unlisted(found, breaking_section(__version__))
    dangling = dangling_reexports(old, new)
    found += dangling
    missing += unlisted_names(dangling, breaking_section(__version__))
    major_or_minor = tuple(map(int, __version__.split(".")))[:2] > tuple(map(int, version.split(".")))[:2]
    if found and not major_or_minor:
        missing.append(f"{len(found)} breaking changes, but {__version__} is not a new minor or major release")
    for line in missing:
        print(f"api check (python): breaking, not under Breaking in CHANGES.md {__version__}: {line}", file=sys.stderr)
    print(f"api check (python): {PACKAGE} {__version__} against {version}: {len(found)} breaking changes, "
          f"{len(found) - len(missing)} listed")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
