"""The CPU clock holds only what a clock can hold: every current-clock input of the golden set is a real
calendar date and time of day (a device may hold 2023/2/29, as the FX5 date page says; a clock cannot).
Checked with Python's own calendar, not with the generator's."""
import datetime

# The fields of a clock a family's vectors inject per step, by the family's own field names.
DATE = ("year", "month", "day")
TIME = ("hour", "minute", "second")
# The CP1E calendar/clock area, BCD: A351 second (bits 00-07) and minute (08-15), A352 hour and day,
# A353 month and year (00 to 99, the years 2000 to 2099).
CP1E_AREA = ("A351", "A352", "A353")


def bcd(byte):
    assert byte >> 4 <= 9 and byte & 0xF <= 9, f"{byte:#04x} is not BCD"
    return (byte >> 4) * 10 + (byte & 0xF)


def real(clock):
    """A ValueError unless `clock` (some of year, month, day, hour, minute, second) is a real date and time."""
    if all(k in clock for k in DATE):
        datetime.date(clock["year"], clock["month"], clock["day"])
    if all(k in clock for k in TIME):
        datetime.time(clock["hour"], clock["minute"], clock["second"])
    if not any(all(k in clock for k in part) for part in (DATE, TIME)):
        raise ValueError(f"not a clock: {clock}")


def clock_inputs(vector):
    """Every current-clock value `vector` gives: the steps' injected clocks, and the CP1E clock area when
    an operand reads it."""
    found = [s["clock"] for s in vector["steps"] if "clock" in s]
    devices = vector["initial"]["devices"]
    if any(op.get("device") == CP1E_AREA[0] for op in vector["initial"]["operands"].values()):
        a351, a352, a353 = (devices[a] for a in CP1E_AREA)
        found.append({"second": bcd(a351 & 0xFF), "minute": bcd(a351 >> 8), "hour": bcd(a352 & 0xFF),
                      "day": bcd(a352 >> 8), "month": bcd(a353 & 0xFF), "year": 2000 + bcd(a353 >> 8)})
    return found


def impossible(vectors):
    out = []
    for v in vectors:
        for clock in clock_inputs(v):
            try:
                real(clock)
            except (ValueError, AssertionError) as exc:
                out.append(f"{v['id']}: {clock} ({exc})")
    return out


def test_every_current_clock_input_is_a_real_date_and_time(all_vectors):
    with_clock = [v for v in all_vectors if clock_inputs(v)]
    # Both kinds of clock are there: the FX5 injected clocks (dates and times) and the CP1E clock area.
    assert {v["family"] for v in with_clock} == {"fx5-time-compare", "fx5-date-compare", "cp1e-time-compare"}
    bad = impossible(with_clock)
    assert not bad, f"{len(bad)} impossible clock inputs: {bad[:5]}"


def test_the_check_refuses_an_impossible_clock():
    """The check itself: a clock no calendar has is caught, in each shape the vectors use."""
    step = {"clock": {"year": 2023, "month": 2, "day": 29}}
    vector = {"id": "x", "steps": [step], "initial": {"operands": {}, "devices": {}}}
    assert impossible([vector])
    step["clock"] = {"year": 2024, "month": 2, "day": 29}
    assert not impossible([vector])
    step["clock"] = {"hour": 24, "minute": 0, "second": 0}
    assert impossible([vector])
    area = {"steps": [{}], "id": "y", "initial": {"operands": {"S1": {"device": "A351"}},
                                                  "devices": {"A351": 0x0000, "A352": 0x3100, "A353": 0x2304}}}
    assert impossible([area])   # 2023/04/31
    area["initial"]["devices"]["A353"] = 0x2305
    assert not impossible([area])   # 2023/05/31
