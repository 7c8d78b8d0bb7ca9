"""The in-process interface (VOCABULARY.md: `implementation`): what an object must provide to be run
by `plcvec verify --python`, the pytest plugin's `--plcvec-python` and `adapters.InProcess`.

Python's form is duck-typed, with the messages of PROTOCOL.md as plain dicts: an implementation
gets a vector's request and answers with what a process would write, less `type` and `id`. It
works on whatever memory it likes (the reference keeps a dict of device values): the package has
no emulator or memory type of its own, as the native runners do, because a dict already is one.
"""
from __future__ import annotations

from typing import Protocol, TypedDict

from .vector import VectorRequest


class StepResult(TypedDict, total=False):
    """What an implementation reports after one step: the whole device image (`devices`: address ->
    word or bit) and, for a contact instruction (the LD/AND/OR forms), the logic state (`result`)."""

    devices: dict
    result: bool


class Implementation(Protocol):
    """An implementation the runner drives in this process.

    It may also have `close()`, called once after the run, and a `cpu_writes` attribute: the devices
    its CPU writes on its own account (diagnostic relays and registers), which a vector that does not
    list them does not count as stray writes (CONTRACT.md).
    """

    def hello(self, request: dict) -> dict:
        """`request` is the runner's hello message (suite version, spec hash, the families with their
        instructions and interpretations). Returns {"adapter": {"name", "version"}, "instructions":
        [...], "interpretations": {id: alternative}, "cpu_writes"?: [device, ...]}: the hello-response
        message without `type` and `protocol`."""

    def run(self, request: VectorRequest) -> dict:
        """`request` is one vector without its expectations, run from its own initial state (nothing is
        carried over from an earlier vector). Returns {"steps": [StepResult, ...]}, one per step, or
        skip(reason), or {"error": message}: a result message without `type` and `id`."""


def skip(reason: str) -> dict:
    """The answer of an implementation that does not run this vector (reported as skipped, which a gate
    holds to --max-skipped): say why, e.g. skip("no TADDP yet")."""
    return {"skip": reason}


__all__ = ["Implementation", "StepResult", "skip"]
