"""IDEC FC6A MICROSmart: HOUR (hour meter).

Written from the manual page fc6a-hour-meter-HOUR.txt.
"""
from __future__ import annotations

from .machine import DeviceMemory

ALTERNATIVES = {
    "HOUR-OUTPUT-OFF": ("latched", "recompared"),
    "HOUR-INPUT-OFF": ("hold", "reset", "hold-drop-fraction"),
    "HOUR-PRESET-ZERO": ("immediate", "never"),
    "HOUR-FIRST-SCAN": ("counts", "from-next-scan"),
    "HOUR-PRESET-CHECK": ("input-on", "every-execution"),
    "HOUR-M8004-OFF": ("never", "valid-preset"),
    "HOUR-D1-OUT-OF-RANGE": ("as-seconds", "error"),
}

DEFAULTS = {
    "HOUR-OUTPUT-OFF": "latched",     # or "recompared"
    "HOUR-INPUT-OFF": "hold",         # or "reset", "hold-drop-fraction"
    "HOUR-PRESET-ZERO": "immediate",  # or "never"
    "HOUR-FIRST-SCAN": "counts",      # or "from-next-scan"
    "HOUR-PRESET-CHECK": "input-on",  # or "every-execution"
    "HOUR-M8004-OFF": "never",        # or "valid-preset"
    "HOUR-D1-OUT-OF-RANGE": "as-seconds",  # or "error"
}

ERROR_FLAG = "M8004"
# "the value returns to 0 hours 0 minutes 0 seconds" after "65,535 hours 59 minutes 59 seconds"
CYCLE = 65536 * 3600


def to_seconds(hms) -> int:
    h, m, s = hms
    return h * 3600 + m * 60 + s


def from_seconds(total: int):
    h, rest = divmod(total, 3600)
    m, s = divmod(rest, 60)
    return [h, m, s]


class HourMeter:
    """An FC6A CPU executing one HOUR instruction per scan.

    The fraction of a second already measured lives in this object (on the CPU it
    is in the system work area D3, D3+1, whose contents vectors never compare).
    """

    CONTACT = False
    CYCLE = CYCLE   # a class attribute, so that a subclass (a mutant) can change it

    def __init__(self, devices: dict, device_sizes: dict, choices: dict | None = None):
        self.mem = DeviceMemory(devices, device_sizes)
        self.choices = dict(DEFAULTS)
        self.choices.update(choices or {})
        self.fraction_ms = 0
        self.wrapped = False   # for "recompared": D2 stays on across a wrap
        self.input_was_on = False   # the input before the first scan counts as off

    def preset(self, operand: dict):
        # "When source device S1 is designated by a constant, the preset value can be 0
        # through 65,535 in hours, then minutes and seconds are set to 0."
        if "constant" in operand:
            return [operand["constant"] & 0xFFFF, 0, 0]
        # "Source device S1, when designated by a data register, ... occupy 3 consecutive
        # data registers ... to store hour, minute, and second data."
        return self.mem.read_block(operand["device"], 3)

    @staticmethod
    def preset_valid(p) -> bool:
        # "Hour data can be 0 through 65,535. Minute and second data can be 0 through 59."
        return 0 <= p[0] <= 65535 and 0 <= p[1] <= 59 and 0 <= p[2] <= 59

    @staticmethod
    def reached(total: int, preset: int) -> bool:
        # "When the measured input ON duration value in destination device D1 reaches the
        # preset value designated by source device S1, the comparison output ... turns on."
        return total >= preset

    def check_preset(self, operands: dict, d2: str):
        """Read and check S1: the preset, or None when it is invalid (M8004 on, D2 off)."""
        p = self.preset(operands["S1"])
        if not self.preset_valid(p):
            # "When any of the hour, minute, or second data of source device S1 exceeds the
            # valid range, a user program execution error will result, turning on special
            # internal relay M8004 ... but the input ON duration is measured."
            # "... is changed to an invalid value after the comparison output has turned
            # on, the comparison output is turned off."
            self.mem.write(ERROR_FLAG, True)
            self.mem.write(d2, False)
            return None
        # The page never says M8004 turns off; HOUR-M8004-OFF=valid-preset does.
        if self.choices["HOUR-M8004-OFF"] == "valid-preset":
            self.mem.write(ERROR_FLAG, False)
        return p

    def execute(self, instruction: str, operands: dict, step: dict):
        if instruction != "HOUR":
            raise ValueError(instruction)
        mem = self.mem
        d1 = operands["D1"]["device"]
        d2 = operands["D2"]["device"]
        on = bool(step["input"])
        turned_on = on and not self.input_was_on
        self.input_was_on = on

        if not on:
            # "While input is on, the ON duration of the input is measured."  Off: HOUR-INPUT-OFF.
            if self.choices["HOUR-INPUT-OFF"] == "reset":
                mem.write_block(d1, [0, 0, 0])
                self.fraction_ms = 0
            elif self.choices["HOUR-INPUT-OFF"] == "hold-drop-fraction":
                self.fraction_ms = 0       # D1 kept; the part of a second is lost
            # HOUR-PRESET-CHECK=every-execution: the preset is checked with the input off too.
            if self.choices["HOUR-PRESET-CHECK"] == "every-execution":
                self.check_preset(operands, d2)
            return None

        # "Minute and second data can be 0 through 59."  A D1 the program set outside
        # that is counted as seconds and carried back into range (HOUR-D1-OUT-OF-RANGE
        # as-seconds), or is an error that stops this execution (error).
        held = mem.read_block(d1, 3)
        if (held[1] > 59 or held[2] > 59) and self.choices["HOUR-D1-OUT-OF-RANGE"] == "error":
            mem.write(ERROR_FLAG, True)
            return None

        # Measure: the elapsed time since the previous execution is ON time; at the
        # scan the input turns on, only under HOUR-FIRST-SCAN=counts.
        if not (turned_on and self.choices["HOUR-FIRST-SCAN"] == "from-next-scan"):
            self.fraction_ms += int(step["elapsed_ms"])
        whole, self.fraction_ms = divmod(self.fraction_ms, 1000)
        total = to_seconds(mem.read_block(d1, 3)) + whole
        wrapped_now = total >= self.CYCLE
        # "When the measured input ON duration value exceeds 65,535 hours 59 minutes 59
        # seconds, the value returns to 0 hours 0 minutes 0 seconds to repeat another
        # measuring cycle, with the comparison output remaining on."
        total %= self.CYCLE
        mem.write_block(d1, from_seconds(total))

        p = self.check_preset(operands, d2)
        if p is None:
            return None

        preset = to_seconds(p)
        reached = self.reached(total, preset)
        if preset == 0 and self.choices["HOUR-PRESET-ZERO"] == "never":
            reached = False
        # "When the D1 value reaches the S1 value, an output or internal relay assigned by
        # destination device D2 is turned on."
        if self.choices["HOUR-OUTPUT-OFF"] == "latched":
            if reached:
                mem.write(d2, True)
        else:  # recompared: D2 = D1 >= S1, except that it stays on across a wrap
            if wrapped_now and mem.read(d2):
                self.wrapped = True
            if reached:
                self.wrapped = False
            mem.write(d2, bool(reached or (self.wrapped and mem.read(d2))))
        return None
