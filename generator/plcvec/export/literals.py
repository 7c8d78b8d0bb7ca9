"""String literals for each language: any text from the spec, quoted so the compiler reads it back.

JSON's escapes are not every language's: C has trigraphs and no \\u below U+00A0, Java turns
\\uXXXX into characters before it reads a literal, Rust writes \\u{...}, Go refuses surrogate
halves. So each language gets its own quoting of the same rule: printable ASCII stays as it is,
everything else is escaped in the one form that language reads back exactly.
"""
from __future__ import annotations

import json

_SIMPLE = {"\n": "\\n", "\t": "\\t", "\r": "\\r", '"': '\\"', "\\": "\\\\"}


def _quote(text: str, other) -> str:
    out = []
    for ch in str(text):
        if ch in _SIMPLE:
            out.append(_SIMPLE[ch])
        elif " " <= ch <= "~":
            out.append(ch)
        else:
            out.append(other(ch))
    return '"' + "".join(out) + '"'


def c_str(text) -> str:
    # UTF-8 bytes as three-digit octal (a \x escape would swallow a following hex digit); "?" is
    # escaped so no "??=" can read as a trigraph under -std=c11.
    body = _quote(text, lambda ch: "".join(f"\\{b:03o}" for b in ch.encode("utf-8")))
    return body.replace("?", "\\?")


def go_str(text) -> str:
    return _quote(text, lambda ch: f"\\U{ord(ch):08x}")


def rust_str(text) -> str:
    return _quote(text, lambda ch: f"\\u{{{ord(ch):x}}}")


def java_str(text) -> str:
    def escape(ch):
        code = ord(ch)
        if code < 0x80:                      # a control character: octal, never \u (see above)
            return f"\\{code:03o}"
        if code > 0xFFFF:                    # a UTF-16 surrogate pair, as Java strings hold it
            code -= 0x10000
            return f"\\u{0xD800 + (code >> 10):04x}\\u{0xDC00 + (code & 0x3FF):04x}"
        return f"\\u{code:04x}"
    return _quote(text, escape)


def ts_str(text) -> str:
    # JSON with ASCII escapes is a valid JavaScript literal (U+2028/2029 come out escaped too).
    return json.dumps(str(text), ensure_ascii=True)


FILTERS = {"c_str": c_str, "go_str": go_str, "rust_str": rust_str, "java_str": java_str, "ts_str": ts_str}
