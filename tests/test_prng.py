"""The golden random vectors' generator: SplitMix64 as published, and what is drawn with it.

Reference outputs: seed 0 from the reference implementation (Vigna's splitmix64.c); seed 20261121
(the seed of spec/fx5-time-compare.yaml) from Java's java.util.SplittableRandom(20261121L).nextLong(),
whose algorithm is SplitMix64, printed as unsigned.
"""
from collections import Counter

import pytest

from plcvec.cases.prng import SplitMix64
from plcvec.cases.random_cases import draw_addition, draw_hour_meter, key_of
from plcvec.spec.loader import load_spec


def test_sequence_from_seed_0_is_the_reference():
    rng = SplitMix64(0)
    assert [rng.next64() for _ in range(3)] == [0xE220A8397B1DCDAF, 0x6E789E6AA1B965F4, 0x06C45D188009454F]


def test_sequence_is_javas_splittable_random():
    rng = SplitMix64(20261121)
    assert [rng.next64() for _ in range(3)] == [3112893543532698984, 7423052691808567535, 9529462432175676356]


def test_below_stays_in_bounds_and_reaches_every_value():
    rng = SplitMix64(7)
    for n in (1, 2, 3, 7, 10, 1000, 1 << 16):
        seen = {rng.below(n) for _ in range(4000)}
        assert min(seen) >= 0 and max(seen) < n
        if n <= 10:
            assert seen == set(range(n))
    with pytest.raises(ValueError):
        rng.below(0)


def test_below_is_unbiased_for_a_range_that_is_not_a_power_of_two():
    # 3 does not divide 2**k: a modulo would favour 0; rejection gives each a third (+-3 % at n=30000).
    rng = SplitMix64(11)
    counts = Counter(rng.below(3) for _ in range(30000))
    assert all(9100 < c < 10900 for c in counts.values()), counts


def test_integer_includes_both_ends():
    rng = SplitMix64(3)
    assert {rng.integer(-1, 1) for _ in range(200)} == {-1, 0, 1}


@pytest.fixture(scope="module")
def families():
    return {f.name: f for f in load_spec()}


def test_additions_are_in_range_distinct_and_keyed_by_content(families):
    fields = _fields(families["fx5-time-add"])
    drawn = list(draw_addition(fields, 99, 200))
    assert len({d["key"] for d in drawn}) == len(drawn)
    for d in drawn:
        assert d["key"] == key_of({"s1": d["s1"], "s2": d["s2"]})
        for f in fields:
            assert f["min"] <= d["s1"][f["name"]] <= f["max"] and f["min"] <= d["s2"][f["name"]] <= f["max"]
    assert list(draw_addition(fields, 99, 200)) == drawn   # the same seed, the same draws
    assert list(draw_addition(fields, 100, 200)) != drawn


def test_hour_meter_sequences_have_one_to_six_scans_of_both_lengths(families):
    fields = _fields(families["fc6a-hour-meter"])
    drawn = list(draw_hour_meter(fields, 5, 300))
    assert {len(d["steps"]) for d in drawn} == set(range(1, 7))
    elapsed = [s["elapsed_ms"] for d in drawn for s in d["steps"]]
    assert min(elapsed) >= 0 and max(elapsed) <= 10 ** 7
    assert any(e <= 2500 for e in elapsed) and any(e > 2500 for e in elapsed)


def test_golden_comparisons_are_drawn_in_and_past_the_ranges():
    """Past-the-range fields raise the operation error; in-range ones compare: both are among the draws."""
    import json

    from conftest import REPO

    data = json.loads((REPO / "vectors" / "fx5-time-compare.json").read_text(encoding="utf-8"))
    outcomes = Counter(v["outcome"]["category"] for v in data["vectors"] if "random" in v["tags"])
    assert outcomes["error"] >= 5 and outcomes["value"] + outcomes["implementation-defined"] >= 50, outcomes


def _fields(fam):
    from plcvec.cases.build import VectorBuilder
    from plcvec.cases.clock_add_cases import AddCases
    from plcvec.cases.hour_meter_cases import HourCases

    return {"clock_add": AddCases, "hour_meter": HourCases}[fam.kind](fam, VectorBuilder(fam)).fields
