"""The vector folder `plcvec export` reads, refused exactly as `plcvec verify` refuses it.

A native runner that gets its vectors through export (C compiles them in) must not build from a
folder the Python runner would refuse: the same loader reads it first (plcvec_verify.suite: the
schema, unknown keys under CONTRACT.md's one rule, a major schema version, non-UTF-8, a cut or
non-JSON file with its line, a duplicated id, a family file whose sha256 is not the one
manifest.json records). One check that loader does not make is made here: one JSON type per device
throughout a vector (a bit holding 2 is not a word). Each refusal is one message naming the file
(and line) or the vector, exit 2, and nothing is written.
"""
from __future__ import annotations

import json
from pathlib import Path

from plcvec.errors import PlcvecError


def check_vectors(folder) -> None:
    """Raise PlcvecError when `folder` (golden JSON files with manifest.json) is not a sound vector set."""
    from plcvec_verify.errors import VerifyError
    from plcvec_verify.suite import Suite

    folder = Path(folder)
    try:
        suite = Suite.load(folder)
    except VerifyError as exc:
        raise PlcvecError(f"export: {exc}") from None
    for vector in suite.vectors:
        problem = device_types_problem(vector)
        if problem:
            family = vector.get("family", "")
            raise PlcvecError(f"export: {folder / (family + '.json')}: vector {vector['id']}: {problem}")


def _cells(vector: dict):
    """(where, device, value) for every device value a vector holds."""
    yield from (("initial", d, v) for d, v in vector["initial"]["devices"].items())
    for i, step in enumerate(vector["steps"]):
        yield from ((f"steps[{i}].set", d, v) for d, v in step.get("set", {}).items())
        yield from ((f"steps[{i}].expect", d, v) for d, v in step["expect"].get("devices", {}).items())
    yield from (("final", d, v) for d, v in vector["final"]["devices"].items())
    for a, alt in enumerate(vector.get("alternatives", ())):
        for i, x in enumerate(alt.get("expect", ())):
            yield from ((f"alternatives[{a}].expect[{i}]", d, v) for d, v in x.get("devices", {}).items())


def device_types_problem(vector: dict) -> str:
    """A device that is a bit (true/false) in one place and a word (a number) in another: "" if none."""
    first: dict[str, tuple[str, object]] = {}
    for where, device, value in _cells(vector):
        seen = first.setdefault(device, (where, value))
        if isinstance(seen[1], bool) != isinstance(value, bool):
            kinds = {True: "a bit", False: "a word"}
            return (f"{device} is {kinds[isinstance(seen[1], bool)]} in {seen[0]} ({json.dumps(seen[1])}) and "
                    f"{kinds[isinstance(value, bool)]} in {where} ({json.dumps(value)}): a device holds one type "
                    "throughout a vector")
    return ""
