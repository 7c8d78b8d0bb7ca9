"""Random cases drawn with hypothesis from the spec's ranges, reproducibly from the spec's seed.

The @given test runner adapts how it explores from run to run, so the same seed did not always give
the same examples. Each example is drawn instead from a ConjectureData fed by one seeded PRNG: the
draws are then a pure function of (seed, count, strategy, hypothesis version), and the version is
pinned in pyproject.toml.
"""
import hashlib
import json
import random

from hypothesis import strategies as st
from hypothesis.control import BuildContext
from hypothesis.internal.conjecture.data import ConjectureData
from hypothesis.internal.conjecture.providers import HypothesisProvider

from plcvec.cases.common import signed_boundaries


class SeededProvider(HypothesisProvider):
    """Hypothesis' own provider, minus its habit of mixing in constants found in whatever modules the
    process has imported (which made the draws depend on, e.g., whether pytest had loaded the tests)."""

    def _maybe_draw_constant(self, choice_type, constraints, *, p=0.05):
        return None


def draw_seeded(strategy, rng):
    """One value of `strategy` drawn from `rng` alone, and the choices hypothesis made for it (which
    replay it, e.g. for shrinking)."""
    data = ConjectureData(random=rng, provider=SeededProvider)
    with BuildContext(data, is_final=True, wrapped_test=None):
        value = data.draw(strategy)
    return value, data.choices


def _collect(strategy, seed_value, count):
    rng = random.Random(seed_value)
    drawn, seen = [], set()
    for _ in range(count):
        value, _ = draw_seeded(strategy, rng)
        key = json.dumps(value, sort_keys=True)
        if key not in seen:
            seen.add(key)
            drawn.append(value)
    return drawn


def key_of(value):
    return hashlib.sha256(json.dumps(value, sort_keys=True).encode()).hexdigest()[:12]


def field_values(field):
    """Mostly in-range values, with the boundary set mixed in."""
    return st.one_of(st.integers(field["min"], field["max"]), st.sampled_from(signed_boundaries(field)))


def in_range(fields):
    """Every field within the range the spec gives it."""
    return st.fixed_dictionaries({f["name"]: st.integers(f["min"], f["max"]) for f in fields})


def around_range(fields):
    """Every field mostly in range, with its boundary set (and what lies just past it) mixed in."""
    return st.fixed_dictionaries({f["name"]: field_values(f) for f in fields})


def compare_parts(cases):
    """The strategies of one comparison case, by name (`plcvec fuzz` recombines them)."""
    subsets = sorted({cases.selector([n for i, n in enumerate(cases.names) if m >> i & 1], clock)
                      for m in range(1 << len(cases.names))
                      for clock in ([False, True] if cases.clock_bit else [False])})
    return {
        "form": st.sampled_from(sorted(cases.forms)),
        "symbol": st.sampled_from(cases.conditions),
        "a": around_range(cases.fields), "b": around_range(cases.fields), "clock": in_range(cases.fields),
        "sel": st.one_of(st.sampled_from(subsets), st.integers(0, 0xFFFF)),
        "rlo_in": st.booleans(),
    }


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


def draw_compare(cases, seed_value, count):
    for d in _collect(st.fixed_dictionaries(compare_parts(cases)), seed_value, count):
        yield compare_case(cases, d)


def _raw_overflow(fields, values):
    """BCD values past the digits' reach cannot be encoded; keep them as raw bits instead."""
    return {f["name"]: values[f["name"]] for f in fields
            if f["encoding"] == "bcd" and not 0 <= values[f["name"]] < 10 ** (f["width"] // 4)}


def draw_addition(fields, seed_value, count):
    hms = in_range(fields)
    for d in _collect(st.fixed_dictionaries({"s1": hms, "s2": hms}), seed_value, count):
        yield dict(d, key=key_of(d))


def hour_meter_step():
    """One scan of an hour meter: the input, and the time since the previous scan (mostly short)."""
    return st.fixed_dictionaries({"input": st.booleans(), "elapsed_ms": st.one_of(st.integers(0, 2500), st.integers(0, 10 ** 7))})


def draw_hour_meter(fields, seed_value, count):
    value = in_range(fields)
    strategy = st.fixed_dictionaries({"preset": value, "measured": value, "steps": st.lists(hour_meter_step(), min_size=1, max_size=6)})
    for d in _collect(strategy, seed_value, count):
        yield dict(d, key=key_of(d))
