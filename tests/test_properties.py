"""Properties stated from the manual, checked against the spec engine with hypothesis.

Expected values come from independent derivations (datetime arithmetic, tuple ordering, the condition
table's meaning), never from the engine itself.
"""
import datetime

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from helpers import Runner

TIME = dict(hour=(0, 23), minute=(0, 59), second=(0, 59))
DATE = dict(year=(1980, 2079), month=(1, 12), day=(1, 31))
CP1E = dict(year=(0, 99), month=(1, 12), day=(1, 31), hour=(0, 23), minute=(0, 59), second=(0, 59))
COMMON = settings(max_examples=150, deadline=None)


def values(ranges):
    return st.fixed_dictionaries({k: st.integers(lo, hi) for k, (lo, hi) in ranges.items()})


def place(devices, head, words):
    prefix, number = head[0], int(head[1:])
    for k, w in enumerate(words):
        devices[f"{prefix}{number + k}"] = w


def fx5_compare(runner, symbol, prefix, a, b, selector):
    devices = {"SM709": False, "D300": selector}
    place(devices, "D100", runner.words(a))
    place(devices, "D200", runner.words(b))
    ops = {"s1": {"device": "D100"}, "s2": {"device": "D200"}, "s3": {"device": "D300"}}
    expects, final, _ = runner.run(f"{prefix}{symbol}", ops, devices, [{}])
    return expects[0]["result"], final["SM709"]


SYMBOLS = ["=", "<>", ">", "<=", "<", ">="]


@pytest.mark.parametrize("family,prefix,ranges", [("fx5-time-compare", "LDTM", TIME), ("fx5-date-compare", "LDDT", DATE)])
def test_six_conditions_partition_every_pair(families, family, prefix, ranges):
    runner = Runner(families[family])

    @COMMON
    @given(values(ranges), values(ranges), st.integers(1, 7))
    def prop(a, b, sel):
        r = {s: fx5_compare(runner, s, prefix, a, b, sel)[0] for s in SYMBOLS}
        assert sum([r["<"], r["="], r[">"]]) == 1  # exactly one ordering holds
        assert r["<>"] == (not r["="])
        assert r["<="] == (r["<"] or r["="]) and r[">="] == (r[">"] or r["="])

    prop()


@pytest.mark.parametrize("family,prefix,ranges", [("fx5-time-compare", "LDTM", TIME), ("fx5-date-compare", "LDDT", DATE)])
def test_unselected_field_never_changes_the_result(families, family, prefix, ranges):
    runner = Runner(families[family])
    names = list(ranges)  # most significant first, as (s3) bits 2, 1, 0

    @COMMON
    @given(values(ranges), values(ranges), st.integers(1, 7), st.sampled_from(SYMBOLS), st.data())
    def prop(a, b, sel, symbol, data):
        selected = [n for i, n in enumerate(names) if sel >> (len(names) - 1 - i) & 1]
        unselected = [n for n in names if n not in selected]
        if not unselected:
            return
        name = data.draw(st.sampled_from(unselected))
        lo, hi = ranges[name]
        a2 = dict(a, **{name: data.draw(st.integers(lo, hi))})
        assert fx5_compare(runner, symbol, prefix, a, b, sel) == fx5_compare(runner, symbol, prefix, a2, b, sel)

    prop()


def test_date_comparison_agrees_with_datetime_date_on_selected_fields(families):
    runner = Runner(families["fx5-date-compare"])
    dates = st.dates(datetime.date(1980, 1, 1), datetime.date(2079, 12, 31))

    @COMMON
    @given(dates, dates, st.integers(1, 7))
    def prop(x, y, sel):
        # (s3) bit 2 year, bit 1 month, bit 0 day (manual, "(1) Set "day" as comparison target" ...).
        keys = [k for k, bit in (("year", 2), ("month", 1), ("day", 0)) if sel >> bit & 1]
        key = lambda d: tuple(getattr(d, k) for k in keys)
        a = dict(year=x.year, month=x.month, day=x.day)
        b = dict(year=y.year, month=y.month, day=y.day)
        assert fx5_compare(runner, "<", "LDDT", a, b, sel) == (key(x) < key(y), False)
        assert fx5_compare(runner, "=", "LDDT", a, b, sel) == (key(x) == key(y), False)
        if sel == 7:
            assert fx5_compare(runner, "<", "LDDT", a, b, sel)[0] == (x < y)

    prop()


def test_time_addition_agrees_with_datetime_modulo_24_hours(families):
    runner = Runner(families["fx5-time-add"])

    @COMMON
    @given(values(TIME), values(TIME))
    def prop(a, b):
        devices = {"SM700": False, "SM8020": False, "SM8022": False, "SD0": 0, "SD8067": 0}
        place(devices, "D100", runner.words(a))
        place(devices, "D200", runner.words(b))
        place(devices, "D300", [0, 0, 0])
        ops = {"s1": {"device": "D100"}, "s2": {"device": "D200"}, "d": {"device": "D300"}}
        _, final, outcome = runner.run("TADD", ops, devices, [{"en": True}])
        start = datetime.datetime(2000, 1, 1, a["hour"], a["minute"], a["second"])
        total = start + datetime.timedelta(hours=b["hour"], minutes=b["minute"], seconds=b["second"])
        assert (final["D300"], final["D301"], final["D302"]) == (total.hour, total.minute, total.second)
        assert final["SM700"] == final["SM8022"] == (total.date() > start.date())
        assert final["SM8020"] == (total.time() == datetime.time(0, 0, 0))
        assert outcome == {"category": "value"}

    prop()


def bcd(v):
    return (v // 10) << 4 | v % 10


def test_cp1e_compares_unmasked_fields_in_calendar_order_and_sets_flags(families):
    runner = Runner(families["cp1e-time-compare"])
    order = ["year", "month", "day", "hour", "minute", "second"]
    mask_bit = {"second": 0, "minute": 1, "hour": 2, "day": 3, "month": 4, "year": 5}

    def words(v):
        # Manual layout: word 0 = minute:second, word 1 = day:hour, word 2 = year:month, BCD bytes.
        return [bcd(v["minute"]) << 8 | bcd(v["second"]), bcd(v["day"]) << 8 | bcd(v["hour"]), bcd(v["year"]) << 8 | bcd(v["month"])]

    @COMMON
    @given(values(CP1E), values(CP1E), st.integers(0, 0x3E), st.sampled_from(["=DT", "<>DT", "<DT", "<=DT", ">DT", ">=DT"]))
    def prop(a, b, mask, symbol):
        devices = {"D300": mask, "P_ER": False, **{f: False for f in ("P_EQ", "P_NE", "P_LT", "P_LE", "P_GT", "P_GE")}}
        place(devices, "D100", words(a))
        place(devices, "D200", words(b))
        ops = {"S1": {"device": "D100"}, "S2": {"device": "D200"}, "C": {"device": "D300"}}
        expects, final, _ = runner.run(f"LD {symbol}", ops, devices, [{}])
        keep = [k for k in order if not mask >> mask_bit[k] & 1]
        x, y = tuple(a[k] for k in keep), tuple(b[k] for k in keep)
        truth = {"=DT": x == y, "<>DT": x != y, "<DT": x < y, "<=DT": x <= y, ">DT": x > y, ">=DT": x >= y}
        assert expects[0]["result"] == truth[symbol]
        # Flag table: = ON iff S1 = S2, <> iff not, < iff S1 < S2, and so on.
        assert (final["P_EQ"], final["P_NE"], final["P_LT"], final["P_LE"], final["P_GT"], final["P_GE"]) == (
            x == y, x != y, x < y, x <= y, x > y, x >= y)

    prop()


def test_hour_meter_counts_only_on_time_in_whole_seconds(families):
    runner = Runner(families["fc6a-hour-meter"])
    steps = st.lists(st.fixed_dictionaries({"input": st.booleans(), "elapsed_ms": st.integers(0, 5000)}), min_size=1, max_size=8)

    @COMMON
    @given(steps)
    def prop(seq):
        devices = {"M8004": False, "M10": False, "D300": 0, "D301": 0}
        place(devices, "D100", [1000, 0, 0])  # preset far away
        place(devices, "D200", [0, 0, 0])
        ops = {"S1": {"device": "D100"}, "D1": {"device": "D200"}, "D2": {"device": "M10"}, "D3": {"device": "D300"}}
        _, final, _ = runner.run("HOUR", ops, devices, seq, scratch=("D300", "D301"))
        on_ms = sum(s["elapsed_ms"] for s in seq if s["input"])
        seconds = on_ms // 1000
        assert (final["D200"], final["D201"], final["D202"]) == (seconds // 3600, seconds // 60 % 60, seconds % 60)
        assert final["M10"] is False

    prop()
