"""The JSON Lines form of a family file: the header on line 1, then one vector per line.

A reader that has no streaming JSON parser (or wants none) reads it a line at a time; a change to
one vector changes one line. Every object is canonical (sorted keys, no spaces), so the same spec
gives the same bytes. The header is the family file without `vectors`; a reader tells it apart by
its position (the first line) and by its `family` and `schema_version` keys and lack of an `id`.
"""
import hashlib
import json


def dumps_line(value) -> str:
    return json.dumps(value, sort_keys=True, ensure_ascii=False, separators=(",", ":"))


def family_jsonl(family_file: dict) -> str:
    """The JSON Lines text of one parsed family file (a dict with `vectors`)."""
    header = {k: v for k, v in family_file.items() if k != "vectors"}
    lines = [dumps_line(header)]
    lines.extend(dumps_line(v) for v in family_file["vectors"])
    return "\n".join(lines) + "\n"


def jsonl_index(note: str, suite_version: str, schema_version: str, spec_sha256: str,
                families: dict[str, str], merged: dict[str, dict[str, str]]) -> str:
    """The index.json beside a folder of JSON-lines files ({family: its JSON-lines text}): which
    families, how many vectors, the sha256 of each file, and which suite they are. Every runner
    that reads the JSON-lines form checks a file against it before trusting it. `merged` is the
    manifest's map of ids merged into another vector ({family: {old id: the id it went to}}), so that
    a runner reading this form too names the vector an old known-failure id became."""
    counts = {name: text.count("\n") - 1 for name, text in families.items()}
    index = {
        "generated": note,
        "suite_version": suite_version,
        "schema_version": schema_version,
        "spec_sha256": spec_sha256,
        "total": sum(counts.values()),
        "families": {name: {"file": f"{name}.jsonl", "count": counts[name],
                            "sha256": hashlib.sha256(text.encode()).hexdigest()}
                     for name, text in sorted(families.items())},
        "merged": {name: dict(sorted(merged.get(name, {}).items())) for name in sorted(families)},
    }
    return json.dumps(index, indent=1, sort_keys=True) + "\n"
