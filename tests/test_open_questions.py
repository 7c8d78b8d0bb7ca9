"""The questions the pages leave open are named, and the vectors that ask them hold what the pages and
the readings say: each expected value below is worked out by hand from the manual page and the
alternative's wording, not read from the generator."""
import pytest

# The interpretations fixed for every implementation (id, family, alternatives with the default first).
NAMED = [
    ("CP1E-ERROR-FLAGS", "cp1e-time-compare", ["kept", "off"]),
    ("HOUR-FIRST-SCAN", "fc6a-hour-meter", ["counts", "from-next-scan"]),
    ("FX5-OR-ON-ERROR", "fx5-time-compare", ["contact-off", "result-off"]),
    ("FX5-OR-ON-ERROR", "fx5-date-compare", ["contact-off", "result-off"]),
    ("HOUR-PRESET-CHECK", "fc6a-hour-meter", ["input-on", "every-execution"]),
    ("HOUR-M8004-OFF", "fc6a-hour-meter", ["never", "valid-preset"]),
    ("TADD-ERROR-ORDER", "fx5-time-add", ["device-range-first", "field-range-first"]),
    ("HOUR-D1-OUT-OF-RANGE", "fc6a-hour-meter", ["as-seconds", "error"]),
]


def by_id(golden, family):
    return {v["id"]: v for v in golden[family]["vectors"]}


def alternative(vector, **choices):
    """The expectation of `vector` under `choices` (interpretation id with '-' as '_' -> alternative)."""
    wanted = {k.replace("_", "-"): v for k, v in choices.items()}
    for alt in vector.get("alternatives", []):
        if all(alt["choices"].get(k) == v for k, v in wanted.items()):
            return alt
    raise AssertionError(f"{vector['id']} carries no alternative {wanted}")


@pytest.mark.parametrize("iid,family,alternatives", NAMED, ids=[f"{i}/{f}" for i, f, _ in NAMED])
def test_each_open_question_is_an_interpretation_with_its_default_first(iid, family, alternatives, families, golden):
    interp = families[family].interpretations[iid]
    assert [a["id"] for a in interp["alternatives"]] == alternatives
    assert interp["default"] == alternatives[0]
    # Some vector of the family asks it: its alternatives tell them apart.
    assert any(iid in v["outcome"].get("interpretations", []) for v in golden[family]["vectors"]), iid


def test_the_error_alternatives_leave_the_flags_to_their_own_question(families):
    """What an error does to the CP1E flags is CP1E-ERROR-FLAGS alone; no other alternative says it."""
    for iid, interp in families["cp1e-time-compare"].interpretations.items():
        for alt in interp["alternatives"]:
            if alt["id"] == "error":
                assert "left as they were" not in alt["says"] and "CP1E-ERROR-FLAGS" in alt["says"], (iid, alt["id"])


def test_hour_timing_is_no_longer_an_assumption_that_decides(families):
    why = families["fc6a-hour-meter"].doc["assumptions"]["timing"]["why"]
    assert "HOUR-FIRST-SCAN" in why


def test_both_tadd_error_conditions_store_the_code_the_reading_says(golden):
    vectors = [v for v in golden["fx5-time-add"]["vectors"] if "/both-errors/" in v["id"]]
    assert len(vectors) >= 3
    for v in vectors:
        # Error table: 2820H (device range) and 3405H (values); nothing but the two registers written.
        assert v["steps"][0]["expect"]["devices"] == {"SD0": 0x2820, "SD8067": 0x2820}, v["id"]
        alt = alternative(v, TADD_ERROR_ORDER="field-range-first")
        assert alt["expect"][0]["devices"] == {"SD0": 0x3405, "SD8067": 0x3405}, v["id"]


def test_tadd_error_registers_keep_an_earlier_code_after_a_good_execution(golden):
    vectors = by_id(golden, "fx5-time-add")
    for code in (0x2820, 0x3405):
        v = vectors[f"fx5-time-add/TADD/error-registers/{code:04X}H-before/valid"]
        assert v["initial"]["devices"]["SD0"] == code and v["initial"]["devices"]["SD8067"] == code
        assert v["final"]["devices"]["SD0"] == code and v["final"]["devices"]["SD8067"] == code
        assert "SD0" not in v["steps"][0]["expect"]["devices"]
        # The addition itself happened: 11:29:29 + 11:29:29 (the middle of each range) = 22:58:58.
        assert v["final"]["devices"]["D300"] == 22 and v["final"]["devices"]["D301"] == 58


def test_hour_d1_out_of_range(golden):
    vectors = by_id(golden, "fc6a-hour-meter")
    v = vectors["fc6a-hour-meter/HOUR/measured-out-of-range/minute=75/1000ms"]
    # 0:75:00 is 4500 s; one second more is 4501 s = 1:15:01, which reaches the preset 1:00:00.
    assert [v["final"]["devices"][d] for d in ("D200", "D201", "D202")] == [1, 15, 1]
    assert v["final"]["devices"]["M10"] is True
    err = alternative(v, HOUR_D1_OUT_OF_RANGE="error", HOUR_FIRST_SCAN="counts")
    assert err["expect"][0]["devices"] == {"M8004": True}
    v = vectors["fc6a-hour-meter/HOUR/measured-out-of-range/second=75/500ms"]
    # No whole second added, but D1 is written back in range: 75 s = 0:01:15.
    assert v["steps"][0]["expect"]["devices"] == {"D201": 1, "D202": 15}


def test_hour_one_long_step_wraps(golden):
    v = by_id(golden, "fc6a-hour-meter")["fc6a-hour-meter/HOUR/wrap/one-long-step"]
    # 65535:00:00 + 7,200 s passes 65535:59:59 and returns through 0:00:00 to 1:00:00.
    assert v["initial"]["devices"]["D200"] == 65535 and v["steps"][0]["elapsed_ms"] == 7_200_000
    assert [v["final"]["devices"][d] for d in ("D200", "D201", "D202")] == [1, 0, 0]
    assert v["final"]["devices"]["M10"] is True


def test_hour_output_relay(golden):
    vectors = by_id(golden, "fc6a-hour-meter")
    v = vectors["fc6a-hour-meter/HOUR/output-relay/reach"]
    assert v["initial"]["operands"]["D2"] == {"device": "Q0"}
    assert [s["expect"]["devices"].get("Q0") for s in v["steps"]] == [None, True, None]   # reached at 2 s
    v = vectors["fc6a-hour-meter/HOUR/output-relay/invalid-preset"]
    assert v["steps"][0]["expect"]["devices"]["Q0"] is False and v["steps"][0]["expect"]["devices"]["M8004"] is True


def test_hour_error_flag_with_the_input_off(golden):
    v = by_id(golden, "fc6a-hour-meter")["fc6a-hour-meter/HOUR/invalid-preset/minute=60/input-off"]
    assert v["steps"][0]["expect"]["devices"] == {}
    every = alternative(v, HOUR_PRESET_CHECK="every-execution", HOUR_INPUT_OFF="hold")
    assert every["expect"][0]["devices"] == {"M8004": True, "M10": False}


def test_cp1e_operands_at_the_top_of_their_area(golden):
    vectors = by_id(golden, "cp1e-time-compare")
    for op, head in (("S1", "D8189"), ("S2", "D8189"), ("C", "D8191")):
        v = vectors[f"cp1e-time-compare/LD >DT/device-range/{op}={head}"]
        assert v["initial"]["operands"][op] == {"device": head}
        assert v["steps"][0]["expect"]["result"] is True
