"""Mitsubishi MELSEC iQ-F FX5: LDTM□/ANDTM□/ORTM□ (time) and LDDT□/ANDDT□/ORDT□ (date).

Written from the manual pages fx5-time-compare-LDTM.txt and
fx5-date-compare-LDDT.txt.  The two pages are the same text with
hour/minute/second replaced by year/month/day, so one class serves both.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from plcvec_verify._renamed import old_names

from .machine import DeviceMemory, to_signed16

# Interpretation defaults (spec/fx5-time-compare.yaml, spec/fx5-date-compare.yaml).
ALTERNATIVES = {
    "FX5-SM709-SCOPE": ("selected-fields", "all-words", "compared-operands"),
    "FX5-AND-OR-WHEN-OFF": ("and-skipped", "always-executed", "short-circuit"),
    "FX5-CLOCK-S2-DEVICE-RANGE": ("ignored", "checked"),
    "FX5-OR-ON-ERROR": ("contact-off", "result-off"),
    "FX5-INVALID-S3-DEVICE-RANGE": ("device-range-first", "s3-first"),
}

DEFAULTS = {
    "FX5-SM709-SCOPE": "selected-fields",          # or "all-words", "compared-operands"
    "FX5-AND-OR-WHEN-OFF": "and-skipped",          # or "always-executed", "short-circuit"
    "FX5-CLOCK-S2-DEVICE-RANGE": "ignored",        # or "checked"
    "FX5-OR-ON-ERROR": "contact-off",              # or "result-off"
    "FX5-INVALID-S3-DEVICE-RANGE": "device-range-first",  # or "s3-first"
}

SM709 = "SM709"

# Field layout, most significant first; (word offset, name, min, max, (s3) bit).
# Time: 'Set the "hour" data ... within the range 0 to 23.'  'Set the "minute" data
# in the devices specified by (s1)+1 ... 0 to 59.'  '"second" ... (s1)+2 ... 0 to 59.'
# '(1) Set "second" as comparison target. (2) ... "minute" ... (3) ... "hour"'
TIME_FIELDS = [
    (0, "hour", 0, 23, 2),
    (1, "minute", 0, 59, 1),
    (2, "second", 0, 59, 0),
]
# Date: 'Set the 4 digit "year" data ... within the range 1980 to 2079.'
# '"month" data in ... (s1)+1 ... 1 to 12.'  '"date" data in ... (s1)+2 ... 1 to 31.'
# '(1) Set "day" ... (2) ... "month" ... (3) ... "year"'
DATE_FIELDS = [
    (0, "year", 1980, 2079, 2),
    (1, "month", 1, 12, 1),
    (2, "day", 1, 31, 0),
]

# "The following table lists the comparison operation results of each instruction."
# TM=/DT= (s1)=(s2), <> (s1)≠(s2), > (s1)>(s2), <= (s1)≤(s2), < (s1)<(s2), >= (s1)≥(s2).
CONDITIONS = {
    "=": lambda c: c == 0,
    "<>": lambda c: c != 0,
    ">": lambda c: c > 0,
    "<=": lambda c: c <= 0,
    "<": lambda c: c < 0,
    ">=": lambda c: c >= 0,
}


def parse_mnemonic(instruction: str, kind: str):
    """'ANDTM<=' -> ('AND', '<=')."""
    for form in ("LD", "AND", "OR"):
        prefix = form + kind
        if instruction.startswith(prefix):
            return form, instruction[len(prefix):]
    raise ValueError(f"not an FX5 {kind} comparison: {instruction}")


class Fx5Compare:
    """An FX5 CPU executing one time- or date-comparison contact per scan."""

    CONTACT = True

    def __init__(self, devices: dict, device_sizes: dict, kind: str, choices: dict | None = None):
        if kind not in ("TM", "DT"):
            raise ValueError(kind)
        self.kind = kind
        self.fields = TIME_FIELDS if kind == "TM" else DATE_FIELDS
        self.mem = DeviceMemory(devices, device_sizes)
        self.choices = dict(DEFAULTS)
        self.choices.update(choices or {})
        self.failed = False   # whether the last evaluation turned SM709 on

    # -- helpers -----------------------------------------------------------------------
    def _error(self) -> bool:
        self.failed = True
        # "SM709 turns on after the instruction is executed and the operation result
        # will be non-continuity."  "Once SM709 turns on, the on state is held until the
        # CPU module is powered off or reset."  -> only ever set here, never cleared.
        self.mem.write(SM709, True)
        return False

    def _out_of_range(self, words, selected_only_bits) -> bool:
        for offset, _name, lo, hi, bit in self.fields:
            if selected_only_bits is not None and not (selected_only_bits >> bit) & 1:
                continue
            # (s1), (s2): "16-bit signed binary"
            if not lo <= to_signed16(words[offset]) <= hi:
                return True
        return False

    def _compare(self, s1, s2, s3) -> int:
        """-1/0/1: field-by-field, most significant selected field first."""
        for offset, _name, _lo, _hi, bit in self.fields:
            if not (s3 >> bit) & 1:
                continue
            a, b = to_signed16(s1[offset]), to_signed16(s2[offset])
            if a != b:
                return -1 if a < b else 1
        return 0

    # -- the comparison itself (the "contact") ------------------------------------------
    def evaluate(self, condition: str, operands: dict, clock: dict | None) -> bool:
        mem = self.mem
        s1_dev = operands["s1"]["device"]
        s2_dev = operands["s2"]["device"]
        s3_op = operands["s3"]
        s3 = (s3_op["constant"] if "constant" in s3_op else mem.read(s3_op["device"])) & 0xFFFF

        # "(5) When 1 is set to the 15 bit, the data in the device specified by (s1) is
        # compared with the current time ... The time data in the device specified by
        # (s2) is regarded as dummy data and ignored."
        use_clock = bool(s3 & 0x8000)

        # "(4) Set 0. If a value other than 0 is set, the operation result will be
        # non-continuity."  (bits 3 to 14)
        # "When 0 is set to the 0 to 2 bits, the time data ... are not compared."
        # Table: "Other than 0001H to 0007H, 8001H to 8007H  None ... (The operation
        # result will be non-continuity.)"
        s3_valid = (s3 & 0x7FF8) == 0 and (s3 & 0x0007) != 0

        # "If the device areas specified by (s1) to (s1)+2 or (s2) to (s2)+2 exceed the
        # corresponding device range, SM709 turns on ... and the operation result will be
        # non-continuity as well."
        s2_checked = (not use_clock) or self.choices["FX5-CLOCK-S2-DEVICE-RANGE"] == "checked"
        if not mem.block_in_range(s1_dev, 3) or (s2_checked and not mem.block_in_range(s2_dev, 3)):
            # An invalid (s3) as well: which rule decides is FX5-INVALID-S3-DEVICE-RANGE.
            if not s3_valid and self.choices["FX5-INVALID-S3-DEVICE-RANGE"] == "s3-first":
                return False
            return self._error()

        s1 = mem.read_block(s1_dev, 3)
        if use_clock:
            s2 = [clock[name] for _o, name, *_ in self.fields]   # the current time/date
        else:
            s2 = mem.read_block(s2_dev, 3)

        # "If the comparison target data in the device are not recognized as time data,
        # SM709 turns on after the instruction is executed and the operation result will
        # be non-continuity."  Which words are "comparison target data" is
        # interpretation FX5-SM709-SCOPE.
        if self.choices["FX5-SM709-SCOPE"] == "all-words":
            if self._out_of_range(s1, None):
                return self._error()
            if not use_clock and self._out_of_range(s2, None):
                return self._error()
            if not s3_valid:
                return False
        elif self.choices["FX5-SM709-SCOPE"] == "compared-operands":
            # The operands are "comparison target data" as a whole, but only when the
            # table says they "are compared": not for a selector that compares nothing.
            if not s3_valid:
                return False
            if self._out_of_range(s1, None) or (not use_clock and self._out_of_range(s2, None)):
                return self._error()
        else:  # selected-fields: a masked word is not comparison target data
            if not s3_valid:
                return False
            if self._out_of_range(s1, s3) or (not use_clock and self._out_of_range(s2, s3)):
                return self._error()
        # Date page: "Even if the data are not recognized as date data, SM709 does not
        # turn on if the data are within the setting range." -> 02/30 is compared as is.

        return CONDITIONS[condition](self._compare(s1, s2, s3))

    def execute(self, instruction: str, operands: dict, step: dict) -> bool:
        """One scan of one LD/AND/OR contact; returns the logic state after it."""
        form, condition = parse_mnemonic(instruction, self.kind)
        clock = step.get("clock")
        if form == "LD":
            return self.evaluate(condition, operands, clock)
        rlo = bool(step["rlo_in"])
        logic = self.choices["FX5-AND-OR-WHEN-OFF"]
        # "(Devices are used as a normally open contact.)"  The MELSEC iQ-R Programming Manual
        # (processing-time tables): "an AND/OR comparison is not executed while the preceding
        # logic is off".
        if form == "AND":
            if not rlo and logic in ("and-skipped", "short-circuit"):
                return False
            contact = self.evaluate(condition, operands, clock)   # executed: may set SM709
            return rlo and contact
        # OR
        if rlo and logic == "short-circuit":
            return True
        self.failed = False
        contact = self.evaluate(condition, operands, clock)
        # "SM709 turns on ... and the operation result will be non-continuity":
        # a non-conductive contact in parallel (contact-off), or the rung's result
        # itself off (FX5-OR-ON-ERROR=result-off).
        if self.failed and self.choices["FX5-OR-ON-ERROR"] == "result-off":
            return False
        return rlo or contact


# Fx5Compare's name until 0.3.0, deprecated until 0.4.0, with a DeprecationWarning.
if TYPE_CHECKING:
    FX5CompareMachine = Fx5Compare
__getattr__ = old_names(__name__, {"FX5CompareMachine": "Fx5Compare"})
