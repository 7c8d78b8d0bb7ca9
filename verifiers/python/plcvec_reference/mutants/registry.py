"""The register of mutants and what they share: each family module registers its mutants here, so
that the package imports them all without them importing the package back.
"""
from __future__ import annotations

from dataclasses import dataclass

from .. import MACHINES, make_machine
from ..machine import DeviceMemory

MUTANTS: dict = {}


@dataclass(frozen=True)
class Mutant:
    name: str
    families: tuple        # the instruction families whose machine carries the bug
    description: str       # the bug, in the manual's words
    cls: type              # the buggy subclass of the families' reference machine class
    # The dimensions of the families' coverage models (spec: coverage.model) the bug lives in:
    # ((dimension, (class patterns, ...)), ...); every vector that catches the mutant exercises, in
    # each of them, a class the patterns match (tests/test_mutants.py checks it).
    exercises: tuple = ()

    def make_machine(self, family: str, devices: dict, device_sizes: dict, choices: dict | None = None):
        """Like plcvec_reference.make_machine; the plain reference for the other families."""
        return make_machine(family, devices, device_sizes, choices,
                            cls=self.cls if family in self.families else None)


def mutant(name: str, families: tuple, description: str, exercises: dict | None = None):
    """Class decorator: register the class as the mutant `name` of `families`; `exercises` maps a
    coverage-model dimension to the class patterns every catching vector exercises in it."""
    def register(cls):
        if name in MUTANTS:
            raise ValueError(f"mutant {name} defined twice")
        for family in families:
            if not issubclass(cls, MACHINES[family][0]):
                raise TypeError(f"mutant {name}: {cls.__name__} is not a {MACHINES[family][0].__name__}")
        MUTANTS[name] = Mutant(name, tuple(families), description, cls,
                               tuple((d, tuple(p)) for d, p in (exercises or {}).items()))
        return cls
    return register


def with_operand(operands: dict, key: str, value: int) -> dict:
    """The operands with `key` replaced by the constant `value` (to execute on a misread word)."""
    return {**operands, key: {"constant": value}}


class _DictMemory(DeviceMemory):
    """Devices kept in a dict with no size: every block 'exists', a word past the end reads 0."""

    def block_in_range(self, base, words):
        return True


class DeviceRangeUnchecked:
    """Mixin for a machine class: the emulator never checks an operand against its device range."""

    def __init__(self, *args):
        super().__init__(*args)
        self.mem = _DictMemory(self.mem.values, self.mem.sizes)


__all__ = ["MUTANTS", "Mutant", "mutant", "with_operand", "DeviceRangeUnchecked"]
