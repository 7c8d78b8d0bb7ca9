"""The hypothesis strategies `plcvec fuzz` draws from: the spec's ranges, and around and past them.

The golden random vectors draw the same kinds of value with the project's own seeded generator
(cases/random_cases.py); these are their hypothesis counterparts, which the shrinker can simplify.
"""
from hypothesis import strategies as st

from plcvec.cases.common import signed_boundaries
from plcvec.cases.random_cases import SHORT_MS, LONG_MS, selector_subsets


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
    """The strategies of one comparison case, by name (the drawer recombines them)."""
    return {
        "form": st.sampled_from(sorted(cases.forms)),
        "symbol": st.sampled_from(cases.conditions),
        "a": around_range(cases.fields), "b": around_range(cases.fields), "clock": in_range(cases.fields),
        "sel": st.one_of(st.sampled_from(selector_subsets(cases)), st.integers(0, 0xFFFF)),
        "rlo_in": st.booleans(),
    }


def hour_meter_step():
    """One scan of an hour meter: the input, and the time since the previous scan (mostly short)."""
    return st.fixed_dictionaries({"input": st.booleans(),
                                  "elapsed_ms": st.one_of(st.integers(0, SHORT_MS), st.integers(0, LONG_MS))})
