"""Mutants of the FX5 clock addition TADD / TADDP."""
from __future__ import annotations

from ..fx5_tadd import DAY, ZERO_FLAG, Fx5TimeAdd
from ..machine import to_signed16
from .registry import DeviceRangeUnchecked, mutant

FAMILY = ("fx5-time-add",)


@mutant("tadd-no-wrap-at-24", FAMILY,
        "'If the sum of two values exceeds 24:00:00' read literally: a sum of exactly 24:00:00 "
        "is stored as 24:00:00 with neither flag, not as 0:00:00 with carry and zero.",
        exercises={"sum": ["exact-wrap"]})
class NoWrapAt24(Fx5TimeAdd):
    def wrap(self, total):
        if total == DAY:
            return total, False
        return super().wrap(total)


@mutant("tadd-flags-not-written", FAMILY,
        "The carry flags SM700/SM8022 and the zero flag SM8020 are never written.")
class FlagsNotWritten(Fx5TimeAdd):
    def _set_flags(self, carry, zero):
        pass


@mutant("tadd-sm8022-not-written", FAMILY,
        "Only SM700 is written as the carry flag; SM8022, the table's second 'Carry' relay, "
        "is left alone.")
class SM8022NotWritten(Fx5TimeAdd):
    CARRY_FLAGS = Fx5TimeAdd.CARRY_FLAGS[:1]


@mutant("taddp-every-scan", FAMILY,
        "TADDP adds on every scan while EN is on, like TADD, instead of once on its rising edge.",
        exercises={"instruction": ["TADDP"], "en": ["held"]})
class TADDPEveryScan(Fx5TimeAdd):
    def execute(self, instruction, operands, step):
        return super().execute("TADD" if instruction == "TADDP" else instruction, operands, step)


@mutant("tadd-hour-24-accepted", FAMILY,
        "The hour range check is off by one ('0 to 23' taken as 0 to 24), so hour 24 in (s1) or "
        "(s2) is added instead of raising error 3405H.",
        exercises={"data": ["*.hour.above"]})
class Hour24Accepted(Fx5TimeAdd):
    RANGES = [(Fx5TimeAdd.RANGES[0][0], Fx5TimeAdd.RANGES[0][1] + 1)] + Fx5TimeAdd.RANGES[1:]


@mutant("tadd-device-range-unchecked", FAMILY,
        "(s1), (s2) and (d) are not checked against the device range, so error 2820H ('The device "
        "range specified by (s1), (s2), and (d) exceeds the corresponding device range') never occurs.",
        exercises={"data": ["*.device-range"]})
class DeviceRangeUncheckedTADD(DeviceRangeUnchecked, Fx5TimeAdd):
    pass


@mutant("tadd-d-cleared-first", FAMILY,
        "(d) is cleared to 0:00:00 before (s1) and (s2) are read, so a source word that is also a "
        "word of the destination is added as 0.",
        exercises={"aliasing": ["s1=d", "s2=d", "d-overlaps-*"]})
class DClearedFirst(Fx5TimeAdd):
    def add(self, operands):
        devices = [operands[k]["device"] for k in ("s1", "s2", "d")]
        if all(self.mem.block_in_range(dev, 3) for dev in devices):
            words = [to_signed16(w) for dev in devices[:2] for w in self.mem.read_block(dev, 3)]
            if all(lo <= v <= hi for v, (lo, hi) in zip(words, self.RANGES * 2)):
                self.mem.write_block(devices[2], [0, 0, 0])   # the checks passed: (d) is "prepared"
        super().add(operands)


@mutant("tadd-runs-while-en-off", FAMILY,
        "TADD adds while its execution condition is off too, as if EN were not an execution condition.",
        exercises={"en": ["off"]})
class RunsWhileEnOff(Fx5TimeAdd):
    def execute(self, instruction, operands, step):
        if instruction == "TADD" and not step["en"]:
            self.previous_en = False
            self.add(operands)
            return None
        return super().execute(instruction, operands, step)


@mutant("tadd-zero-flag-set-only", FAMILY,
        "The zero flag SM8020 is only ever turned on: a result that is not 0:00:00 leaves it on, "
        "although every execution writes the carry flags.",
        exercises={"flags-before": ["on"]})
class ZeroFlagSetOnly(Fx5TimeAdd):
    def _set_flags(self, carry, zero):
        was = self.mem.read(ZERO_FLAG)
        super()._set_flags(carry, zero)
        if was:
            self.mem.write(ZERO_FLAG, True)


@mutant("tadd-s1-copied-into-d-first", FAMILY,
        "(s1) is copied into (d) word by word from the hour, then (s2) is added to (d) in place, so a word "
        "of (s2), or a later word of (s1), that is also a word of (d) is overwritten before it is read.",
        exercises={"aliasing": ["s2=d", "d-overlaps-*"]})
class S1CopiedIntoDFirst(Fx5TimeAdd):
    def sum_seconds(self, s1_dev, s2_dev, d_dev):
        mem = self.mem
        for k in range(3):
            mem.write(mem.address(d_dev, k), mem.read(mem.address(s1_dev, k)))
        return super().sum_seconds(d_dev, s2_dev, d_dev)

