#!/usr/bin/env python3
"""The house rules of the C runner (VOCABULARY.md), checked: no circle between the modules of the
library (libplcvec.a) or of the reference (libplcvec_reference.a, its mutants included), and no
hand-written function over 80 lines unless the comment before it says why ("over 80 lines: ...").

A module is an object file (judge.c.o); it depends on another when it uses a symbol the other
defines, as binutils' nm lists them: what the linker sees, so a circle through a shared header (a
file calling back into the one that calls it) is found too. A circle is a chain of such
dependencies that comes back to where it started, however long.

    python3 verifiers/c/tests/house.py BUILD   # BUILD holds libplcvec.a; exit 0, or 1 naming each problem
"""
from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent.parent
LIBRARIES = {"library": "libplcvec.a", "reference": "reference/libplcvec_reference.a"}
CODE = ("src", "reference", "mutants", "adapter", "faults", "tests", "examples", "benchmark", "include")
LONGEST = 80
# The first line of a function's definition: a declarator ending in `)` and, on the same line or
# the next, its opening brace.
START = re.compile(r"^\s*(?:(?:static|inline|const|extern|unsigned|signed|struct|enum)\s+)*[A-Za-z_][\w:<>*& ]*\b"
                   r"[A-Za-z_]\w*\s*\([^;]*\)\s*(?:const\s*)?\{?\s*$")


def graph(archive: Path) -> dict[str, set[str]]:
    """{object: the objects whose symbols it uses} of a static library, from `nm`."""
    out = subprocess.run(["nm", str(archive)], capture_output=True, text=True, check=True).stdout
    defined: dict[str, str] = {}
    used: dict[str, set[str]] = {}
    member = None
    for line in out.splitlines():
        if line.endswith(":") and not line.startswith(" "):
            member = Path(line[:-1]).name.removesuffix(".o").removesuffix(".c")
            used.setdefault(member, set())
            continue
        parts = line.split()
        if member and len(parts) == 2 and parts[0] == "U":
            used[member].add(parts[1])
        elif member and len(parts) == 3 and parts[1] in "TDRBC":
            defined[parts[2]] = member
    return {m: {defined[s] for s in syms if s in defined and defined[s] != m} for m, syms in used.items()}


def circles(edges: dict[str, set[str]]) -> list[list[str]]:
    """Every elementary circle found by a depth-first walk (each reported once, by its smallest module)."""
    found, seen = [], set()

    def walk(path: list[str]):
        for nxt in sorted(edges[path[-1]]):
            if nxt == path[0]:
                key = tuple(sorted(path))
                if key not in seen:
                    seen.add(key)
                    found.append(path + [nxt])
            elif nxt not in path and nxt > path[0]:
                walk(path + [nxt])

    for start in sorted(edges):
        walk([start])
    return found


def long_functions(path: Path) -> list[tuple[int, int]]:
    lines = path.read_text(encoding="utf-8").split("\n")
    out, i = [], 0
    while i < len(lines):
        line = lines[i]
        opens = line.rstrip().endswith("{") or (i + 1 < len(lines) and lines[i + 1].strip() == "{")
        if START.match(line) and opens and not line.lstrip().startswith(("if", "for", "while", "switch", "else")):
            depth, j = 0, i
            while j < len(lines):
                depth += lines[j].count("{") - lines[j].count("}")
                if depth == 0 and "{" in "".join(lines[i:j + 1]):
                    break
                j += 1
            length = j - i + 1
            before = lines[i - 1] if i else ""
            if length > LONGEST and "over 80 lines:" not in before:
                out.append((i + 1, length))
            i = j + 1
            continue
        i += 1
    return out


def main() -> int:
    if len(sys.argv) != 2 or not (Path(sys.argv[1]) / LIBRARIES["library"]).is_file():
        print("usage: house.py BUILD (the build folder that holds libplcvec.a)", file=sys.stderr)
        return 2
    problems = []
    for name, archive in LIBRARIES.items():
        for circle in circles(graph(Path(sys.argv[1]) / archive)):
            problems.append(f"{name}: a circle: {' -> '.join(circle)}")
    for folder in CODE:
        for path in sorted((HERE / folder).rglob("*")):
            if path.suffix in (".c", ".h", ".cpp", ".hpp") and "generated" not in path.parts:
                for line, length in long_functions(path):
                    problems.append(f"{path.relative_to(HERE)}:{line}: a function of {length} lines (at most {LONGEST})")
    for p in problems:
        print(f"c: {p}", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
