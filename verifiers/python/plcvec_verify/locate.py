"""Where the commands find the spec and the vectors when no path is given.

Two places can hold them:
- a checkout of the plcvec repository: its own `spec/` and `vectors/`. A checkout is the current
  folder or one of its parents holding a `pyproject.toml` of the project named plcvec (as git finds
  its repository); failing that, the source tree the package itself is imported from when it is not
  installed as a built wheel (an editable install, or PYTHONPATH pointing into a checkout).
- the installed package: a built wheel or sdist carries a copy of both as package data
  (`plcvec_verify/_data/vectors`, `plcvec/_data/spec`), found with importlib.resources.

A checkout wins: a developer working in one means its files, and `plcvec generate` may write only
there. The installed copy is read only: nothing is ever written into site-packages.
"""
from __future__ import annotations

import importlib.resources
import re
import sysconfig
from dataclasses import dataclass
from pathlib import Path

from .errors import VerifyError

PROJECT = "plcvec"
DATA = "_data"   # the package-data folder a built distribution adds (see setup.py)
_NAME = re.compile(r'^\s*name\s*=\s*["\']plcvec["\']\s*$', re.MULTILINE)


@dataclass(frozen=True)
class Location:
    """A folder and what it is: "checkout" (writable, the repository's own) or "installed" (read only)."""

    path: Path
    kind: str

    def describe(self) -> str:
        return f"{self.path} ({'the checkout' if self.kind == 'checkout' else 'installed with plcvec, read only'})"


def is_checkout(folder: Path) -> bool:
    """A plcvec repository: its pyproject.toml names the project plcvec."""
    try:
        return bool(_NAME.search((folder / "pyproject.toml").read_text(encoding="utf-8")))
    except (OSError, UnicodeDecodeError):
        return False


def checkout_of(start: Path) -> Path | None:
    """The checkout holding `start`, or None."""
    start = start.resolve()
    for folder in (start, *start.parents):
        if is_checkout(folder):
            return folder
    return None


def package_folder(package: str) -> Path | None:
    """The folder an importable package lives in, through importlib.resources (None if it is not a
    plain folder, as in a zip import, which the commands do not support)."""
    root = importlib.resources.files(package)
    return root if isinstance(root, Path) else None


def checkout() -> Path | None:
    """The checkout in use: the one around the current folder, else the source tree the package runs from."""
    found = checkout_of(Path.cwd())
    if found:
        return found
    here = package_folder(__package__)
    if here is None or (here / DATA).is_dir():
        return None   # a built install: its data is used, not a folder that happens to contain it
    # Not built: the package runs from its source folder (verifiers/python/plcvec_verify) in a checkout.
    return checkout_of(here)


def locate(package: str, name: str, marker: str) -> Location:
    """`name` (spec or vectors) of the checkout in use, else the copy installed with `package`.

    `marker` is a glob that must match inside the folder for it to count (a checkout without
    generated vectors is reported, not silently swapped for the installed ones)."""
    root = checkout()
    if root is not None:
        return Location(root / name, "checkout")
    folder = package_folder(package)
    if folder is not None and any((folder / DATA / name).glob(marker)):
        return Location(folder / DATA / name, "installed")
    raise VerifyError(f"no {name} folder found: not in a plcvec checkout, and the installed plcvec carries none "
                      f"(reinstall it from a wheel or sdist, or name the folder with an option)")


def default_vectors() -> Location:
    return locate(__package__, "vectors", "manifest.json")


def default_vectors_text() -> str:
    """For --help: the default vector folder and whose it is, or why there is none."""
    try:
        return default_vectors().describe()
    except VerifyError as exc:
        return f"none ({exc})"


def inside_installation(path) -> bool:
    """True if `path` lies in the interpreter's site-packages or in a built install of the packages:
    places the commands never write to."""
    path = Path(path).resolve()
    roots = {Path(sysconfig.get_paths()[key]) for key in ("purelib", "platlib")}
    for package in (PROJECT, __package__):
        folder = package_folder(package)
        if folder is not None and (folder / DATA).is_dir():
            roots.add(folder)
    for root in roots:
        root = root.resolve()
        if path == root or root in path.parents:
            return True
    return False
