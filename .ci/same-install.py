#!/usr/bin/env python3
"""Do two virtual environments hold the same installation of plcvec? (.ci/package-check.sh)

    python3 .ci/same-install.py VENV_A VENV_B

The same distributions at the same versions, and plcvec's own files the same, byte for byte: the
path, sha256 and size of every file its RECORD lists, but for those an installer writes for each
environment (the console scripts in bin/, made from entry_points.txt, which is compared; the
RECORD itself; direct_url.json, the artifact's path). Exit 0 the same, 1 not (each difference
named), 2 a folder that is no such environment.
"""
from __future__ import annotations

import sys
from pathlib import Path

PER_ENVIRONMENT = ("RECORD", "direct_url.json")


class NotAnInstallation(Exception):
    """A folder that is not a virtual environment with plcvec installed: exit 2."""


def site_packages(venv: Path) -> Path:
    found = sorted(venv.glob("lib/python3*/site-packages"))
    if len(found) != 1:
        raise NotAnInstallation(f"{venv}: no single lib/python3*/site-packages")
    return found[0]


def distributions(site: Path) -> list[str]:
    return sorted(p.name for p in site.glob("*.dist-info"))


def record(site: Path) -> list[str]:
    """plcvec's RECORD lines (path,sha256,size) of the files every installation of it has alike."""
    found = sorted(site.glob("plcvec-*.dist-info/RECORD"))
    if len(found) != 1:
        raise NotAnInstallation(f"{site}: no single plcvec-*.dist-info/RECORD")
    lines = found[0].read_text(encoding="utf-8").splitlines()
    return sorted(line for line in lines if line and not line.startswith("../")
                  and line.split(",", 1)[0].rpartition("/")[2] not in PER_ENVIRONMENT)


def differences(name: str, a: list[str], b: list[str]) -> list[str]:
    only_a, only_b = sorted(set(a) - set(b)), sorted(set(b) - set(a))
    return [f"{name}: only in the first: {x}" for x in only_a] + [f"{name}: only in the second: {x}" for x in only_b]


def main(argv: list[str]) -> int:
    if len(argv) != 2:
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    try:
        a, b = (site_packages(Path(v)) for v in argv)
        dist_a, rec_a, dist_b, rec_b = distributions(a), record(a), distributions(b), record(b)
    except NotAnInstallation as exc:
        print(f"same-install: {exc}", file=sys.stderr)
        return 2
    problems = differences("distributions", dist_a, dist_b) + differences("plcvec's files", rec_a, rec_b)
    if problems:
        print("\n".join(problems), file=sys.stderr)
        return 1
    print(f"same-install: the same {len(dist_a)} distributions, plcvec's {len(rec_a)} files byte for byte")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
