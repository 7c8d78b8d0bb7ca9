"""IDEC FC6A MICROSmart: HOUR (hour meter).

Written from the manual page fc6a-hour-meter-HOUR.txt.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from plcvec_verify._renamed import old_names

from .machine import DeviceMemory, split_address

ALTERNATIVES = {
    "HOUR-OUTPUT-OFF": ("latched", "recompared"),
    "HOUR-INPUT-OFF": ("hold", "reset", "hold-drop-fraction"),
    "HOUR-PRESET-ZERO": ("immediate", "never"),
    "HOUR-FIRST-SCAN": ("counts", "from-next-scan", "after-cpu-start"),
    "HOUR-PRESET-CHECK": ("input-on", "every-execution"),
    "HOUR-M8004-OFF": ("never", "valid-preset"),
    "HOUR-D1-OUT-OF-RANGE": ("as-seconds", "error", "as-seconds-if-added", "by-field", "undefined"),
    "HOUR-WRAP-REACH": ("after-wrap", "before-wrap"),
    "HOUR-M8004-REPEAT": ("every-check", "once"),
    "HOUR-D2-SPECIAL": ("accepted", "error", "undefined"),
    "HOUR-S1-CONSTANT-RANGE": ("error", "as-is", "low-16-bits", "undefined"),
}

DEFAULTS = {
    "HOUR-OUTPUT-OFF": "latched",     # or "recompared"
    "HOUR-INPUT-OFF": "hold",         # or "reset", "hold-drop-fraction"
    "HOUR-PRESET-ZERO": "immediate",  # or "never"
    "HOUR-FIRST-SCAN": "counts",      # or "from-next-scan", "after-cpu-start"
    "HOUR-PRESET-CHECK": "input-on",  # or "every-execution"
    "HOUR-M8004-OFF": "never",        # or "valid-preset"
    "HOUR-D1-OUT-OF-RANGE": "as-seconds",  # or "error", "as-seconds-if-added", "by-field", "undefined"
    "HOUR-WRAP-REACH": "after-wrap",  # or "before-wrap"
    "HOUR-M8004-REPEAT": "every-check",  # or "once"
    "HOUR-D2-SPECIAL": "accepted",    # or "error", "undefined"
    "HOUR-S1-CONSTANT-RANGE": "error",  # or "as-is", "low-16-bits", "undefined"
}

ERROR_FLAG = "M8004"
# "the value returns to 0 hours 0 minutes 0 seconds" after "65,535 hours 59 minutes 59 seconds"
CYCLE = 65536 * 3600
# "Special internal relays cannot be designated as destination device D2": the FC6A's special
# internal relays are M8000 onwards (M8004, the error relay, is one).
SPECIAL_RELAYS = ("M", 8000)


def to_seconds(hms) -> int:
    h, m, s = hms
    return h * 3600 + m * 60 + s


def from_seconds(total: int):
    h, rest = divmod(total, 3600)
    m, s = divmod(rest, 60)
    return [h, m, s]


def is_special_relay(device: str) -> bool:
    kind, number = split_address(device)
    return kind == SPECIAL_RELAYS[0] and number is not None and number >= SPECIAL_RELAYS[1]


def tick(hms):
    """One second more on a D1 whose words count each on their own (HOUR-D1-OUT-OF-RANGE=by-field):
    [h, m, s] after it, and whether the hour went from 65535 to 0."""
    h, m, s = hms
    s = (s + 1) & 0xFFFF
    if s == 60:
        s = 0
        m = (m + 1) & 0xFFFF
        if m == 60:
            m = 0
            h = (h + 1) & 0xFFFF
            return [h, m, s], h == 0
    return [h, m, s], False


class Fc6aHourMeter:
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
        self.first_scan = True      # the first execution since the CPU started
        self.last_check_valid = True   # for HOUR-M8004-REPEAT=once: no check yet

    def preset(self, operand: dict):
        # "When source device S1 is designated by a constant, the preset value can be 0
        # through 65,535 in hours, then minutes and seconds are set to 0."
        if "constant" in operand:
            hours = operand["constant"]
            if not 0 <= hours <= 65535 and self.choices["HOUR-S1-CONSTANT-RANGE"] == "low-16-bits":
                hours &= 0xFFFF
            return [hours, 0, 0]
        # "Source device S1, when designated by a data register, ... occupy 3 consecutive
        # data registers ... to store hour, minute, and second data."
        return self.mem.read_block(operand["device"], 3)

    def preset_valid(self, p) -> bool:
        # "Hour data can be 0 through 65,535. Minute and second data can be 0 through 59."
        # Only a constant can hold an hour outside 0..65535: HOUR-S1-CONSTANT-RANGE=as-is takes it.
        hour_ok = 0 <= p[0] <= 65535 or self.choices["HOUR-S1-CONSTANT-RANGE"] == "as-is"
        return hour_ok and 0 <= p[1] <= 59 and 0 <= p[2] <= 59

    @staticmethod
    def reached(total: int, preset: int) -> bool:
        # "When the measured input ON duration value in destination device D1 reaches the
        # preset value designated by source device S1, the comparison output ... turns on."
        return total >= preset

    def forbidden(self, operands: dict) -> bool:
        """A program the page forbids, whose reading is `undefined`: the instruction does nothing we judge."""
        if is_special_relay(operands["D2"]["device"]) and self.choices["HOUR-D2-SPECIAL"] == "undefined":
            return True
        hours = operands["S1"].get("constant", 0)
        return not 0 <= hours <= 65535 and self.choices["HOUR-S1-CONSTANT-RANGE"] == "undefined"

    def check_preset(self, operands: dict, d2):
        """Read and check S1: the preset, or None when it is invalid (M8004 on, D2 off)."""
        p = self.preset(operands["S1"])
        if not self.preset_valid(p):
            # "When any of the hour, minute, or second data of source device S1 exceeds the
            # valid range, a user program execution error will result, turning on special
            # internal relay M8004 ... but the input ON duration is measured."
            # HOUR-M8004-REPEAT=once: only when the check before found S1 valid.
            if self.choices["HOUR-M8004-REPEAT"] == "every-check" or self.last_check_valid:
                self.mem.write(ERROR_FLAG, True)
            self.last_check_valid = False
            # "... is changed to an invalid value after the comparison output has turned
            # on, the comparison output is turned off."
            if d2 is not None:
                self.mem.write(d2, False)
            return None
        self.last_check_valid = True
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
        first, self.first_scan = self.first_scan, False
        if self.forbidden(operands):
            return None
        # "Special internal relays cannot be designated as destination device D2":
        # HOUR-D2-SPECIAL=error never writes such a D2 and reports an error instead.
        d2_error = is_special_relay(d2) and self.choices["HOUR-D2-SPECIAL"] == "error"
        if d2_error:
            d2 = None

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

        self.measure_and_compare(operands, d1, d2, step, turned_on, first)
        if d2_error:
            mem.write(ERROR_FLAG, True)
        return None

    def measure_and_compare(self, operands, d1, d2, step, turned_on, first):
        mem = self.mem
        # "Minute and second data can be 0 through 59."  A D1 the program set outside
        # that is read as HOUR-D1-OUT-OF-RANGE says.
        held = mem.read_block(d1, 3)
        reading = self.choices["HOUR-D1-OUT-OF-RANGE"] if held[1] > 59 or held[2] > 59 else "as-seconds"
        if reading == "undefined":
            return
        if reading == "error":
            mem.write(ERROR_FLAG, True)
            return

        # Measure: the elapsed time since the previous execution is ON time; at the
        # scan the input turns on, only under HOUR-FIRST-SCAN=counts (and after-cpu-start,
        # but for the first scan since the CPU started).
        first_scan = self.choices["HOUR-FIRST-SCAN"]
        skip = (turned_on and first_scan == "from-next-scan") or (first and first_scan == "after-cpu-start")
        if not skip:
            self.fraction_ms += int(step["elapsed_ms"])
        whole, self.fraction_ms = divmod(self.fraction_ms, 1000)
        if reading == "by-field":
            hms, wraps = held, 0
            for _ in range(whole):
                hms, wrapped = tick(hms)
                wraps += wrapped
        else:
            total = to_seconds(held) + whole
            wraps = total // self.CYCLE
            # "When the measured input ON duration value exceeds 65,535 hours 59 minutes 59
            # seconds, the value returns to 0 hours 0 minutes 0 seconds to repeat another
            # measuring cycle, with the comparison output remaining on."
            hms = from_seconds(total % self.CYCLE)
        if whole or reading != "as-seconds-if-added":
            mem.write_block(d1, hms)

        p = self.check_preset(operands, d2)
        if p is None:
            return
        # HOUR-WRAP-REACH=before-wrap compares the count as it was before it wrapped.
        before_wrap = wraps and self.choices["HOUR-WRAP-REACH"] == "before-wrap"
        counted = [hms[0] + (65536 * wraps if before_wrap else 0), hms[1], hms[2]]
        if reading == "by-field":   # hour, then minute, then second
            reached = counted >= list(p)
        else:
            reached = self.reached(to_seconds(counted), to_seconds(p))
        if to_seconds(p) == 0 and self.choices["HOUR-PRESET-ZERO"] == "never":
            reached = False
        if d2 is not None:
            self.set_output(d2, reached, bool(wraps), bool(before_wrap))

    def set_output(self, d2, reached, wrapped_now, compared_first):
        mem = self.mem
        # "When the D1 value reaches the S1 value, an output or internal relay assigned by
        # destination device D2 is turned on."
        if self.choices["HOUR-OUTPUT-OFF"] == "latched":
            if reached:
                mem.write(d2, True)
            return
        # recompared: D2 = D1 >= S1, except that it stays on across a wrap
        if wrapped_now and not compared_first and mem.read(d2):
            self.wrapped = True
        if reached:
            self.wrapped = False
        mem.write(d2, bool(reached or (self.wrapped and mem.read(d2))))
        if wrapped_now and compared_first and mem.read(d2):
            self.wrapped = True     # on when D1 wrapped, after the comparison


# Fc6aHourMeter's name until 0.3.0, deprecated until 0.4.0, with a DeprecationWarning.
if TYPE_CHECKING:
    HourMeter = Fc6aHourMeter
__getattr__ = old_names(__name__, {"HourMeter": "Fc6aHourMeter"})
