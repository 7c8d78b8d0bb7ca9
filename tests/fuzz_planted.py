"""Adapters with one planted bug each, for tests/test_fuzz.py: the reference implementation with the bug.

In process: `--python tests/fuzz_planted.py:EveryScan`. As a process, kept light because a test restarts
it once per crash: `python3 tests/fuzz_planted.py every-scan`.
"""
import os
import sys

from plcvec_reference import make_machine
from plcvec_reference.adapter import ReferenceAdapter
from plcvec_reference.fx5_compare import Fx5Compare
from plcvec_reference.fx5_tadd import Fx5TimeAdd


class HourAsMinuteMachine(Fx5Compare):
    """Reads the minute word where the hour belongs when comparing (the range check is still right)."""

    def _compare(self, s1, s2, s3):
        return super()._compare([s1[1], *s1[1:]], [s2[1], *s2[1:]], s3)


class EveryScanMachine(Fx5TimeAdd):
    """TADDP adds on every scan EN is on, as TADD does, instead of on the rising edge only."""

    def execute(self, instruction, operands, step):
        return super().execute("TADD", operands, step)


class _Planted(ReferenceAdapter):
    MACHINES = {}

    def __init__(self):
        super().__init__()
        self.make_machine = lambda family, *args: make_machine(family, *args, cls=self.MACHINES.get(family))


class HourAsMinute(_Planted):
    MACHINES = {"fx5-time-compare": HourAsMinuteMachine}


class EveryScan(_Planted):
    MACHINES = {"fx5-time-add": EveryScanMachine}


class CrashOnConstantPreset(ReferenceAdapter):
    """Raises on an HOUR preset given as a constant: a crash is a disagreement too."""

    def run(self, request):
        if request["initial"]["operands"].get("S1", {}).get("constant") is not None:
            raise RuntimeError("constant presets are not supported")
        return super().run(request)


class ExitOnConstantPreset(ReferenceAdapter):
    """The process dies on an HOUR preset given as a constant (for the stdio protocol only)."""

    def run(self, request):
        if request["initial"]["operands"].get("S1", {}).get("constant") is not None:
            os._exit(3)
        return super().run(request)


PLANTED = {"hour-as-minute": HourAsMinute, "every-scan": EveryScan, "exit-on-constant-preset": ExitOnConstantPreset}


if __name__ == "__main__":
    from plcvec_verify.serve import serve

    sys.exit(serve(PLANTED[sys.argv[1]]()))
