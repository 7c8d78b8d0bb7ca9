"""Identifiers for names from the spec, in each language's own style.

A spec name may hold comparison symbols (`LDTM<=`, `LD <>DT`) and dashes (`FX5-SM709-SCOPE`,
`manual-example`). It is split into words once; each language's filter joins them its way
(`LDTM_LE`, `LdtmLe`, `ldtm_le`). A symbol becomes the word the FX5 manual's own ST names use for
it (`LDTM_LE` for LDTM<=), so one convention serves every family.
"""
from __future__ import annotations

import functools
import re

# Longest first: "<=" must not read as "<" then "=".
_SYMBOL_WORDS = [("<>", "NE"), ("<=", "LE"), (">=", "GE"), ("<", "LT"), (">", "GT"), ("=", "EQ")]
_TOKEN = re.compile("|".join(re.escape(s) for s, _ in _SYMBOL_WORDS) + r"|[A-Za-z0-9]+")


def identifier_words(text: str) -> list[str]:
    """`LD <=DT` -> [LD, LE, DT]; `FX5-SM709-SCOPE` -> [FX5, SM709, SCOPE]; `s1.hour=24` -> [s1, hour, EQ, 24]."""
    symbols = dict(_SYMBOL_WORDS)
    words = [symbols.get(tok, tok) for tok in _TOKEN.findall(text)]
    if not words:
        raise ValueError(f"{text!r} has no letters or digits to make an identifier of")
    return words


def upper_snake(words) -> str:
    """FX5_SM709_SCOPE: C enumerators, Rust/Java constants, Go exported constants (after a prefix)."""
    return _safe("_".join(w.upper() for w in _words(words)))


def lower_snake(words) -> str:
    return _safe("_".join(w.lower() for w in _words(words)))


def pascal(words) -> str:
    """Fx5Sm709Scope: Rust enum variants, Go and TypeScript type names."""
    return _safe("".join(w[:1].upper() + w[1:].lower() for w in _words(words)))


def camel(words) -> str:
    text = pascal(words)
    return text[:1].lower() + text[1:]


def _words(value):
    return value.words if hasattr(value, "words") else _text_words(str(value))


@functools.lru_cache(maxsize=None)
def _text_words(text: str) -> tuple[str, ...]:
    # The C tables name the same devices and clauses tens of thousands of times per export.
    return tuple(identifier_words(text))


def _safe(ident: str) -> str:
    # An identifier cannot start with a digit in any of the five languages.
    return f"_{ident}" if ident[:1].isdigit() else ident


def digest(value, length: int = 8) -> str:
    """A short name that depends only on the content (`digest` filter): a table shared by many
    vectors (a list of clauses, a set of device sizes) named this way keeps its name when vectors
    are added or removed, so an export changes only the lines of what changed."""
    import hashlib

    text = value if isinstance(value, str) else repr(value)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()[:length]
