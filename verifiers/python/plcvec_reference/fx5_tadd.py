"""Mitsubishi MELSEC iQ-F FX5: TADD / TADDP (adding clock data).

Written from the manual page fx5-time-add-TADD.txt.
"""
from __future__ import annotations

from .machine import DeviceMemory, to_signed16

ALTERNATIVES = {
    "TADD-FLAGS-OFF": ("written-each-execution", "set-only"),
    "TADD-EXACT-24": ("carry-at-24", "carry-above-24"),
    "TADD-ON-ERROR": ("not-executed", "computed"),
    "TADD-ERROR-ORDER": ("device-range-first", "field-range-first"),
}

DEFAULTS = {
    "TADD-FLAGS-OFF": "written-each-execution",   # or "set-only"
    "TADD-EXACT-24": "carry-at-24",               # or "carry-above-24"
    "TADD-ON-ERROR": "not-executed",              # or "computed"
    "TADD-ERROR-ORDER": "device-range-first",     # or "field-range-first"
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


class TADDMachine:
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

        s1 = [to_signed16(w) for w in mem.read_block(s1_dev, 3)]
        s2 = [to_signed16(w) for w in mem.read_block(s2_dev, 3)]
        if value_bad:
            self._error(ERR_VALUE_RANGE)
            if self.choices["TADD-ON-ERROR"] == "not-executed":
                return

        total = (s1[0] + s2[0]) * 3600 + (s1[1] + s2[1]) * 60 + (s1[2] + s2[2])
        result, carry = self.wrap(total)
        h, rest = divmod(result, 3600)
        m, s = divmod(rest, 60)
        mem.write_block(d_dev, [h, m, s])
        # "If the result is 0 (0:00:00), the zero flag turns on."
        self._set_flags(carry, result == 0)

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
