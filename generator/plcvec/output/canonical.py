"""Canonical, diff-friendly JSON: one vector per block, one top-level key per line.

Changing one vector changes a few lines of its file. Keys inside values are sorted; the order of a
vector's own keys is the order the builder gives, which is fixed in code.
"""
import json


# One encoder for every value: json.dumps with these options would build a new one per call.
_ENCODER = json.JSONEncoder(sort_keys=True, ensure_ascii=False, separators=(", ", ": "))


def dumps_value(value):
    return _ENCODER.encode(value)


def dumps_object_lines(obj, indent):
    pad = " " * indent
    items = [f"{pad} {json.dumps(k)}: {dumps_value(v)}" for k, v in obj.items()]
    return pad + "{" + (",\n".join(items))[indent + 1:] + "}"


def dumps_vector_file(header, vectors):
    lines = ["{"]
    for k, v in header.items():
        lines.append(f" {json.dumps(k)}: {dumps_value(v)},")
    lines.append(' "vectors": [')
    lines.append(",\n".join(dumps_object_lines(v, 2) for v in vectors))
    lines.append(" ]")
    lines.append("}")
    return "\n".join(lines) + "\n"
