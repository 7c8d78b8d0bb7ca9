"""The JSON Lines form of a family file: the header on line 1, then one vector per line.

A reader that has no streaming JSON parser (or wants none) reads it a line at a time; a change to
one vector changes one line. Every object is canonical (sorted keys, no spaces), so the same spec
gives the same bytes. The header is the family file without `vectors`; a reader tells it apart by
its position (the first line) and by its `family` and `schema_version` keys and lack of an `id`.
"""
import json


def dumps_line(value) -> str:
    return json.dumps(value, sort_keys=True, ensure_ascii=False, separators=(",", ":"))


def family_jsonl(family_file: dict) -> str:
    """The JSON Lines text of one parsed family file (a dict with `vectors`)."""
    header = {k: v for k, v in family_file.items() if k != "vectors"}
    lines = [dumps_line(header)]
    lines.extend(dumps_line(v) for v in family_file["vectors"])
    return "\n".join(lines) + "\n"
