#!/usr/bin/env python3
"""The shared text cases' vector files (verifiers/parity/text/vectors/), taken from the golden set.

The cases are the vectors text/answers.json answers. Their files are the golden set's (vectors/)
cut down to those vectors, header and all, so that every runner can run them: the C library, whose
vectors are compiled in from the golden set, can only judge a case whose vector is the golden one.
When the spec changes one of these vectors, `--check` fails, this script brings the files up to
date, and text/expected.txt must then be brought up to date by hand from TEXT.md's rules: it is
the expected text, not the output of any runner.

    python3 verifiers/parity/text_cases.py            # rewrite text/vectors/ from vectors/
    python3 verifiers/parity/text_cases.py --check    # exit 1, naming each file that differs
"""
from __future__ import annotations

import argparse
import hashlib
import json
import sys
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
GOLDEN = ROOT / "vectors"
TEXT = Path(__file__).resolve().parent / "text"

sys.path.insert(0, str(ROOT / "generator"))
from plcvec.output.atomic import write_atomic  # noqa: E402
from plcvec.output.canonical import dumps_vector_file  # noqa: E402


def case_ids() -> set[str]:
    return set(json.loads((TEXT / "answers.json").read_text(encoding="utf-8"))["answers"])


def case_files() -> dict[str, str]:
    """{file name: text} of text/vectors/: each golden family file with only the cases' vectors."""
    ids = case_ids()
    golden = json.loads((GOLDEN / "manifest.json").read_text(encoding="utf-8"))
    files, entries, found = {}, {}, set()
    for family, entry in sorted(golden["families"].items()):
        data = json.loads((GOLDEN / entry["file"]).read_text(encoding="utf-8"))
        vectors = [v for v in data.pop("vectors") if v["id"] in ids]
        if not vectors:
            continue
        found |= {v["id"] for v in vectors}
        data["count"] = len(vectors)
        text = dumps_vector_file(data, vectors)
        files[entry["file"]] = text
        entries[family] = {
            "count": len(vectors),
            "file": entry["file"],
            "outcomes": dict(sorted(Counter(v["outcome"]["category"] for v in vectors).items())),
            "sha256": hashlib.sha256(text.encode()).hexdigest(),
            "tags": dict(sorted(Counter(t for v in vectors for t in v["tags"]).items())),
        }
    if found != ids:
        missing = ", ".join(sorted(ids - found))
        raise SystemExit(f"text_cases: {TEXT / 'answers.json'} answers vectors the golden set does not have: {missing}")
    manifest = {k: golden[k] for k in ("generated", "suite_version", "generator_version", "schema_version", "spec_sha256")}
    manifest |= {"families": entries, "total": len(found)}
    files["manifest.json"] = json.dumps(manifest, indent=1, sort_keys=True) + "\n"
    return files


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true", help="only say which files differ (exit 1)")
    args = parser.parse_args()
    want = case_files()
    out = TEXT / "vectors"
    have = {p.name for p in out.glob("*.json")}
    differ = sorted(name for name in want.keys() | have
                    if not (out / name).is_file() or (out / name).read_text(encoding="utf-8") != want.get(name))
    if args.check:
        for name in differ:
            print(f"text_cases: {out / name} is not the golden set's; run python3 {Path(__file__).relative_to(ROOT)}"
                  " and bring text/expected.txt up to date by hand")
        return 1 if differ else 0
    for name in sorted(have - want.keys()):
        (out / name).unlink()
    for name, text in want.items():
        write_atomic(out / name, text)
    print(f"text_cases: {len(differ)} files rewritten in {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
