"""The Python holds no instruction facts: edit a copy of the spec, regenerate, and the vectors follow the edit.

Every expected value here comes from the edit and from the manual (quoted in the spec's clauses),
computed by the small reference model below, never copied from generator output.
"""
import json
import re
import shutil
from pathlib import Path

import pytest

from plcvec.output.golden import family_vectors
from plcvec.spec.loader import load_spec

REPO = Path(__file__).resolve().parents[1]
SPEC = REPO / "spec"

TC_FILE, TC = "fx5-time-compare.yaml", "fx5-time-compare"
DC_FILE, DC = "fx5-date-compare.yaml", "fx5-date-compare"
TA_FILE, TA = "fx5-time-add.yaml", "fx5-time-add"


def edited_spec(tmp_path, name, at, old, new):
    """A copy of spec/ in tmp_path with `old` replaced by `new` (exactly once) on the one line of `name`
    that contains `at` (found by its text, so that lines added above it do not move the edit)."""
    folder = tmp_path / "spec"
    shutil.copytree(SPEC, folder)
    path = folder / name
    lines = path.read_text(encoding="utf-8").split("\n")
    hits = [i for i, l in enumerate(lines) if at in l]
    assert len(hits) == 1, f"{name}: {at!r} is on {len(hits)} lines, not one"
    line = hits[0] + 1
    assert lines[line - 1].count(old) == 1, f"{name}:{line} is {lines[line - 1]!r}"
    lines[line - 1] = lines[line - 1].replace(old, new)
    path.write_text("\n".join(lines), encoding="utf-8")
    return folder


def generate(spec_dir, *only):
    """{family: {vector id: vector}} generated in process from a spec folder: every family, or those named."""
    families = [f for f in load_spec(spec_dir) if not only or f.name in only]
    assert not only or len(families) == len(only)
    return {fam.name: {v["id"]: v for v in family_vectors(fam)} for fam in families}


@pytest.fixture(scope="module")
def baseline(generated):
    """The vectors of the unedited spec, as generated once for the test session."""
    return {fam: {v["id"]: v for v in vectors} for fam, vectors in generated[1].items()}


# ------------------------------------------------------------------ reference model (from the manual)
# FX5 LDTM□ (fx5-time-compare-LDTM.txt): (s1), (s1)+1, (s1)+2 hold hour, minute, second as 16-bit signed
# binary; hour 0..23, minute 0..59, second 0..59. (s3) bit 0 selects the second, bit 1 the minute, bit 2
# the hour; bits 3..14 must be 0; bit 15 compares with the current time. Selected data outside its range
# turns SM709 on and gives non-continuity. Selected fields are compared as a time of day (hour first).

ORDER = ("hour", "minute", "second")
WORD = {"hour": 0, "minute": 1, "second": 2}
MANUAL_BITS = {"second": 0, "minute": 1, "hour": 2}
MANUAL_RANGES = {"hour": (0, 23), "minute": (0, 59), "second": (0, 59)}
CONDITIONS = {"=": lambda c: c == 0, "<>": lambda c: c != 0, ">": lambda c: c > 0,
              "<=": lambda c: c <= 0, "<": lambda c: c < 0, ">=": lambda c: c >= 0}


def signed(word):
    return word - 0x10000 if word >= 0x8000 else word


def word_at(vector, operand, offset):
    """The initial value of word `offset` of an operand, or None when that word is not in the vector."""
    op = vector["initial"]["operands"][operand]
    if "constant" in op:
        return op["constant"]
    kind, number = re.fullmatch(r"([A-Z]+)(\d+)", op["device"]).groups()
    value = vector["initial"]["devices"].get(f"{kind}{int(number) + offset}")
    return None if value is None else signed(value)


def selector(vector):
    return word_at(vector, "s3", 0) & 0xFFFF


def model_ldtm(vector, *, bits=MANUAL_BITS, ranges=MANUAL_RANGES):
    """(result, error) an LD-form time comparison must give, or None when the model does not apply."""
    symbol = vector["instruction"][len("LDTM"):]
    s3 = selector(vector)
    if s3 & 0xFFF8 or len(vector["steps"]) != 1 or set(vector["steps"][0]) != {"expect"}:
        return None  # reserved bits, current-clock mode, scan sequences: not what these tests are about
    selected = [f for f in ORDER if s3 >> bits[f] & 1]
    s1 = {f: word_at(vector, "s1", WORD[f]) for f in ORDER}
    s2 = {f: word_at(vector, "s2", WORD[f]) for f in ORDER}
    if any(v is None for v in list(s1.values()) + list(s2.values())):
        return None  # device-range vectors
    if not selected:
        return False, False
    if any(not ranges[f][0] <= x[f] <= ranges[f][1] for f in selected for x in (s1, s2)):
        return False, True
    a, b = tuple(s1[f] for f in selected), tuple(s2[f] for f in selected)
    return CONDITIONS[symbol]((a > b) - (a < b)), False


def check_ldtm_vectors(vectors, error_device="SM709", **model):
    """Every LD-form vector with a definite outcome agrees with the model; returns how many were checked."""
    checked = 0
    for vid, v in vectors.items():
        if not v["instruction"].startswith("LDTM") or v["outcome"]["category"] == "implementation-defined":
            continue
        expected = model_ldtm(v, **model)
        if expected is None:
            continue
        result, error = expected
        step = v["steps"][0]["expect"]
        assert step["result"] is result, vid
        assert (v["outcome"]["category"] == "error") is error, vid
        assert step["devices"].get(error_device, v["initial"]["devices"][error_device]) is (
            error or v["initial"]["devices"][error_device]), vid
        assert v["final"]["devices"][error_device] is (error or v["initial"]["devices"][error_device]), vid
        checked += 1
    return checked


def test_model_agrees_with_the_unedited_spec(baseline):
    """The reference model is right about the real spec, so it can judge the edited ones."""
    assert check_ldtm_vectors(baseline[TC]) >= 150


# ------------------------------------------------------------------ (1) narrow the hour range to 0..22

BOUNDARY_23 = f"{TC}/LDTM=/boundary/s1.hour=23/only"
BOUNDARY_22 = f"{TC}/LDTM=/boundary/s1.hour=22/only"


def test_hour_max_22_makes_hour_23_an_error(tmp_path, baseline):
    before = baseline[TC][BOUNDARY_23]
    assert before["outcome"]["category"] == "value"
    assert model_ldtm(before) == (True, False)

    folder = edited_spec(tmp_path, TC_FILE, "- {name: hour, word: 0,", "min: 0, max: 23, clause: range.hour",
                         "min: 0, max: 22, clause: range.hour")
    after = generate(folder, TC)[TC]

    v = after[BOUNDARY_23]
    assert word_at(v, "s1", 0) == 23 and selector(v) == 1 << MANUAL_BITS["hour"]  # hour only, as the id says
    # Outside the (new) range: SM709 turns on and the result is non-continuity.
    assert v["outcome"]["category"] == "error"
    assert v["outcome"]["errors"] == [{"device": "SM709", "step": 0}]
    assert v["initial"]["devices"]["SM709"] is False
    assert v["steps"][0]["expect"]["result"] is False
    assert v["steps"][0]["expect"]["devices"]["SM709"] is True
    assert v["final"]["devices"]["SM709"] is True

    # The new top of the range has its own boundary vector, and it compares normally.
    assert BOUNDARY_22 not in baseline[TC]
    w = after[BOUNDARY_22]
    assert word_at(w, "s1", 0) == 22 and selector(w) == 1 << MANUAL_BITS["hour"]
    assert w["outcome"]["category"] == "value"
    assert w["steps"][0]["expect"]["result"] is (word_at(w, "s1", 0) == word_at(w, "s2", 0))
    assert w["final"]["devices"]["SM709"] is False

    # And every LD vector of the family follows the narrowed range, not the manual's 0..23.
    ranges = dict(MANUAL_RANGES, hour=(0, 22))
    assert check_ldtm_vectors(after, ranges=ranges) >= 150
    # No vector with a definite value outcome compares a selected hour of 23 any more.
    for vid, x in after.items():
        if x["outcome"]["category"] != "value" or any("clock" in s for s in x["steps"]):
            continue
        s3 = selector(x)
        if s3 >> MANUAL_BITS["hour"] & 1 and not s3 & 0xFFF8:
            assert all(word_at(x, op, 0) is None or word_at(x, op, 0) <= 22 for op in ("s1", "s2")), vid


def test_hour_range_edit_touches_no_other_family(tmp_path, baseline):
    folder = edited_spec(tmp_path, TC_FILE, "- {name: hour, word: 0,", "max: 23,", "max: 22,")
    after = generate(folder)
    assert after[TC] != baseline[TC]
    assert {k: v for k, v in after.items() if k != TC} == {k: v for k, v in baseline.items() if k != TC}


# ------------------------------------------------------------------ (2) swap the (s3) bits of second and minute

def test_swapped_selector_bits_compare_the_other_field(tmp_path, baseline):
    folder = edited_spec(tmp_path, TC_FILE, "field_bits: {second: 0,", "field_bits: {second: 0, minute: 1, hour: 2}",
                         "field_bits: {second: 1, minute: 0, hour: 2}")
    after = generate(folder, TC)[TC]
    swapped = {"second": 1, "minute": 0, "hour": 2}

    # The manual's worked example, row "Second data" (s3 = 0001H), A<B: with the manual's layout bit 0 is
    # the second; after the edit bit 0 is the minute, so the vector must compare (s1)+1 with (s2)+1.
    vid = f"{TC}/LDTM</manual-example/abc/A<B/second-data"
    before, now = baseline[TC][vid], after[vid]
    assert selector(before) == selector(now) == 0x0001
    assert now["initial"] == before["initial"]  # same data A and B: only the meaning of bit 0 changed
    a_min, b_min = word_at(now, "s1", 1), word_at(now, "s2", 1)
    a_sec, b_sec = word_at(now, "s1", 2), word_at(now, "s2", 2)
    assert (a_min < b_min) != (a_sec < b_sec), "the example must tell minutes from seconds"
    assert before["steps"][0]["expect"]["result"] is (a_sec < b_sec)
    assert now["steps"][0]["expect"]["result"] is (a_min < b_min)
    assert now["outcome"]["category"] == "value"

    # Row "Minute data" (s3 = 0002H) now compares seconds, for each pair of the example.
    for pair in ("A<B", "B<C", "A<C"):
        v = after[f"{TC}/LDTM</manual-example/abc/{pair}/minute-data"]
        assert selector(v) == 0x0002
        assert v["steps"][0]["expect"]["result"] is (word_at(v, "s1", 2) < word_at(v, "s2", 2)), pair

    # Every LD vector follows the swapped layout (and would fail the manual's).
    assert check_ldtm_vectors(after, bits=swapped) >= 150
    with pytest.raises(AssertionError):
        check_ldtm_vectors(after)


# ------------------------------------------------------------------ (3) a different TADD range-error code

def test_tadd_error_code_follows_the_spec(tmp_path, baseline):
    old, new = 0x3405, 0x3499
    folder = edited_spec(tmp_path, TA_FILE, "code: 0x3405,", "code: 0x3405", f"code: {new:#06x}")
    after = generate(folder, TA)[TA]

    def outside(v):
        # (s1) or (s2) holding an hour outside 0 to 23 or a minute/second outside 0 to 59 (manual, 3405H).
        return any(not MANUAL_RANGES[f][0] <= word_at(v, op, WORD[f]) <= MANUAL_RANGES[f][1]
                   for op in ("s1", "s2") for f in ORDER)

    def range_vectors(vectors):
        return {vid: v for vid, v in vectors.items() if "/range/" in vid and outside(v)}

    # The in-range boundary neighbours of those vectors store no code at all, before and after.
    in_range = [v for vid, v in after.items() if "/range/" in vid and not outside(v)]
    assert in_range
    for v in in_range:
        assert v["final"]["devices"]["SD0"] == v["initial"]["devices"]["SD0"] == 0

    before_rv, after_rv = range_vectors(baseline[TA]), range_vectors(after)
    assert after_rv and set(after_rv) == set(before_rv)

    def codes(v):
        """The error code of the default outcome, and what SD0/SD8067 hold after the step."""
        outcome = v["outcome"].get("default", v["outcome"])
        assert outcome["category"] == "error"
        return ({e["code"] for e in outcome["errors"]},
                {v["steps"][0]["expect"]["devices"][r] for r in ("SD0", "SD8067")},
                {v["final"]["devices"][r] for r in ("SD0", "SD8067")})

    for vid in after_rv:
        assert codes(before_rv[vid]) == ({old}, {old}, {old}), vid
        assert codes(after_rv[vid]) == ({new}, {new}, {new}), vid
        for alt in after_rv[vid].get("alternatives", []):
            assert {e["code"] for e in alt["outcome"]["errors"]} == {new}, vid
            assert alt["final"]["devices"]["SD0"] == new, vid

    # The old code is gone from every value in the family; the 2820H device-range error is unchanged.
    def ints(node):
        if isinstance(node, dict):
            for x in node.values():
                yield from ints(x)
        elif isinstance(node, list):
            for x in node:
                yield from ints(x)
        elif isinstance(node, int) and not isinstance(node, bool):
            yield node
    assert old not in set(ints(list(after.values())))
    device_range = [v for vid, v in after.items() if "/device-range/" in vid and v["outcome"]["category"] == "error"]
    assert device_range
    for v in device_range:
        assert v["outcome"]["errors"] == [{"code": 0x2820, "step": 0}]
        assert v["final"]["devices"]["SD0"] == v["final"]["devices"]["SD8067"] == 0x2820


# ------------------------------------------------------------------ (4) another error device for LDDT

def test_error_device_name_follows_the_spec(tmp_path, baseline):
    folder = edited_spec(tmp_path, DC_FILE, "device: SM709", "device: SM709", "device: SM710")
    # Regression cases (spec/regressions/) give their devices by name, as recorded, so they do not
    # follow a rename (generate reports such a case at its line): only derived vectors are compared.
    (folder / "regressions" / f"{DC}.yaml").unlink()
    regenerated = generate(folder, DC, TC)
    after = regenerated[DC]

    assert set(after) == {vid for vid, v in baseline[DC].items() if "regression" not in v["tags"]}
    text = json.dumps(after)
    assert '"SM709"' not in text

    def devices_of(v):
        yield v["initial"]["devices"]
        yield v["final"]["devices"]
        for s in v["steps"]:
            yield s["expect"]["devices"]
        for alt in v.get("alternatives", []):
            yield alt["final"]["devices"]
            for e in alt["expect"]:
                yield e["devices"]

    errors = 0
    for vid, v in after.items():
        old = baseline[DC][vid]
        # Same vector with SM709 renamed SM710 everywhere a device is named, and nothing else changed.
        for new_devs, old_devs in zip(devices_of(v), devices_of(old)):
            assert new_devs == {("SM710" if k == "SM709" else k): x for k, x in old_devs.items()}, vid
        assert v["steps"][0]["expect"].get("result") == old["steps"][0]["expect"].get("result"), vid
        outcome = v["outcome"].get("default", v["outcome"])
        if outcome["category"] == "error":
            assert outcome["errors"] and all(e.get("device") == "SM710" for e in outcome["errors"]), vid
            for e in outcome["errors"]:
                # The error step turns SM710 on, unless it was already on (the flag latches).
                changed = v["steps"][e["step"]]["expect"]["devices"]
                assert changed.get("SM710", v["initial"]["devices"]["SM710"]) is True, vid
            errors += 1
    assert errors > 0

    # The time comparison, a separate family with its own SM709, still uses SM709.
    assert regenerated[TC] == baseline[TC]
    assert any(e.get("device") == "SM709" for v in regenerated[TC].values() for e in v["outcome"].get("errors", []))
