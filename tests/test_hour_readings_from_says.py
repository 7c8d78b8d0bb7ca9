"""An emulator written from an alternative's `says` alone passes the vectors that ask it.

TinyHour is HOUR as its author would write it from the page (the defaults) and the wording of two
readings, HOUR-D1-OUT-OF-RANGE=by-field and HOUR-WRAP-REACH=before-wrap, without the engine or the
reference: if the `says` left something open, the author's guess would fail some vector.
"""
import pytest

from plcvec_verify import InProcess, Selection, Suite, run

from conftest import REPO

HOUR_SECONDS = 3600
OUT_OF_RANGE = "fc6a-hour-meter/HOUR/measured-out-of-range/*"
WRAPS = "fc6a-hour-meter/HOUR/wrap/*"


class TinyHour:
    """Only what the vectors of a D1 out of range and of a wrap need: the input on, S1 valid."""

    def __init__(self, d1_reading, wrap_reading, declare=None):
        self.d1, self.wrap = d1_reading, wrap_reading
        self.declare = {"HOUR-D1-OUT-OF-RANGE": d1_reading, "HOUR-WRAP-REACH": wrap_reading} if declare is None else declare

    def hello(self, request):
        return {"adapter": {"name": "tiny-hour"}, "instructions": ["HOUR"], "interpretations": self.declare}

    def run(self, request):
        mem = dict(request["initial"]["devices"])
        ops = request["initial"]["operands"]
        d1 = [f"D{int(ops['D1']['device'][1:]) + k}" for k in range(3)]
        d2 = ops["D2"]["device"]
        if "constant" in ops["S1"]:
            preset = [ops["S1"]["constant"], 0, 0]
        else:
            preset = [mem[f"D{int(ops['S1']['device'][1:]) + k}"] for k in range(3)]
        ms, out = 0, []
        for step in request["steps"]:
            mem.update(step.get("set", {}))
            ms += step["elapsed_ms"]
            whole, ms = divmod(ms, 1000)
            hms, wraps = self.add([mem[a] for a in d1], whole)
            mem.update(zip(d1, hms))
            if self.reached(hms, wraps, preset):
                mem[d2] = True
            out.append({"devices": dict(mem)})
        return {"steps": out}

    def add(self, hms, seconds):
        h, m, s = hms
        if self.d1 == "by-field" and (m > 59 or s > 59):
            # "Each word of D1 counts as a counter of its own, one whole second at a time: ..."
            wraps = 0
            for _ in range(seconds):
                s = (s + 1) & 0xFFFF
                if s == 60:
                    s, m = 0, (m + 1) & 0xFFFF
                    if m == 60:
                        m, h = 0, (h + 1) & 0xFFFF
                        wraps += h == 0
            return [h, m, s], wraps
        total = h * HOUR_SECONDS + m * 60 + s + seconds
        wraps, total = divmod(total, 65536 * HOUR_SECONDS)
        return [total // HOUR_SECONDS, total // 60 % 60, total % 60], wraps

    def reached(self, hms, wraps, preset):
        if wraps and self.wrap == "before-wrap":
            return True     # "the count before the wrap ... reaches any S1 of at most 65535:59:59"
        return hms >= preset    # hour, then minute, then second: for values in range, the count's order


@pytest.fixture(scope="module")
def suite():
    return Suite.load(REPO / "vectors")


@pytest.mark.parametrize("d1, wrap", [("by-field", "after-wrap"), ("as-seconds", "before-wrap"), ("by-field", "before-wrap")])
def test_an_emulator_written_from_the_says_passes(suite, d1, wrap):
    report = run(suite, InProcess(TinyHour(d1, wrap)), Selection(ids=(OUT_OF_RANGE, WRAPS)))
    assert report.counts["pass"] == 10 and report.exit_code == 0, [r.id for r in report.failed]


@pytest.mark.parametrize("d1, wrap, declared", [
    ("by-field", "after-wrap", {}),                                    # follows by-field, declares nothing
    ("as-seconds", "before-wrap", {"HOUR-WRAP-REACH": "after-wrap"}),  # follows before-wrap, declares after
])
def test_the_same_emulator_declaring_another_reading_fails(suite, d1, wrap, declared):
    report = run(suite, InProcess(TinyHour(d1, wrap, declared)), Selection(ids=(OUT_OF_RANGE, WRAPS)))
    assert report.exit_code == 1
