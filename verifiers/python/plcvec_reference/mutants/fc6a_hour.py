"""Mutants of the FC6A hour meter HOUR."""
from __future__ import annotations

from ..fc6a_hour import ERROR_FLAG, Fc6aHourMeter, to_seconds
from .registry import mutant

FAMILY = ("fc6a-hour-meter",)


@mutant("hour-output-above-preset", FAMILY,
        "D2 turns on only once D1 is past S1, not when 'the D1 value reaches the S1 value'.",
        exercises={"reach": ["at"]})
class OutputAbovePreset(Fc6aHourMeter):
    @staticmethod
    def reached(total, preset):
        return total > preset


@mutant("hour-drops-fraction", FAMILY,
        "Each scan's ON time is cut to whole seconds and the remainder thrown away, so many "
        "short scans never add up to the 'measured input ON duration'.")
class DropsFraction(Fc6aHourMeter):
    def execute(self, instruction, operands, step):
        super().execute(instruction, operands, step)
        self.fraction_ms = 0


@mutant("hour-wrap-early", FAMILY,
        "D1 returns to 0 when the hour reaches 65,535, not after it 'exceeds 65,535 hours "
        "59 minutes 59 seconds'.")
class WrapEarly(Fc6aHourMeter):
    CYCLE = Fc6aHourMeter.CYCLE - 3600


@mutant("hour-wrap-clears-d2", FAMILY,
        "When D1 returns to 0 hours 0 minutes 0 seconds D2 is turned off with it, instead of "
        "'with the comparison output remaining on'.",
        exercises={"wrap": ["yes"]})
class WrapClearsD2(Fc6aHourMeter):
    def execute(self, instruction, operands, step):
        d1 = operands["D1"]["device"]
        before = to_seconds(self.mem.read_block(d1, 3))
        super().execute(instruction, operands, step)
        # While the input is on D1 only goes down when it wraps.
        if step["input"] and to_seconds(self.mem.read_block(d1, 3)) < before:
            self.mem.write(operands["D2"]["device"], False)


class _OnInvalidPreset(Fc6aHourMeter):
    """Runs the reference, then undoes some of what it does when S1 is out of range."""

    def execute(self, instruction, operands, step):
        if not step["input"] or self.preset_valid(self.preset(operands["S1"])):
            return super().execute(instruction, operands, step)
        kept = self.keep(operands)
        super().execute(instruction, operands, step)
        self.restore(operands, kept)
        return None


@mutant("hour-invalid-preset-stops-measuring", FAMILY,
        "An out-of-range S1 cancels the execution and D1 stops, although the manual says "
        "'but the input ON duration is measured'.",
        exercises={"preset": ["*.above"]})
class InvalidPresetStopsMeasuring(_OnInvalidPreset):
    def keep(self, operands):
        return self.mem.read_block(operands["D1"]["device"], 3), self.fraction_ms

    def restore(self, operands, kept):
        d1, self.fraction_ms = kept
        self.mem.write_block(operands["D1"]["device"], d1)


@mutant("hour-invalid-preset-keeps-d2", FAMILY,
        "When S1 'is changed to an invalid value after the comparison output has turned on', "
        "D2 stays on instead of 'the comparison output is turned off'.",
        exercises={"preset": ["*.above"], "output-before": ["on"]})
class InvalidPresetKeepsD2(_OnInvalidPreset):
    def keep(self, operands):
        return self.mem.read(operands["D2"]["device"])

    def restore(self, operands, kept):
        self.mem.write(operands["D2"]["device"], kept)


@mutant("hour-measures-while-off", FAMILY,
        "The elapsed time is added to D1 while the input is off too, although 'While input is on, "
        "the ON duration of the input is measured'.",
        exercises={"input": ["off"]})
class MeasuresWhileOff(Fc6aHourMeter):
    def execute(self, instruction, operands, step):
        return super().execute(instruction, operands, dict(step, input=True))


@mutant("hour-constant-in-minutes", FAMILY,
        "A constant S1 is taken as minutes, not as 'the preset value ... in hours, then minutes and "
        "seconds are set to 0'.",
        exercises={"preset-operand": ["constant"]})
class ConstantInMinutes(Fc6aHourMeter):
    def preset(self, operand):
        if "constant" in operand:
            hours, minutes = divmod(operand["constant"] & 0xFFFF, 60)
            return [hours, minutes, 0]
        return super().preset(operand)


@mutant("hour-stops-when-output-on", FAMILY,
        "D1 stops once D2 is on, although 'As long as the input remains on, the measured input ON "
        "duration value continues to increase'.",
        exercises={"output-before": ["on"]})
class StopsWhenOutputOn(Fc6aHourMeter):
    def execute(self, instruction, operands, step):
        if step["input"] and self.mem.read(operands["D2"]["device"]):
            return super().execute(instruction, operands, dict(step, elapsed_ms=0))
        return super().execute(instruction, operands, step)


@mutant("hour-error-flag-cleared", FAMILY,
        "Every execution turns M8004 off before it runs, the input off included, as if the user "
        "program execution error flag reported only the latest execution; an invalid preset at an "
        "execution with the input on turns it on again.",
        exercises={"error-before": ["on"]})
class ErrorFlagCleared(Fc6aHourMeter):
    # Until 0.2.0 this mutant cleared M8004 only where the preset was valid and the input on: that is
    # the reading HOUR-M8004-OFF=valid-preset, which a declaration explains, so it was no bug.
    def execute(self, instruction, operands, step):
        self.mem.write(ERROR_FLAG, False)
        return super().execute(instruction, operands, step)


@mutant("hour-one-second-per-scan", FAMILY,
        "A scan adds at most one second to D1, however long it was, so a slow scan loses ON time "
        "the 'measured input ON duration' should hold.",
        exercises={"whole-seconds": ["several"]})
class OneSecondPerScan(Fc6aHourMeter):
    def execute(self, instruction, operands, step):
        if step["input"]:
            self.fraction_ms = min(self.fraction_ms + int(step["elapsed_ms"]), 1999) - int(step["elapsed_ms"])
        return super().execute(instruction, operands, step)
