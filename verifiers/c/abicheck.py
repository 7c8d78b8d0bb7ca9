#!/usr/bin/env python3
"""What abidiff's report says changed, against CHANGES.md's Breaking entries (verifiers/c/abicheck).

Every change the report lists but additions must be named in backticks under Breaking in the entry
of the version being checked (CHANGES.md), or in a news fragment's Breaking section (changes.d/*.md)
not yet folded into it: a struct by its typedef, a function or variable by its name, the soname by
the new one. A breaking change also needs a new minor or major version.

    abicheck.py --report REPORT --repo REPO --version 0.2.0 --base-version 0.1.0
Exit 0, or 1 naming each change not listed.
"""
from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

# "  [D] 'function int plcvec_x(int)'    {plcvec_x}" and "  [C] 'const T plcvec_y[3]' was changed ..."
ENTRY = re.compile(r"^  \[(?P<kind>[DC])\] '(?P<what>[^']*)'(?P<rest>.*)$")
SYMBOL = re.compile(r"\{(?P<name>\w+)\}")
FUNCTION = re.compile(r"function .*?\b(?P<name>\w+)\(")
VARIABLE = re.compile(r"\b(?P<name>\w+)(\[\d*\])?$")
STRUCT = re.compile(r"underlying type 'struct (?P<name>\w+)'.* changed:")
SONAME = re.compile(r"^SONAME changed from '(?P<old>[^']*)' to '(?P<new>[^']*)'")


def changes(report: str) -> dict[str, str]:
    """{name: what happened} for every change the report lists but additions."""
    found: dict[str, str] = {}
    entry_name, entry_structs = None, []

    def close():
        if entry_name:
            for struct in entry_structs or [entry_name]:
                found.setdefault(struct, f"changed (seen through {entry_name})" if entry_structs else "changed")

    for line in report.splitlines():
        if (m := SONAME.match(line)):
            found[m["new"]] = f"the soname, {m['old']} before"
            continue
        if (m := ENTRY.match(line)):
            close()
            what, symbol = m["what"], SYMBOL.search(m["rest"])
            name = symbol["name"] if symbol else (FUNCTION.search(what) or VARIABLE.search(what.split(" was ")[0]))
            name = name if isinstance(name, str) else (name["name"] if name else what)
            if m["kind"] == "D":
                found[name] = "removed"
                entry_name, entry_structs = None, []
            else:
                entry_name, entry_structs = name, []
            continue
        if entry_name and (m := STRUCT.search(line)):
            entry_structs.append(m["name"])
    close()
    return found


def _breaking(text: str) -> str:
    m = re.search(r"^###+ Breaking\s*\n(.*?)(?=^##|\Z)", text, re.S | re.M)
    return m.group(1) if m else ""


def listed(repo: Path, version: str) -> set[str]:
    """The names in backticks under Breaking: CHANGES.md's entry for `version`, and the fragments'."""
    sys.path.insert(0, str(repo / "generator"))
    from plcvec.release.changes import changelog_entry

    text = ""
    changes_md = repo / "CHANGES.md"
    if changes_md.is_file():
        try:
            text += _breaking(changelog_entry(changes_md.read_text(encoding="utf-8"), version))
        except Exception:       # no entry yet for this version: the fragments hold it
            pass
    for fragment in sorted((repo / "changes.d").glob("*.md")):
        text += _breaking(fragment.read_text(encoding="utf-8"))
    return set(re.findall(r"`([^`\n]+)`", text))


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--report", required=True, type=Path)
    p.add_argument("--repo", required=True, type=Path)
    p.add_argument("--version", required=True)
    p.add_argument("--base-version", required=True)
    args = p.parse_args(argv)
    found = changes(args.report.read_text(encoding="utf-8"))
    names = listed(args.repo, args.version)
    missing = {name: what for name, what in sorted(found.items()) if name not in names}
    for name, what in missing.items():
        print(f"c: ABI: `{name}` {what} since {args.base_version}; not named under Breaking for {args.version} "
              "(CHANGES.md or changes.d/)", file=sys.stderr)
    if found and args.version.split(".")[:2] == args.base_version.split(".")[:2]:
        print(f"c: ABI: {len(found)} changes since {args.base_version} need a new minor version, not {args.version}",
              file=sys.stderr)
        return 1
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
