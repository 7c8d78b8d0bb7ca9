"""Mutants of the FX5 time and date comparisons (LDTM□/ANDTM□/ORTM□, LDDT□/ANDDT□/ORDT□)."""
from __future__ import annotations

import calendar

from ..fx5_compare import CONDITIONS, SM709, Fx5Compare, parse_mnemonic
from ..machine import operand_value, to_signed16
from .registry import DeviceRangeUnchecked, mutant, with_operand

TIME, DATE = "fx5-time-compare", "fx5-date-compare"
BOTH = (TIME, DATE)

# (s3) "(5) When 1 is set to the 15 bit, the data in the device specified by (s1) is compared
# with the current time"; "(1) ... (2) ... (3)": bits 0 to 2 select the fields.
CLOCK_BIT = 0x8000
FIELD_BITS = 0x0007


class _FieldsMisread(Fx5Compare):
    """Built on misread(fields): the bug is in how the page's field table was copied."""

    @staticmethod
    def misread(fields):
        raise NotImplementedError

    def __init__(self, *args):
        super().__init__(*args)
        self.fields = self.misread(self.fields)


@mutant("fx5-low-field-first", BOTH,
        "The selected fields are compared from (s1)+2 up (second before minute before hour, "
        "day before month before year), so a later field decides before an earlier one.")
class LowFieldFirst(_FieldsMisread):
    @staticmethod
    def misread(fields):
        return fields[::-1]


@mutant("fx5-selector-bits-reversed", BOTH,
        "The (s3) bit configuration is read from the other end: b0 selects hour (year) and b2 "
        "second (day), instead of '(1) Set \"second\" as comparison target' for b0.",
        exercises={"selector": ["hour", "second", "year", "day", "*+minute", "minute+*", "*+month", "month+*"]})
class SelectorBitsReversed(_FieldsMisread):
    @staticmethod
    def misread(fields):
        top = max(bit for *_, bit in fields)
        return [(offset, name, lo, hi, top - bit) for offset, name, lo, hi, bit in fields]


class _S3Misread(Fx5Compare):
    """Executes as if (s3) held misread(s3): the bug is in how (s3) is decoded."""

    @staticmethod
    def misread(s3: int) -> int:
        raise NotImplementedError

    def evaluate(self, condition, operands, clock):
        s3 = operand_value(self.mem, operands["s3"])
        return super().evaluate(condition, with_operand(operands, "s3", self.misread(s3)), clock)


@mutant("fx5-clock-bit-ignored", BOTH,
        "Bit 15 of (s3) is ignored: (s1) is always compared with (s2), never with the current "
        "time or date.",
        exercises={"source": ["current-clock"]})
class ClockBitIgnored(_S3Misread):
    @staticmethod
    def misread(s3):
        return s3 & ~CLOCK_BIT


@mutant("fx5-reserved-bits-ignored", BOTH,
        "Bits 3 to 14 of (s3) are masked off instead of '(4) Set 0. If a value other than 0 is "
        "set, the operation result will be non-continuity'.",
        exercises={"selector": ["reserved", "reserved+fields"]})
class ReservedBitsIgnored(_S3Misread):
    @staticmethod
    def misread(s3):
        return s3 & (CLOCK_BIT | FIELD_BITS)


@mutant("fx5-empty-selector-equal", BOTH,
        "When 0 is set to the 0 to 2 bits no field differs, so the data count as equal (TM=/DT= "
        "conducts) instead of 'the operation result will be non-continuity'.",
        exercises={"selector": ["none"]})
class EmptySelectorEqual(Fx5Compare):
    def evaluate(self, condition, operands, clock):
        if operand_value(self.mem, operands["s3"]) & ~CLOCK_BIT == 0:
            return CONDITIONS[condition](0)
        return super().evaluate(condition, operands, clock)


@mutant("fx5-sm709-not-latched", BOTH,
        "SM709 is written on every execution, off when the data are good, although 'Once SM709 "
        "turns on, the on state is held until the CPU module is powered off or reset'.",
        exercises={"error-before": ["on"]})
class SM709NotLatched(Fx5Compare):
    def evaluate(self, condition, operands, clock):
        self.raised = False
        result = super().evaluate(condition, operands, clock)
        if not self.raised:
            self.mem.write(SM709, False)
        return result

    def _error(self):
        self.raised = True
        return super()._error()


@mutant("fx5-device-range-unchecked", BOTH,
        "(s1) to (s1)+2 and (s2) to (s2)+2 are not checked against the device range, although 'If "
        "the device areas ... exceed the corresponding device range, SM709 turns on'.",
        exercises={"data": ["*.device-range"]})
class DeviceRangeUncheckedFX5(DeviceRangeUnchecked, Fx5Compare):
    pass


@mutant("fx5-time-hour-24-accepted", (TIME,),
        "The hour range check is off by one ('within the range 0 to 23' taken as 0 to 24), so "
        "hour 24 is compared instead of turning SM709 on.",
        exercises={"data": ["*.hour.above"]})
class Hour24Accepted(_FieldsMisread):
    @staticmethod
    def misread(fields):
        return [(offset, name, lo, hi + 1 if name == "hour" else hi, bit) for offset, name, lo, hi, bit in fields]


def nonexistent(words) -> bool:
    """A year/month/day whose day is past the end of its month (2006/02/30)."""
    year, month, day = (to_signed16(w) for w in words)
    if not 1 <= month <= 12:
        return False
    days = calendar.mdays[month] + (month == 2 and calendar.isleap(year))
    return day > days


@mutant("fx5-date-calendar-check", (DATE,),
        "A date that does not exist but is within the setting range (2006/02/30) turns SM709 on, "
        "although 'Even if the data are not recognized as date data, SM709 does not turn on if "
        "the data are within the setting range'.",
        exercises={"data": ["nonexistent"]})
class CalendarCheck(Fx5Compare):
    def _out_of_range(self, words, selected_only_bits) -> bool:
        day_bit = next(bit for _o, name, *_, bit in self.fields if name == "day")
        day_checked = selected_only_bits is None or (selected_only_bits >> day_bit) & 1
        return super()._out_of_range(words, selected_only_bits) or bool(day_checked and nonexistent(words))


@mutant("fx5-date-nonexistent-rejected", (DATE,),
        "A date that does not exist (2008/02/31) makes the result non-continuity, although the "
        "manual says it 'can be set' and 'the comparison operation is performed'.",
        exercises={"data": ["nonexistent", "*.day.above"]})
class NonexistentRejected(Fx5Compare):
    def evaluate(self, condition, operands, clock):
        result = super().evaluate(condition, operands, clock)
        dates = [self.mem.read_block(operands["s1"]["device"], 3)]
        if not operand_value(self.mem, operands["s3"]) & CLOCK_BIT:
            dates.append(self.mem.read_block(operands["s2"]["device"], 3))
        return result and not any(nonexistent(d) for d in dates)


@mutant("fx5-or-in-series", BOTH,
        "ORTM□/ORDT□ combine the comparison with the preceding logic in series, as ANDTM□/ANDDT□ do, "
        "although the contact is connected in parallel.",
        exercises={"form": ["OR"]})
class OrInSeries(Fx5Compare):
    def execute(self, instruction, operands, step):
        form, condition = parse_mnemonic(instruction, self.kind)
        if form != "OR":
            return super().execute(instruction, operands, step)
        rlo = bool(step["rlo_in"])
        return rlo and self.evaluate(condition, operands, step.get("clock"))


@mutant("fx5-and-ignores-preceding-off", BOTH,
        "ANDTM□/ANDDT□ pass their own comparison on whatever the preceding logic, as if it were "
        "always on, so a rung that is off conducts.",
        exercises={"logic": ["off"]})
class AndIgnoresPrecedingOff(Fx5Compare):
    def execute(self, instruction, operands, step):
        form, condition = parse_mnemonic(instruction, self.kind)
        if form == "AND":
            return self.evaluate(condition, operands, step.get("clock"))
        return super().execute(instruction, operands, step)


@mutant("fx5-le-as-lt", BOTH,
        "TM<=/DT<= conducts only when (s1) < (s2), as TM</DT< does, instead of '(s1)≤(s2)'.",
        exercises={"condition": ["<="]})
class LeAsLt(Fx5Compare):
    def evaluate(self, condition, operands, clock):
        return super().evaluate("<" if condition == "<=" else condition, operands, clock)


@mutant("fx5-equal-counts-as-less", BOTH,
        "When every selected field is equal the comparison answers (s1) < (s2) instead of "
        "(s1) = (s2), so TM=/DT= never conducts and TM</DT< does.",
        exercises={"ordering": ["eq"]})
class EqualCountsAsLess(Fx5Compare):
    def _compare(self, s1, s2, s3):
        return super()._compare(s1, s2, s3) or -1
