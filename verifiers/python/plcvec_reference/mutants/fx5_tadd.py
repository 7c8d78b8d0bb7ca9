"""Mutants of the FX5 clock addition TADD / TADDP."""
from __future__ import annotations

from ..fx5_tadd import DAY, TADDMachine
from . import DeviceRangeUnchecked, mutant

FAMILY = ("fx5-time-add",)


@mutant("tadd-no-wrap-at-24", FAMILY,
        "'If the sum of two values exceeds 24:00:00' read literally: a sum of exactly 24:00:00 "
        "is stored as 24:00:00 with neither flag, not as 0:00:00 with carry and zero.")
class NoWrapAt24(TADDMachine):
    def wrap(self, total):
        if total == DAY:
            return total, False
        return super().wrap(total)


@mutant("tadd-flags-not-written", FAMILY,
        "The carry flags SM700/SM8022 and the zero flag SM8020 are never written.")
class FlagsNotWritten(TADDMachine):
    def _set_flags(self, carry, zero):
        pass


@mutant("tadd-sm8022-not-written", FAMILY,
        "Only SM700 is written as the carry flag; SM8022, the table's second 'Carry' relay, "
        "is left alone.")
class SM8022NotWritten(TADDMachine):
    CARRY_FLAGS = TADDMachine.CARRY_FLAGS[:1]


@mutant("taddp-every-scan", FAMILY,
        "TADDP adds on every scan while EN is on, like TADD, instead of once on its rising edge.")
class TADDPEveryScan(TADDMachine):
    def execute(self, instruction, operands, step):
        return super().execute("TADD" if instruction == "TADDP" else instruction, operands, step)


@mutant("tadd-hour-24-accepted", FAMILY,
        "The hour range check is off by one ('0 to 23' taken as 0 to 24), so hour 24 in (s1) or "
        "(s2) is added instead of raising error 3405H.")
class Hour24Accepted(TADDMachine):
    RANGES = [(TADDMachine.RANGES[0][0], TADDMachine.RANGES[0][1] + 1)] + TADDMachine.RANGES[1:]


@mutant("tadd-device-range-unchecked", FAMILY,
        "(s1), (s2) and (d) are not checked against the device range, so error 2820H ('The device "
        "range specified by (s1), (s2), and (d) exceeds the corresponding device range') never occurs.")
class DeviceRangeUncheckedTADD(DeviceRangeUnchecked, TADDMachine):
    pass
