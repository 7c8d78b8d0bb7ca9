"""Omron SYSMAC CP1E: LD/AND/OR =DT, <>DT, <DT, <=DT, >DT, >=DT (time comparison).

Written from the manual page cp1e-time-compare-DT.txt (W483 p. 2-93).
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from plcvec_verify._renamed import old_names

from .machine import DeviceMemory, operand_value

ALTERNATIVES = {
    "CP1E-NON-BCD": ("error", "raw-bytes"),
    "CP1E-OUT-OF-RANGE": ("compared", "error"),
    "CP1E-ALL-MASKED": ("error", "equal", "not-compared"),
    "CP1E-C-HIGH-BITS": ("ignored", "error"),
    "CP1E-AND-OR-WHEN-OFF": ("always-executed", "and-skipped", "short-circuit"),
    "CP1E-ER-FLAG": ("reflects-each-execution", "held"),
    "CP1E-ERROR-FLAGS": ("kept", "off"),
    "CP1E-PAST-AREA-END": ("error", "program-error"),
}

DEFAULTS = {
    "CP1E-NON-BCD": "error",                 # or "raw-bytes"
    "CP1E-OUT-OF-RANGE": "compared",         # or "error"
    "CP1E-ALL-MASKED": "error",              # or "equal", "not-compared"
    "CP1E-C-HIGH-BITS": "ignored",           # or "error"
    "CP1E-AND-OR-WHEN-OFF": "always-executed",  # or "and-skipped", "short-circuit"
    "CP1E-ER-FLAG": "reflects-each-execution",  # or "held"
    "CP1E-ERROR-FLAGS": "kept",              # or "off"
    "CP1E-PAST-AREA-END": "error",           # or "program-error"
}

ERROR_FLAG = "P_ER"
FLAGS = {"=": "P_EQ", "<>": "P_NE", "<": "P_LT", "<=": "P_LE", ">": "P_GT", ">=": "P_GE"}

# Calendar/Clock Area layout, most significant field first:
# (word offset, byte: 0 = bits 00-07, 1 = bits 08-15, name, min, max, C mask bit)
# "A351.00 to A351.07 Second (00 to 59, BCD)  A351.08 to A351.15 Minute (00 to 59, BCD)
#  A352.00 to A352.07 Hour (00 to 23, BCD)    A352.08 to A352.15 Day of month (01 to 31, BCD)
#  A353.00 to A353.07 Month (01 to 12, BCD)   A353.08 to A353.15 Year (00 to 99, BCD)"
# "Bits 00 to 05 of C mask the seconds, minutes, hours, day, month, and year, respectively."
FIELDS = [
    (2, 1, "year", 0, 99, 5),
    (2, 0, "month", 1, 12, 4),
    (1, 1, "day", 1, 31, 3),
    (1, 0, "hour", 0, 23, 2),
    (0, 1, "minute", 0, 59, 1),
    (0, 0, "second", 0, 59, 0),
]

# Flag table: rows S1 = S2, S1 > S2, S1 < S2.
FLAG_TABLE = {
    0: {"=": True, "<>": False, "<": False, "<=": True, ">": False, ">=": True},
    1: {"=": False, "<>": True, "<": False, "<=": False, ">": True, ">=": True},
    -1: {"=": False, "<>": True, "<": True, "<=": True, ">": False, ">=": False},
}


def parse_mnemonic(instruction: str):
    """'AND <=DT' -> ('AND', '<=')."""
    form, symbol = instruction.split(" ", 1)
    if form not in ("LD", "AND", "OR") or not symbol.endswith("DT"):
        raise ValueError(f"not a CP1E time comparison: {instruction}")
    return form, symbol[:-2]


def field_byte(words, offset, byte) -> int:
    return (words[offset] >> (8 * byte)) & 0xFF


def is_bcd(b: int) -> bool:
    return (b >> 4) <= 9 and (b & 0xF) <= 9


def bcd_value(b: int) -> int:
    return (b >> 4) * 10 + (b & 0xF)


class Cp1eTimeCompare:
    """A CP1E CPU executing one time-comparison instruction per scan.

    P_ER is an Omron *condition flag*: it reflects the result of the instruction just
    executed (CP1L Getting Started Guide W07E, Condition Flags: "Condition flags are
    used to reflect the processing results during or after the execution of
    instructions"; CJ2 Software User's Manual 6-21: "the Error Flag, Carry Flag, and
    other flags that indicate the results of instruction execution"; Omron flag tables
    read "ON if ... OFF in all other cases").  spec/cp1e-time-compare.yaml agrees:
    validity.error.latch: false.  So an execution that ends without error turns P_ER
    OFF. The other reading, that only an error ever writes P_ER, is the alternative
    "held" of interpretation CP1E-ER-FLAG.
    """

    CONTACT = True
    # Class attributes, so that a subclass (a mutant) can change one of them.
    FIELDS = FIELDS
    is_bcd = staticmethod(is_bcd)

    def __init__(self, devices: dict, device_sizes: dict, choices: dict | None = None):
        self.mem = DeviceMemory(devices, device_sizes)
        self.choices = dict(DEFAULTS)
        self.choices.update(choices or {})

    def _error(self) -> bool:
        # Error: P_ER on, execution condition OFF.  The flag table has no row for an
        # execution without a comparison result: the six flags keep their values, or
        # (CP1E-ERROR-FLAGS=off) are all written OFF.
        self.mem.write(ERROR_FLAG, True)
        if self.choices["CP1E-ERROR-FLAGS"] == "off":
            for flag in FLAGS.values():
                self.mem.write(flag, False)
        return False

    def reflect_flags(self, order: int):
        # "the result of a time comparison instruction is reflected in the arithmetic
        # flags (=, <>, <, <=, >, >=)."
        for symbol, flag in FLAGS.items():
            self.mem.write(flag, FLAG_TABLE[order][symbol])

    def evaluate(self, condition: str, operands: dict) -> bool:
        mem = self.mem
        # "S1 to S1+2", "S2 to S2+2": three words each. One that is past the end of the
        # data area (S1 in one of the last two words of D) is CP1E-PAST-AREA-END, found
        # before C or the data are looked at.
        if not (mem.block_in_range(operands["S1"]["device"], 3) and mem.block_in_range(operands["S2"]["device"], 3)):
            if self.choices["CP1E-PAST-AREA-END"] == "program-error":
                return False          # not executed: writes nothing, OFF execution condition
            return self._error()
        s1 = mem.read_block(operands["S1"]["device"], 3)
        s2 = mem.read_block(operands["S2"]["device"], 3)
        c = operand_value(mem, operands["C"])

        # Bits 06 to 15 of C: not described by the manual (CP1E-C-HIGH-BITS).
        if c & 0xFFC0 and self.choices["CP1E-C-HIGH-BITS"] == "error":
            return self._error()

        # "To mask a time value, set the corresponding bit in the control word (C) to 1."
        # "compares the unmasked values (corresponding bit of C set to 0)"
        unmasked = [f for f in self.FIELDS if not (c >> f[5]) & 1]
        if not unmasked and self.choices["CP1E-ALL-MASKED"] == "error":
            return self._error()
        if not unmasked and self.choices["CP1E-ALL-MASKED"] == "not-compared":
            # Nothing compared, no result: OFF, flags untouched, no error.
            if self.choices["CP1E-ER-FLAG"] == "reflects-each-execution":
                mem.write(ERROR_FLAG, False)
            return False

        order = 0
        for offset, byte, _name, lo, hi, _bit in unmasked:
            a, b = field_byte(s1, offset, byte), field_byte(s2, offset, byte)
            for raw in (a, b):
                if not self.is_bcd(raw):
                    # "Second (00 to 59, BCD)" ... (CP1E-NON-BCD)
                    if self.choices["CP1E-NON-BCD"] == "error":
                        return self._error()
                elif not lo <= bcd_value(raw) <= hi:
                    # (CP1E-OUT-OF-RANGE)
                    if self.choices["CP1E-OUT-OF-RANGE"] == "error":
                        return self._error()
            # "The time comparison instructions are limited to comparing 8-bit time
            # values."  For valid BCD the byte order is the numeric order; with
            # "raw-bytes" the bytes are compared as unsigned 8-bit values.
            if order == 0 and a != b:
                order = -1 if a < b else 1

        self.reflect_flags(order)
        if self.choices["CP1E-ER-FLAG"] == "reflects-each-execution":
            mem.write(ERROR_FLAG, False)     # executed without error
        return FLAG_TABLE[order][condition]

    def execute(self, instruction: str, operands: dict, step: dict) -> bool:
        form, condition = parse_mnemonic(instruction)
        # "The time comparison instructions are treated just like the LD, AND, and OR
        # instructions to control the execution of subsequent instructions."
        if form == "LD":
            return self.evaluate(condition, operands)
        rlo = bool(step["rlo_in"])
        if form == "AND":
            if not rlo and self.choices["CP1E-AND-OR-WHEN-OFF"] in ("and-skipped", "short-circuit"):
                return False
            contact = self.evaluate(condition, operands)
            return rlo and contact
        if rlo and self.choices["CP1E-AND-OR-WHEN-OFF"] == "short-circuit":
            return True
        contact = self.evaluate(condition, operands)
        return rlo or contact


# Cp1eTimeCompare's name until 0.3.0, deprecated until 0.4.0, with a DeprecationWarning.
if TYPE_CHECKING:
    CP1ETimeCompare = Cp1eTimeCompare
__getattr__ = old_names(__name__, {"CP1ETimeCompare": "Cp1eTimeCompare"})
