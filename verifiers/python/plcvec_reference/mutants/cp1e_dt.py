"""Mutants of the CP1E time comparisons LD/AND/OR =DT, <>DT, <DT, <=DT, >DT, >=DT."""
from __future__ import annotations

from ..cp1e_dt import ERROR_FLAG, FLAG_TABLE, Cp1eTimeCompare
from ..machine import operand_value
from .registry import DeviceRangeUnchecked, mutant, with_operand

FAMILY = ("cp1e-time-compare",)


@mutant("cp1e-bcd-read-as-binary", FAMILY,
        "The BCD check looks at the byte's value instead of each digit: a byte up to 99H passes, so "
        "1AH is compared instead of turning P_ER on, while A0H still turns it on.",
        exercises={"data": ["*.non-bcd"]})
class BCDReadAsBinary(Cp1eTimeCompare):
    # Until 0.2.0 this mutant checked no byte: that is the reading CP1E-NON-BCD=raw-bytes, which a
    # declaration explains, so it was no bug.
    is_bcd = staticmethod(lambda byte: byte <= 0x99)


@mutant("cp1e-mask-bit-shifted", FAMILY,
        "The mask bits of C are counted from 1: bit 01 masks the seconds ... bit 06 the year, "
        "instead of 'Bits 00 to 05 of C mask the seconds, minutes, hours, day, month, and year'.",
        exercises={"mask": ["year", "month", "day", "hour", "minute", "second", "all-but-*", "some", "none", "reserved+fields", "reserved"]})
class MaskBitShifted(Cp1eTimeCompare):
    FIELDS = [field[:-1] + (field[-1] + 1,) for field in Cp1eTimeCompare.FIELDS]


@mutant("cp1e-mask-inverted", FAMILY,
        "A C bit set to 1 selects its field for comparison, the opposite of 'To mask a time "
        "value, set the corresponding bit in the control word (C) to 1'.")
class MaskInverted(Cp1eTimeCompare):
    def evaluate(self, condition, operands):
        mask_bits = sum(1 << field[-1] for field in self.FIELDS)
        c = operand_value(self.mem, operands["C"]) ^ mask_bits
        return super().evaluate(condition, with_operand(operands, "C", c))


@mutant("cp1e-seconds-first", FAMILY,
        "The unmasked fields are compared from S1 (seconds) up instead of from the year down, so "
        "a later field decides before an earlier one.",
        exercises={"mask": ["all", "all-but-*", "some", "reserved", "reserved+fields"]})
class SecondsFirst(Cp1eTimeCompare):
    FIELDS = Cp1eTimeCompare.FIELDS[::-1]


@mutant("cp1e-and-as-or", FAMILY,
        "AND =DT … AND >=DT combine the comparison with the preceding logic as OR does.",
        exercises={"form": ["AND"]})
class AndAsOr(Cp1eTimeCompare):
    def execute(self, instruction, operands, step):
        form, _, symbol = instruction.partition(" ")
        return super().execute(f"OR {symbol}" if form == "AND" else instruction, operands, step)


@mutant("cp1e-flags-not-reflected", FAMILY,
        "The arithmetic flags (=, <>, <, <=, >, >=) are left alone, although 'the result of a "
        "time comparison instruction is reflected in the arithmetic flags'.",
        exercises={"ordering": ["lt", "eq", "gt"]})
class FlagsNotReflected(Cp1eTimeCompare):
    def reflect_flags(self, order):
        pass


@mutant("cp1e-or-ignores-on", FAMILY,
        "OR =DT … OR >=DT pass on only their own comparison, dropping an execution condition that "
        "is already ON, instead of combining the two as OR does.",
        exercises={"logic": ["on"]})
class OrIgnoresOn(Cp1eTimeCompare):
    def execute(self, instruction, operands, step):
        form, _, symbol = instruction.partition(" ")
        if form == "OR":
            return self.evaluate(symbol[:-2], operands)
        return super().execute(instruction, operands, step)


@mutant("cp1e-ne-as-gt", FAMILY,
        "<>DT gives ON only when S1 > S2, as >DT does, instead of whenever S1 and S2 differ.",
        exercises={"condition": ["<>DT"]})
class NeAsGt(Cp1eTimeCompare):
    def evaluate(self, condition, operands):
        return super().evaluate(">" if condition == "<>" else condition, operands)


@mutant("cp1e-equal-as-less", FAMILY,
        "Equal unmasked data are taken as S1 < S2, so =DT never gives ON and the flags show '<'.",
        exercises={"ordering": ["eq"]})
class EqualAsLess(Cp1eTimeCompare):
    def reflect_flags(self, order):
        self.order = order or -1
        super().reflect_flags(self.order)

    def evaluate(self, condition, operands):
        self.order = None
        result = super().evaluate(condition, operands)
        return result if self.order is None else FLAG_TABLE[self.order][condition]


@mutant("cp1e-error-flag-blocks", FAMILY,
        "With P_ER already ON the comparison is not executed at all (execution condition OFF, flags "
        "and P_ER left as they were), as if an earlier error stopped the instruction.",
        exercises={"error-before": ["on"]})
class ErrorFlagBlocks(Cp1eTimeCompare):
    def evaluate(self, condition, operands):
        if self.mem.read(ERROR_FLAG):
            return False
        return super().evaluate(condition, operands)


@mutant("cp1e-past-area-compared", FAMILY,
        "S1 or S2 at the last one or two words of the data area is compared all the same, the words "
        "past the end read as 0, instead of the error or program error CP1E-PAST-AREA-END names.",
        exercises={"data": ["*.device-range"]})
class PastAreaCompared(DeviceRangeUnchecked, Cp1eTimeCompare):
    pass

