#!/usr/bin/env python3
"""The public API against the previous release, by API Extractor: fail on a change CHANGES.md does not announce.

    python3 api/check.py [--previous 9ebc6da] [--prove OLD=NEW]

Builds the previous release's declarations in a git worktree in a temporary folder (removed after;
the node_modules of this folder serve it, so nothing is installed twice), has API Extractor write the
report of each of its entry points (package.json's "exports": `plcvec`, `plcvec/reference`, ...)
and of this folder's build (`npm run build` first), and compares them entry by entry, declaration by
declaration; an entry point the new build no longer exports has lost every declaration. A declaration line of the previous report that the new one lacks (a
symbol removed, renamed or given another signature) is a change that may break a user: it must be
named in CHANGES.md's Breaking (or Deprecated, for a rename that keeps the old name working)
section of the version being checked, the symbol's name as a word (`Report.results` for a member).
The version being checked is package.json's version when CHANGES.md has a section for it, else the
first section (the release being written); the news fragments in changes.d/, not yet folded into
CHANGES.md, count as that section's. The constants generated from the spec (SUITE, TAGS,
INSTRUCTIONS, ...) are left out: their values are the spec's data, which CHANGES.md lists by name.

`--prove OLD=NEW` also renames a symbol in a scratch copy of the built declarations and requires
the check to catch it (a symbol CHANGES.md does not name): the check is shown to fail on a
deliberate rename in the same run, the tool started once for the three reports.

Exit status: 0 every change is announced, 1 some is not (each listed), 2 the check could not run.
"""
from __future__ import annotations

import argparse
import json
import re
import shutil
import subprocess
import sys
import tempfile
from collections import Counter
from pathlib import Path

HERE = Path(__file__).resolve().parent
PACKAGE = HERE.parent
REPO = PACKAGE.parents[1]
REPORTS = Path("dist/api")
MAIN_REPORT = "plcvec.api.md"   # the main entry point's (api/report.mjs names each entry's report)
DECLARATION = re.compile(r"^export (?:declare )?(?:abstract )?(?:class|interface|type|function|const|let|enum|namespace) (\w+)")
MEMBER = re.compile(r"^\s+(?:(?:readonly|static|protected|get|set|abstract|declare)\s+)*\[?([\w.]+)")
# The constants generated from the spec (src/generated/names.ts: SUITE, TAGS, INSTRUCTIONS, ...) hold
# its data, which moves with every spec; CHANGES.md names those changes by vector, tag and instruction.
IGNORED = set(re.findall(r"^export const (\w+)", (PACKAGE / "src/generated/names.ts").read_text(encoding="utf-8"), re.M))


def run(cmd: list[str], cwd: Path) -> None:
    done = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    if done.returncode != 0:
        print(f"api/check.py: {' '.join(cmd)} (in {cwd}) failed:\n{done.stdout}{done.stderr}", file=sys.stderr)
        sys.exit(2)


def declarations(report: str) -> Counter:
    """(qualified name, line) for every declaration line of an API Extractor report."""
    out: Counter = Counter()
    current = None
    for line in report.splitlines():
        if not line.strip() or line.lstrip().startswith(("//", "```", "import ", ">", "#")):
            continue
        top = DECLARATION.match(line)
        if top:
            current = top.group(1)
            out[(current, line)] += 1
        elif current and line.startswith((" ", "\t")):
            member = MEMBER.match(line)
            out[(f"{current}.{member.group(1)}" if member else current, line.strip())] += 1
        elif line.strip() in ("}", "};") or current is None:
            continue
        else:
            out[(current, line.strip())] += 1
    return out


def reports(folder: Path) -> dict[str, Counter]:
    """{report file name: its declarations} of every entry point api/report.mjs reported in `folder`."""
    return {path.name: declarations(path.read_text(encoding="utf-8")) for path in sorted((folder / REPORTS).glob("*.api.md"))}


def announced(version: str) -> str:
    """The Breaking and Deprecated sections of `version` and of [Unreleased] in CHANGES.md, and of the
    news fragments in changes.d/ that are not folded into it yet."""
    chosen = ""
    changes = REPO / "CHANGES.md"
    if changes.is_file():
        sections = re.split(r"^## ", changes.read_text(encoding="utf-8"), flags=re.M)[1:]
        chosen = next((s for s in sections if re.match(rf"\[?v?{re.escape(version)}\b", s)), sections[0] if sections else "")
        # What is not released yet is announced for the next release, which package.json's version
        # names only once it is made.
        chosen += "\n" + "\n".join(s for s in sections if re.match(r"\[?unreleased\b", s, re.I) and s is not chosen)
    chosen += "\n" + "\n".join(p.read_text(encoding="utf-8") for p in sorted((REPO / "changes.d").glob("*.md")))
    kept = []
    for part in re.split(r"^### ", chosen, flags=re.M)[1:]:
        if part.split("\n", 1)[0].strip().lower() in ("breaking", "deprecated"):
            kept.append(part)
    return "\n".join(kept)


def previous_build(commit: str, scratch: Path) -> Path:
    """The previous release's declarations, built in a worktree of `commit` under `scratch`."""
    old = scratch / "previous"
    run(["git", "worktree", "add", "--detach", str(old), commit], REPO)
    package = old / PACKAGE.relative_to(REPO)
    (package / "node_modules").symlink_to(PACKAGE / "node_modules")
    # --noCheck: the previous release's declarations are emitted as a checked build emits them (the
    # same files, byte for byte), without type-checking a release's sources that no longer change.
    run(["node", "node_modules/typescript/bin/tsc", "-p", "tsconfig.json", "--declaration", "--emitDeclarationOnly", "--noCheck"], package)
    return package


def renamed_build(rename: str, scratch: Path) -> Path:
    """A scratch copy of this folder's declarations with one symbol renamed."""
    old, new = rename.split("=", 1)
    folder = scratch / "renamed"
    folder.mkdir()
    # The main entry point alone: the deliberate rename is made there.
    manifest = json.loads((PACKAGE / "package.json").read_text(encoding="utf-8"))
    manifest["exports"] = {".": manifest["exports"]["."]}
    (folder / "package.json").write_text(json.dumps(manifest), encoding="utf-8")
    # The package's compiler options, over the declarations alone.
    (folder / "tsconfig.json").write_text(json.dumps({"extends": str(PACKAGE / "tsconfig.json"), "files": ["dist/src/index.d.ts"]}))
    (folder / "node_modules").symlink_to(PACKAGE / "node_modules")
    shutil.copytree(PACKAGE / "dist" / "src", folder / "dist" / "src")
    for d in (folder / "dist" / "src").rglob("*.d.ts"):
        d.write_text(re.sub(rf"\b{re.escape(old)}\b", new, d.read_text(encoding="utf-8")), encoding="utf-8")
    return folder


EXTENDS = re.compile(r"^export (?:declare )?(?:abstract )?(?:class|interface) (\w+)(?:<.*?>)? extends ([\w., <>]+?)(?: implements .*)? \{")


def bases(declared: Counter) -> dict[str, set[str]]:
    """{class or interface: the names it extends}, from the declaration lines of API Extractor reports."""
    out: dict[str, set[str]] = {}
    for name, line in declared:
        found = EXTENDS.match(line)
        if found and "." not in name:
            out[name] = {re.sub(r"<.*", "", b).strip() for b in found.group(2).split(",")}
    return out


def inherited(name: str, line: str, after: Counter, parents: dict[str, set[str]]) -> bool:
    """Whether member `name` (Type.member), gone from its type, is declared alike in a type it extends:
    a member moved up into a base (an options interface another one extends) is still there."""
    top, _, member = name.partition(".")
    seen, todo = set(), list(parents.get(top, ()))
    while todo:
        base = todo.pop()
        if base in seen:
            continue
        seen.add(base)
        if after[(f"{base}.{member}", line)]:
            return True
        todo += parents.get(base, ())
    return False


def unannounced(before: Counter, after: Counter, text: str, pool: Counter | None = None) -> list[str]:
    """The symbols whose declaration lines of `before` are not all in `after`, that `text` does not name.
    `pool` (default `after`): every entry point's declarations, where a moved member's base is found."""
    pool = after if pool is None else pool
    parents = bases(pool)
    changed = {name for name, line in before - after if name.split(".")[0] not in IGNORED
               and not ("." in name and inherited(name, line, pool, parents))}
    # A declaration that changed as a whole is named once, not with each of its members.
    changed = {n for n in changed if "." not in n or n.split(".")[0] not in changed}
    return sorted(n for n in changed if not re.search(rf"(?<![\w.]){re.escape(n)}(?![\w])", text))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--previous", default="9ebc6da", help="the previous release's commit (default: 0.1.0's)")
    parser.add_argument("--prove", metavar="OLD=NEW", help="also rename OLD in a scratch copy of the build and require the check to fail on it")
    args = parser.parse_args()
    version = json.loads((PACKAGE / "package.json").read_text())["version"]
    text = announced(version)
    with tempfile.TemporaryDirectory(prefix="plcvec-api-") as tmp:
        scratch = Path(tmp)
        try:
            folders = [previous_build(args.previous, scratch), PACKAGE]
            if args.prove:
                folders.append(renamed_build(args.prove, scratch))
            run(["node", str(HERE / "report.mjs"), *map(str, folders)], PACKAGE)   # one start of the tool for all
            before, *afters = [reports(f) for f in folders]
        finally:
            subprocess.run(["git", "worktree", "remove", "--force", str(scratch / "previous")], cwd=REPO, capture_output=True)
    if MAIN_REPORT not in before:
        print(f"api/check.py: no report of the main entry point of {args.previous}", file=sys.stderr)
        return 2
    pool = sum(afters[0].values(), Counter())
    missing = sorted({name for entry in before
                      for name in unannounced(before[entry], afters[0].get(entry, Counter()), text, pool)})
    for name in missing:
        print(f"api/check.py: {name} changed or went since {args.previous} (API Extractor's report), "
              f"and CHANGES.md does not name it under Breaking or Deprecated", file=sys.stderr)
    if args.prove and args.prove.split("=")[0] not in unannounced(before[MAIN_REPORT], afters[1][MAIN_REPORT], text):
        print(f"api/check.py: renaming {args.prove} was not caught: the check cannot fail", file=sys.stderr)
        return 1
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
