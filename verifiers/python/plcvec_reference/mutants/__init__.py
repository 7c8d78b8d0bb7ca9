"""Mutants: the reference implementation with exactly one plausible bug each.

Design principle 7: "Verifiers are tested by mutants. A verifier that cannot fail is a defect."
Each mutant is a subclass of one reference machine class that overrides one method or one
class attribute, so the bug is the whole difference. tests/test_mutants.py proves the verifier
rejects every one of them, in process and over the stdio protocol; a mutant that survives means
the vectors are missing a case. MUTANTS.md beside this package lists which vectors catch which.

    from plcvec_reference.mutants import MUTANTS
    machine = MUTANTS["tadd-no-wrap-at-24"].make_machine(family, devices, device_sizes, choices)
    python3 -m plcvec_reference.adapter --mutant tadd-no-wrap-at-24
"""
from __future__ import annotations

from .registry import MUTANTS, DeviceRangeUnchecked, Mutant, mutant, with_operand

# Importing the modules registers their mutants, listed family by family.
from . import fx5_compare, fx5_tadd, fc6a_hour, cp1e_dt  # noqa: E402,F401,I001

__all__ = ["MUTANTS", "Mutant", "mutant", "with_operand", "DeviceRangeUnchecked"]
