"""The vector model (VOCABULARY.md: `vector`): what a vector holds, what the runner reads of it, and the
part of it an implementation receives.

A vector stays the JSON object it was read as (a dict): a run over the golden set reads thousands of
them, and a copy into classes would cost more than judging them. The TypedDicts below name the keys
this package reads, for the reader and for a type checker; vectors/schema/ is the whole shape.
"""
from __future__ import annotations

from typing import TypedDict


class Step(TypedDict, total=False):
    """One execution (scan): its inputs (`clock`, `rlo_in`, `en`, `input`, `elapsed_ms`, `set`, ...)
    and what it must leave (`expect`: the devices it changes, the result of a contact instruction)."""

    set: dict
    expect: dict


class Vector(TypedDict, total=False):
    id: str
    family: str
    instruction: str
    tags: list
    assumes: dict
    initial: dict           # {"devices", "operands", "scratch"?}
    steps: list             # [Step, ...]
    final: dict             # {"devices"}: the state after the last step under the default alternatives
    outcome: dict           # the category, and the interpretations it depends on
    alternatives: list      # the expectation under each other choice of alternatives


class VectorRequest(TypedDict):
    """A vector without its expectations: what an implementation is given to run
    (run-request.schema.json#/$defs/request)."""

    id: str
    family: str
    instruction: str
    assumes: dict
    initial: dict
    steps: list             # each step's inputs, without `expect`


# Step keys that are inputs: everything a step holds except this one.
_EXPECT = "expect"


def request_of(vector: Vector) -> VectorRequest:
    """The part of a vector an adapter receives: everything needed to run it, no expectation."""
    return {
        "id": vector["id"],
        "family": vector["family"],
        "instruction": vector["instruction"],
        "assumes": vector.get("assumes", {}),
        "initial": vector["initial"],
        "steps": [{k: v for k, v in step.items() if k != _EXPECT} for step in vector["steps"]],
    }


def touched_interpretations(vector: Vector) -> set[str]:
    """The interpretations a vector's outcome depends on."""
    return set(vector["outcome"].get("interpretations", ()))


# What the runner reads of a vector, checked once at load so that a damaged file is reported by
# name rather than failing half-way through a run (the full schema is vectors/schema/).
VECTOR_KEYS = {"id": str, "family": str, "instruction": str, "initial": dict, "steps": list,
               "final": dict, "outcome": dict}


def shape_problem(v, family: str) -> str:
    """What keeps `v`, read from `family`'s file, from being run and judged ("" when nothing does)."""
    if not isinstance(v, dict):
        return "not a JSON object"
    for key, kind in VECTOR_KEYS.items():
        if not isinstance(v.get(key), kind):
            return f"no `{key}` ({kind.__name__})"
    if v["family"] != family:
        return f"family {v['family']!r} in a {family!r} file"
    if not isinstance(v["initial"].get("devices"), dict) or not isinstance(v["initial"].get("operands"), dict):
        return "`initial` needs `devices` and `operands`"
    if not v["steps"] or not all(isinstance(st, dict) and isinstance(st.get(_EXPECT), dict) for st in v["steps"]):
        return "every step needs an `expect`"
    if not isinstance(v["final"].get("devices"), dict):
        return "`final` needs `devices`"
    return ""


__all__ = ["Vector", "Step", "VectorRequest", "request_of", "touched_interpretations", "shape_problem"]
