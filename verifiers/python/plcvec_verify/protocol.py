"""The JSON-lines adapter protocol: message shapes and their validation.

The JSON Schemas in `schema/` are the definition (PROTOCOL.md documents them with a transcript).
Every message an adapter sends is checked against them. Result messages are many, and a full
JSON Schema validation costs far more than running a vector, so a result goes through a cheap
structural check first; only a message that check does not accept goes to the full validator,
which is the judge and gives the message a user reads. The cheap check never accepts what the
schema rejects (tests/test_verify_protocol.py draws messages with hypothesis to show it).
"""
from __future__ import annotations

import json
from functools import lru_cache
from pathlib import Path

from .quick_schema import compile_schema

PROTOCOL_VERSION = 1
SCHEMA_DIR = Path(__file__).resolve().parent / "schema"

# Message file names by (direction, type).
SCHEMAS = {
    "hello-request": "hello-request.schema.json",
    "hello-response": "hello-response.schema.json",
    "run-request": "run-request.schema.json",
    "result": "result.schema.json",
    "bye": "bye.schema.json",
    "fatal": "fatal.schema.json",
}

WORD_MAX = 0xFFFF


@lru_cache(maxsize=None)
def validator(name: str):
    import jsonschema

    schema = json.loads((SCHEMA_DIR / SCHEMAS[name]).read_text(encoding="utf-8"))
    cls = jsonschema.validators.validator_for(schema)
    cls.check_schema(schema)
    return cls(schema)


@lru_cache(maxsize=None)
def quick_check(name: str):
    """Schema `name`'s quick check (quick_schema.py): jsonschema's answer to "valid?", or None for a
    schema it cannot read in full."""
    return compile_schema(json.loads((SCHEMA_DIR / SCHEMAS[name]).read_text(encoding="utf-8")))


def message_errors(name: str, message) -> list[str]:
    """schema_errors(name, message), with no jsonschema (nor its import, a tenth of a second) for a
    message the quick check shows valid: the handshake of every run."""
    check = quick_check(name)
    if check is not None and check(message):
        return []
    return schema_errors(name, message)


def schema_errors(name: str, message) -> list[str]:
    """Every way `message` breaks schema `name`, as `at <path>: <reason>` lines (empty: valid)."""
    errors = sorted(validator(name).iter_errors(message), key=lambda e: list(e.absolute_path))
    out = []
    for e in errors:
        where = "/".join(str(p) for p in e.absolute_path) or "(the message)"
        out.append(f"at {where}: {e.message}")
    return out


def _device_values_ok(devices) -> bool:
    if type(devices) is not dict or "" in devices:
        return False
    for v in devices.values():
        t = type(v)
        if t is bool:
            continue
        if t is not int or not 0 <= v <= WORD_MAX:
            return False
    return True


def _step_ok(step) -> bool:
    if type(step) is not dict or not _device_values_ok(step.get("devices")):
        return False
    n = len(step)
    if "result" in step:
        return n == 2 and type(step["result"]) is bool
    return n == 1


def result_looks_valid(msg) -> bool:
    """A sufficient (not necessary) condition for `msg` to be a valid result message."""
    if type(msg) is not dict or len(msg) != 3 or msg.get("type") != "result" or type(msg.get("id")) is not str:
        return False
    steps = msg.get("steps")
    if steps is not None:
        return type(steps) is list and all(_step_ok(s) for s in steps)
    for key in ("skip", "error"):
        value = msg.get(key)
        if value is not None:
            return type(value) is str and value != ""
    return False


def result_errors(msg) -> list[str]:
    """Schema errors of a result message; fast when it is valid."""
    if result_looks_valid(msg):
        return []
    return schema_errors("result", msg)


def result_shape_ok(msg) -> bool:
    """The structure a comparison can walk, without looking at each device value.

    The runner compares first and validates fully only when the comparison finds a difference:
    a comparison that passes has seen every reported value equal, with its type, to a value of
    the vector, and those are valid. This saves the walk over every value of every answer.
    """
    if type(msg) is not dict or len(msg) != 3 or msg.get("type") != "result" or type(msg.get("id")) is not str:
        return False
    steps = msg.get("steps")
    if type(steps) is not list:
        return False
    for step in steps:
        if type(step) is not dict or type(step.get("devices")) is not dict:
            return False
        if len(step) != 1 and (len(step) != 2 or type(step.get("result")) is not bool):
            return False
    return True


def hello_request(suite, families, *, protocol=PROTOCOL_VERSION) -> dict:
    """The runner's first line: who is asking, for which suite, and what it contains."""
    interps = suite.interpretations(families)
    return {
        "type": "hello",
        "protocol": protocol,
        "suite_version": suite.suite_version,
        "schema_version": suite.schema_version,
        "spec_sha256": suite.spec_sha256,
        "families": {
            family: {
                "instructions": suite.headers[family].get("instructions", []),
                "interpretations": {i: {"default": d["default"], "alternatives": d["alternatives"]}
                                    for i, d in interps.items() if family in d["families"]},
            }
            for family in sorted(families)
        },
    }


_ENCODER = json.JSONEncoder(separators=(",", ":"), ensure_ascii=False)


def encode(message: dict) -> bytes:
    """One protocol line. Compact separators: the lines are for programs, and size is speed."""
    return _ENCODER.encode(message).encode("utf-8") + b"\n"
