"""Mitsubishi MELSEC iQ-F FX5: TADD / TADDP (adding clock data).

Written from the manual page fx5-time-add-TADD.txt.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from plcvec_verify._renamed import old_names

from .machine import DeviceMemory, to_signed16, to_word

ALTERNATIVES = {
    "TADD-FLAGS-OFF": ("written-each-execution", "set-only"),
    "TADD-EXACT-24": ("carry-at-24", "carry-above-24"),
    "TADD-ON-ERROR": ("not-executed", "computed"),
    "TADD-ERROR-ORDER": ("device-range-first", "field-range-first"),
    "TADD-OVERLAP": ("sources-first", "second-first", "hour-first"),
}

DEFAULTS = {
    "TADD-FLAGS-OFF": "written-each-execution",   # or "set-only"
    "TADD-EXACT-24": "carry-at-24",               # or "carry-above-24"
    "TADD-ON-ERROR": "not-executed",              # or "computed"
    "TADD-ERROR-ORDER": "device-range-first",     # or "field-range-first"
    "TADD-OVERLAP": "sources-first",              # or "second-first", "hour-first"
}

DAY = 24 * 3600

# "SM700 Carry ... SM8020 Zero ... SM8022 Carry"
CARRY_FLAGS = ("SM700", "SM8022")
ZERO_FLAG = "SM8020"
# "Error code (SD0/SD8067)"
ERROR_REGISTERS = ("SD0", "SD8067")
ERR_DEVICE_RANGE = 0x2820
ERR_VALUE_RANGE = 0x3405

# "(s1) hour (0 to 23) ... minute (0 to 59) ... second (0 to 59)"
RANGES = [(0, 23), (0, 59), (0, 59)]
# Seconds in one hour, minute, second; and what each word counts up to before it carries.
WEIGHTS = (3600, 60, 1)
RADIX = (24, 60, 60)


class Fx5TimeAdd:
    """An FX5 CPU executing TADD or TADDP once per scan."""

    CONTACT = False
    # Class attributes, so that a subclass (a mutant) can change one of them.
    CARRY_FLAGS = CARRY_FLAGS
    RANGES = RANGES

    def __init__(self, devices: dict, device_sizes: dict, choices: dict | None = None):
        self.mem = DeviceMemory(devices, device_sizes)
        self.choices = dict(DEFAULTS)
        self.choices.update(choices or {})
        self.previous_en = False     # TADDP: the state before the first scan is off

    def _error(self, code: int):
        for reg in ERROR_REGISTERS:
            self.mem.write(reg, code)

    def _set_flags(self, carry: bool, zero: bool):
        if self.choices["TADD-FLAGS-OFF"] == "written-each-execution":
            for f in self.CARRY_FLAGS:
                self.mem.write(f, carry)
            self.mem.write(ZERO_FLAG, zero)
        else:  # set-only: an execution only ever turns a flag on
            if carry:
                for f in self.CARRY_FLAGS:
                    self.mem.write(f, True)
            if zero:
                self.mem.write(ZERO_FLAG, True)

    def wrap(self, total: int):
        """The sum in seconds -> (the result in seconds, the carry)."""
        # "If the sum of two values exceeds 24:00:00, the carry flag turns on, and the
        # result will be the sum minus 24:00:00."  But: "If 1 second is added to 23:59:59,
        # the result will be 0:00:00. This turns on both the carry flag and the zero flag."
        # and the flag table: "If the result exceeds ... 23:59:59".  -> TADD-EXACT-24.
        if self.choices["TADD-EXACT-24"] == "carry-at-24":
            carry = total >= DAY
        else:
            carry = total > DAY
        return total % DAY, carry

    def add(self, operands: dict):
        """One execution of the addition."""
        mem = self.mem
        s1_dev, s2_dev, d_dev = (operands[k]["device"] for k in ("s1", "s2", "d"))

        # "2820H The device range specified by (s1), (s2), and (d) exceeds the
        # corresponding device range."
        # ("These instructions occupy three points for each of three devices")
        device_bad = not all(mem.block_in_range(dev, 3) for dev in (s1_dev, s2_dev, d_dev))

        # "3405H Any of values specified by (s1) and (s2) is outside the following range.
        # 0 to 23 / ... (s1)+1, (s2)+1, (s1)+2, and (s2)+2 ... 0 to 59"
        # Only an operand whose three words exist can be read and checked.
        def out_of_range(dev):
            if not mem.block_in_range(dev, 3):
                return False
            data = [to_signed16(w) for w in mem.read_block(dev, 3)]
            return any(not lo <= v <= hi for v, (lo, hi) in zip(data, self.RANGES))
        value_bad = out_of_range(s1_dev) or out_of_range(s2_dev)

        if device_bad:
            # Both conditions: TADD-ERROR-ORDER says which code; nothing else is
            # written, since an operand past its device cannot be read or written.
            if value_bad and self.choices["TADD-ERROR-ORDER"] == "field-range-first":
                self._error(ERR_VALUE_RANGE)
            else:
                self._error(ERR_DEVICE_RANGE)
            return

        if value_bad:
            self._error(ERR_VALUE_RANGE)
            if self.choices["TADD-ON-ERROR"] == "not-executed":
                return

        total = self.sum_seconds(s1_dev, s2_dev, d_dev)
        result, carry = self.wrap(total)
        h, rest = divmod(result, 3600)
        m, s = divmod(rest, 60)
        mem.write_block(d_dev, [h, m, s])
        # "If the result is 0 (0:00:00), the zero flag turns on."
        self._set_flags(carry, result == 0)

    def sum_seconds(self, s1_dev: str, s2_dev: str, d_dev: str) -> int:
        """(s1) + (s2) in seconds, read in the order TADD-OVERLAP says.

        The order shows only when (d) overlaps (s1) or (s2) at another offset ((d) = (s1)+1, ...):
        then a source word read after a word of (d) was written holds what was written.
        """
        mem = self.mem

        def word(dev, k):
            return to_signed16(mem.read(mem.address(dev, k)))

        order = self.choices["TADD-OVERLAP"]
        if order == "sources-first":
            s1 = [word(s1_dev, k) for k in range(3)]
            s2 = [word(s2_dev, k) for k in range(3)]
            return sum((a + b) * w for a, b, w in zip(s1, s2, WEIGHTS))
        total = 0
        if order == "second-first":
            # Second, minute, hour: each word of (d) gets its digit as soon as it is known.
            carry = 0
            for k in (2, 1, 0):
                a, b = word(s1_dev, k), word(s2_dev, k)
                total += (a + b) * WEIGHTS[k]
                carry, digit = divmod(a + b + carry, RADIX[k])
                mem.write(mem.address(d_dev, k), to_word(digit))
            return total
        # hour-first: the plain sum of each pair of words into (d), hour to second; the
        # carries are settled afterwards, from the three sums.
        for k in (0, 1, 2):
            a, b = word(s1_dev, k), word(s2_dev, k)
            total += (a + b) * WEIGHTS[k]
            mem.write(mem.address(d_dev, k), to_word(a + b))
        return total

    def execute(self, instruction: str, operands: dict, step: dict):
        en = bool(step["en"])
        if instruction == "TADD":
            run = en                              # every scan while EN is on
        elif instruction == "TADDP":
            run = en and not self.previous_en     # pulse: rising edge of EN only
        else:
            raise ValueError(instruction)
        self.previous_en = en
        if run:
            self.add(operands)
        return None


# Fx5TimeAdd's name until 0.3.0, deprecated until 0.4.0, with a DeprecationWarning.
if TYPE_CHECKING:
    TADDMachine = Fx5TimeAdd
__getattr__ = old_names(__name__, {"TADDMachine": "Fx5TimeAdd"})
