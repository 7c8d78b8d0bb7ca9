"""Canonical, diff-friendly JSON: one vector per block, one top-level key per line.

Changing one vector changes a few lines of its file. Keys inside values are sorted; the order of a
vector's own keys is the order the builder gives, which is fixed in code.
"""
import json
from json.encoder import encode_basestring, encode_basestring_ascii

try:
    from json.encoder import c_make_encoder
except ImportError:  # a Python without the _json accelerator
    c_make_encoder = None

# One encoder for every value: json.dumps with these options would build a new one per call.
_ENCODER = json.JSONEncoder(sort_keys=True, ensure_ascii=False, separators=(", ", ": "))
# JSONEncoder.encode builds a fresh C encoder for each value it is given; the golden set encodes
# tens of thousands of values, so the C encoder is built once, with the arguments encode() gives it
# (the same since Python 3.10). `_MARKERS` keeps the circular-reference check; it is empty between calls.
_MARKERS = {}
_C_ENCODE = None if c_make_encoder is None else c_make_encoder(
    _MARKERS, _ENCODER.default, encode_basestring, None, _ENCODER.key_separator, _ENCODER.item_separator,
    _ENCODER.sort_keys, _ENCODER.skipkeys, _ENCODER.allow_nan)


def dumps_value(value):
    """The canonical text of a value: sorted keys, ", " and ": ", non-ASCII characters as they are."""
    if isinstance(value, str):
        return encode_basestring(value)   # what _ENCODER.encode does with a string
    if _C_ENCODE is None:
        return _ENCODER.encode(value)
    try:
        return "".join(_C_ENCODE(value, 0))
    except BaseException:
        _MARKERS.clear()   # an encoding that failed half-way leaves its marks behind
        raise


def dumps_object(obj, known=None):
    """dumps_value(obj) of a dict with string keys, taking the text of a value from `known` (key ->
    text already encoded) where it is there, so a value other output also needs is encoded once."""
    known = known or {}
    return "{" + ", ".join(f"{encode_basestring(k)}: {known[k] if k in known else dumps_value(obj[k])}"
                           for k in sorted(obj)) + "}"


# The text json.dumps gives a top-level key (ASCII-escaped).
_key = encode_basestring_ascii


# The C encoder itself (a tuple of pieces), or the Python encoder's text as one piece.
_pieces = _C_ENCODE or (lambda value, _level: (_ENCODER.encode(value),))
_STATE_PARTS = ("operands", "devices")


def vector_texts(vector):
    """The canonical text of each of a vector's own values, by key, and of the operands and devices of
    its initial and final states, by (key, part): the CSV export (plcvec.output.golden.csv_export)
    writes those again, from these texts, so each is encoded once.

    dumps_value() written out in the loop: a golden set encodes some fifty thousand values here, and
    a call per value was a sixth of the encoding."""
    texts = {}
    join, pieces = "".join, _pieces
    try:
        for k, v in vector.items():
            if type(v) is str:
                texts[k] = encode_basestring(v)
            elif (k == "initial" or k == "final") and isinstance(v, dict):
                parts = {}
                for p, x in v.items():
                    if p in _STATE_PARTS:
                        parts[p] = texts[k, p] = join(pieces(x, 0))
                texts[k] = dumps_object(v, parts)
            else:
                texts[k] = join(pieces(v, 0))
    except BaseException:
        _MARKERS.clear()   # as in dumps_value
        raise
    return texts


def dumps_vector_file(header, vectors, texts=None):
    """The text of a vector file; `texts`, when given, holds vector_texts() of each vector.

    The pieces go into one list joined once: a golden file is megabytes, and joining line by line
    would copy each vector's text several times over."""
    out = ["{\n"]
    for k, v in header.items():
        out += [" ", _key(k), ": ", dumps_value(v), ",\n"]
    out.append(' "vectors": [\n')
    for n, (vector, vtexts) in enumerate(zip(vectors, texts or [None] * len(vectors))):
        vtexts = vtexts or {k: dumps_value(v) for k, v in vector.items()}
        out.append(",\n  {" if n else "  {")
        for i, k in enumerate(vector):
            out += [",\n   " if i else "", _key(k), ": ", vtexts[k]]
        out.append("}")
    out.append("\n ]\n}\n")
    return "".join(out)
