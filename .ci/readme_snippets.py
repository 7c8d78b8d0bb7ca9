#!/usr/bin/env python3
"""The code blocks of the READMEs, taken out so that CI runs them instead of a retyped copy.

Every fenced block of a checked Markdown file carries a marker on the line before its fence (blank
lines between are allowed):

    <!-- snippet: PATH -->          the block is written to <out>/PATH by `extract`, to be built or run
    <!-- snippet-skip: REASON -->   the block is not run; the reason says why (output, a placeholder…)

    python3 .ci/readme_snippets.py check README.md verifiers/*/README.md
    python3 .ci/readme_snippets.py extract verifiers/go/README.md --out /tmp/readme-go
    python3 .ci/readme_snippets.py list verifiers/go/README.md

`check` fails on a block with no marker, two markers, an empty skip reason, a path that leaves the
output folder, or one path given twice. `extract` checks the same, then writes each `snippet:` block
(several blocks may not share a path). Exit 0, or 1 with `file:line: problem` for each problem, or 2
for a usage error.
"""
from __future__ import annotations

import argparse
import re
import sys
from dataclasses import dataclass
from pathlib import Path, PurePosixPath

MARKER = re.compile(r"^\s*<!--\s*(snippet|snippet-skip):\s*(.*?)\s*-->\s*$")
FENCE = re.compile(r"^(\s*)(`{3,}|~{3,})(.*)$")


@dataclass
class Block:
    file: Path
    line: int          # 1-based line of the opening fence
    info: str          # the fence's info string (language)
    text: str
    kind: str | None   # "snippet", "snippet-skip" or None
    arg: str           # the path, or the skip reason


def blocks(path: Path) -> tuple[list[Block], list[str]]:
    """The fenced blocks of one Markdown file, each with its marker; and the problems found."""
    lines = path.read_text(encoding="utf-8").splitlines()
    found, problems = [], []
    marker: tuple[str, str, int] | None = None
    i = 0
    while i < len(lines):
        line = lines[i]
        m = MARKER.match(line)
        if m:
            if marker:
                problems.append(f"{path}:{marker[2]}: a marker with no fenced block after it")
            marker = (m.group(1), m.group(2), i + 1)
            i += 1
            continue
        f = FENCE.match(line)
        if f:
            indent, fence, info = f.groups()
            body, j = [], i + 1
            close = re.compile(r"^\s*" + re.escape(fence[0]) + "{" + str(len(fence)) + r",}\s*$")
            while j < len(lines) and not close.match(lines[j]):
                body.append(lines[j][len(indent):] if lines[j].startswith(indent) else lines[j])
                j += 1
            if j == len(lines):
                problems.append(f"{path}:{i + 1}: a fenced block that is never closed")
            kind, arg = (marker[0], marker[1]) if marker else (None, "")
            found.append(Block(path, i + 1, info.strip(), "\n".join(body) + "\n", kind, arg))
            if not marker:
                problems.append(f"{path}:{i + 1}: a fenced block with no <!-- snippet: PATH --> or "
                                "<!-- snippet-skip: REASON --> marker on the line before it")
            elif not arg:
                problems.append(f"{path}:{i + 1}: the marker gives no "
                                + ("path" if kind == "snippet" else "reason"))
            elif kind == "snippet":
                p = PurePosixPath(arg)
                if p.is_absolute() or ".." in p.parts:
                    problems.append(f"{path}:{i + 1}: snippet path {arg!r} leaves the output folder")
            marker = None
            i = j + 1
            continue
        if marker and line.strip():
            problems.append(f"{path}:{marker[2]}: a marker not followed by a fenced block")
            marker = None
        i += 1
    if marker:
        problems.append(f"{path}:{marker[2]}: a marker with no fenced block after it")
    seen: dict[str, int] = {}
    for b in found:
        if b.kind == "snippet" and b.arg:
            if b.arg in seen:
                problems.append(f"{path}:{b.line}: snippet path {b.arg!r} already used at line {seen[b.arg]}")
            seen.setdefault(b.arg, b.line)
    return found, problems


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    for name in ("check", "list"):
        p = sub.add_parser(name)
        p.add_argument("files", nargs="+", type=Path)
    p = sub.add_parser("extract")
    p.add_argument("file", type=Path)
    p.add_argument("--out", type=Path, required=True)
    args = parser.parse_args(argv)

    files = args.files if args.command != "extract" else [args.file]
    problems, all_blocks = [], []
    for f in files:
        if not f.is_file():
            print(f"readme_snippets: {f}: no such file", file=sys.stderr)
            return 2
        found, bad = blocks(f)
        all_blocks += found
        problems += bad
    if problems:
        print("\n".join(problems), file=sys.stderr)
        return 1
    if args.command == "check":
        run = sum(b.kind == "snippet" for b in all_blocks)
        print(f"{len(all_blocks)} fenced blocks in {len(files)} file(s): {run} run by CI, "
              f"{len(all_blocks) - run} skipped with a reason")
    elif args.command == "list":
        for b in all_blocks:
            print(f"{b.file}:{b.line}: {b.kind}: {b.arg}")
    else:
        snippets = [b for b in all_blocks if b.kind == "snippet"]
        if not snippets:
            print(f"readme_snippets: {args.file}: no <!-- snippet: PATH --> block to extract", file=sys.stderr)
            return 1
        for b in snippets:
            target = args.out / b.arg
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_text(b.text, encoding="utf-8")
            print(f"{target}  <- {b.file}:{b.line}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
