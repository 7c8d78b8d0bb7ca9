"""Random cases drawn from the spec's ranges with the spec's seed, the same for ever.

Each family's `generation` section gives a seed and a number of draws; the draws come from
SplitMix64 (prng.py) alone, so the golden `random` vectors depend on the spec and nothing else: no
library version, no Python version. A draw repeated is kept once. The vector id ends in a hash of
what was drawn (`key_of`), so it names what the vector tests, never its position.

What is drawn, per family kind:
- comparison: an instruction form and condition; (s1) and (s2) with each field in its range half the
  time and otherwise one of its boundary values, which include the values just past the range (and,
  for BCD, values no digits can hold: those become raw field bits, see `compare_case`); the clock;
  a selector that is one of the field-subset classes half the time and any 16-bit word otherwise;
  the preceding logic state;
- addition: two times of day in range;
- hour meter: a preset and a measured value in range, and one to six scans, each with the input
  and the elapsed time (up to 2.5 s half the time, up to 10,000 s otherwise).

`plcvec fuzz` draws the same kinds of case, widened, with hypothesis (fuzz/strategies.py).
"""
import hashlib
import json

from plcvec.cases.common import signed_boundaries
from plcvec.cases.prng import SplitMix64

MAX_SCANS = 6
SHORT_MS, LONG_MS = 2500, 10 ** 7


# json.dumps(value, sort_keys=True), with its encoder made once: json.dumps makes a new one for each
# call given any option, and every draw and every random vector's id is encoded.
_encode = json.JSONEncoder(sort_keys=True).encode


def key_of(value):
    return hashlib.sha256(_encode(value).encode()).hexdigest()[:12]


def _collect(draw_one, seed_value, count):
    """`count` draws of `draw_one(rng)` from one seeded generator, each distinct draw once, in order."""
    rng = SplitMix64(seed_value)
    drawn, seen = [], set()
    for _ in range(count):
        value = draw_one(rng)
        key = _encode(value)
        if key not in seen:
            seen.add(key)
            drawn.append(value)
    return drawn


def in_range(rng, fields):
    """Every field within the range the spec gives it."""
    return {f["name"]: rng.integer(f["min"], f["max"]) for f in fields}


def around_range(rng, fields):
    """Each field in range half the time, else one of its boundary values (and what lies just past them)."""
    return {f["name"]: rng.choice(signed_boundaries(f)) if rng.boolean() else rng.integer(f["min"], f["max"])
            for f in fields}


def selector_subsets(cases):
    """Every selector value that selects a subset of the fields (with or without the clock bit)."""
    return sorted({cases.selector([n for i, n in enumerate(cases.names) if m >> i & 1], clock)
                   for m in range(1 << len(cases.names))
                   for clock in ([False, True] if cases.clock_bit else [False])})


def compare_case(cases, d, raw=None):
    """A drawn comparison (form, symbol, a, b, clock, sel, rlo_in) as the operand words of a case.

    `raw` may map "a" and "b" to field bits placed over the drawn values as they are (bits that no value
    encodes, such as a nibble above 9 in a BCD field)."""
    fields = cases.fields
    raw = raw or {}
    clock_mode = bool(cases.clock_bit) and bool(d["sel"] >> cases.clock_bit["bit"] & 1)
    return {
        "key": key_of(d), "form": d["form"], "symbol": d["symbol"],
        "s1": cases.ops.words(d["a"], raw={**_raw_overflow(fields, d["a"]), **raw.get("a", {})}),
        "s2": cases.ops.words(d["b"], raw={**_raw_overflow(fields, d["b"]), **raw.get("b", {})}),
        "sel": d["sel"], "clock": d["clock"] if clock_mode else None,
        "rlo_in": None if cases.forms[d["form"]]["logic"] == "load" else d["rlo_in"],
    }


def _raw_overflow(fields, values):
    """BCD values past the digits' reach cannot be encoded; keep them as raw bits instead."""
    return {f["name"]: values[f["name"]] for f in fields
            if f["encoding"] == "bcd" and not 0 <= values[f["name"]] < 10 ** (f["width"] // 4)}


def draw_compare(cases, seed_value, count):
    forms, subsets, fields = sorted(cases.forms), selector_subsets(cases), cases.fields

    def one(rng):
        return {"form": rng.choice(forms), "symbol": rng.choice(cases.conditions),
                "a": around_range(rng, fields), "b": around_range(rng, fields), "clock": in_range(rng, fields),
                "sel": rng.choice(subsets) if rng.boolean() else rng.integer(0, 0xFFFF),
                "rlo_in": rng.boolean()}

    for d in _collect(one, seed_value, count):
        yield compare_case(cases, d)


def draw_addition(fields, seed_value, count):
    for d in _collect(lambda rng: {"s1": in_range(rng, fields), "s2": in_range(rng, fields)}, seed_value, count):
        yield dict(d, key=key_of(d))


def _scan(rng):
    """One scan of an hour meter: the input, and the time since the previous scan (short half the time)."""
    return {"input": rng.boolean(), "elapsed_ms": rng.integer(0, SHORT_MS if rng.boolean() else LONG_MS)}


def draw_hour_meter(fields, seed_value, count):
    def one(rng):
        return {"preset": in_range(rng, fields), "measured": in_range(rng, fields),
                "steps": [_scan(rng) for _ in range(rng.integer(1, MAX_SCANS))]}

    for d in _collect(one, seed_value, count):
        yield dict(d, key=key_of(d))
