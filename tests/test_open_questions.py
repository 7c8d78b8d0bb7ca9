"""The questions the pages leave open are named, and the vectors that ask them hold what the pages and
the readings say: each expected value below is worked out by hand from the manual page and the
alternative's wording, not read from the generator."""
import pytest

# The interpretations fixed for every implementation (id, family, alternatives with the default first).
NAMED = [
    ("CP1E-ERROR-FLAGS", "cp1e-time-compare", ["kept", "off"]),
    ("HOUR-FIRST-SCAN", "fc6a-hour-meter", ["counts", "from-next-scan", "after-cpu-start"]),
    ("FX5-OR-ON-ERROR", "fx5-time-compare", ["contact-off", "result-off"]),
    ("FX5-OR-ON-ERROR", "fx5-date-compare", ["contact-off", "result-off"]),
    ("HOUR-PRESET-CHECK", "fc6a-hour-meter", ["input-on", "every-execution"]),
    ("HOUR-M8004-OFF", "fc6a-hour-meter", ["never", "valid-preset"]),
    ("TADD-ERROR-ORDER", "fx5-time-add", ["device-range-first", "field-range-first"]),
    ("HOUR-D1-OUT-OF-RANGE", "fc6a-hour-meter", ["as-seconds", "error", "as-seconds-if-added", "by-field", "undefined"]),
    ("HOUR-WRAP-REACH", "fc6a-hour-meter", ["after-wrap", "before-wrap"]),
    ("HOUR-M8004-REPEAT", "fc6a-hour-meter", ["every-check", "once"]),
    ("HOUR-D2-SPECIAL", "fc6a-hour-meter", ["accepted", "error", "undefined"]),
    ("HOUR-S1-CONSTANT-RANGE", "fc6a-hour-meter", ["error", "as-is", "low-16-bits", "undefined"]),
    ("TADD-OVERLAP", "fx5-time-add", ["sources-first", "second-first", "hour-first"]),
    ("FX5-INVALID-S3-DEVICE-RANGE", "fx5-time-compare", ["device-range-first", "s3-first"]),
    ("FX5-INVALID-S3-DEVICE-RANGE", "fx5-date-compare", ["device-range-first", "s3-first"]),
    ("CP1E-PAST-AREA-END", "cp1e-time-compare", ["error", "program-error"]),
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


def _changes(entry):
    return [e["devices"] for e in entry["expect"]]


def test_hour_d1_out_of_range_counted_word_by_word(golden):
    """HOUR-D1-OUT-OF-RANGE=by-field, worked from its `says`: the second word counts 60, 61, ... and
    carries only when it becomes exactly 60; 65535 + 1 is 0 with no carry; S1 (1:00:00 here) is
    compared hour first, so 0:75:xx stays below it and D2 stays off."""
    vectors = by_id(golden, "fc6a-hour-meter")
    base = "fc6a-hour-meter/HOUR/measured-out-of-range/"
    worked = {
        "second=60/1000ms": [{"D202": 61}],                  # 0:00:60 + 1 s = 0:00:61
        "minute=75/1000ms": [{"D202": 1}],                   # 0:75:00 + 1 s = 0:75:01, below 1:00:00
        "second=65535/2000ms": [{"D202": 1}],                # 65535 -> 0 (no carry) -> 1
        "minute=65535/1000ms": [{"D202": 1}],                # 0:65535:00 + 1 s = 0:65535:01
        "minute=75,second=59/1000ms": [{"D201": 76, "D202": 0}],   # the second carries into the minute
        "second=75/500ms": [{}],                             # no whole second: nothing changes
    }
    for key, changes in worked.items():
        v = vectors[base + key]
        assert _changes(alternative(v, HOUR_D1_OUT_OF_RANGE="by-field", HOUR_FIRST_SCAN="counts")
                        if "HOUR-FIRST-SCAN" in v["outcome"]["interpretations"]
                        else alternative(v, HOUR_D1_OUT_OF_RANGE="by-field")) == changes, key
    # as-seconds for the same words: 65535 s = 18:12:15, + 2 s = 18:12:17, past 1:00:00 (D2 on).
    v = vectors[base + "second=65535/2000ms"]
    assert v["steps"][0]["expect"]["devices"] == {"D200": 18, "D201": 12, "D202": 17, "M10": True}


def test_hour_d1_out_of_range_written_only_when_a_second_is_added(golden):
    vectors = by_id(golden, "fc6a-hour-meter")
    v = vectors["fc6a-hour-meter/HOUR/measured-out-of-range/second=75/500ms"]
    assert _changes(alternative(v, HOUR_D1_OUT_OF_RANGE="as-seconds-if-added")) == [{}]   # 0:00:75 stays
    v = vectors["fc6a-hour-meter/HOUR/measured-out-of-range/second=60/1000ms"]
    # 60 s + 1 s = 61 s = 0:01:01, written since a second was added.
    assert _changes(alternative(v, HOUR_D1_OUT_OF_RANGE="as-seconds-if-added", HOUR_FIRST_SCAN="counts")) == [
        {"D201": 1, "D202": 1}]


def test_hour_wrap_that_passes_the_preset(golden):
    """65535:59:58 + 2 s wraps to 0:00:00 in the execution that passes the preset 65535:59:59: after-wrap
    compares 0:00:00 (below, D2 stays off); before-wrap compares the count before the wrap (D2 on)."""
    v = by_id(golden, "fc6a-hour-meter")["fc6a-hour-meter/HOUR/wrap/reach-while-wrapping"]
    assert _changes({"expect": [s["expect"] for s in v["steps"]]}) == [{"D200": 0, "D201": 0, "D202": 0}, {"D202": 1}]
    before = alternative(v, HOUR_WRAP_REACH="before-wrap", HOUR_FIRST_SCAN="counts")
    assert _changes(before) == [{"D200": 0, "D201": 0, "D202": 0, "M10": True}, {"D202": 1}]
    # D2 was on when D1 wrapped: recompared keeps it on at 0:00:01.
    assert before["final"]["devices"]["M10"] is True


def test_hour_error_flag_reported_once(golden):
    v = by_id(golden, "fc6a-hour-meter")["fc6a-hour-meter/HOUR/error-flag/minute=60/cleared-by-program"]
    # every-check: on, on again after the program cleared it, still on.
    assert [s["expect"]["devices"].get("M8004") for s in v["steps"]] == [True, True, None]
    once = alternative(v, HOUR_M8004_REPEAT="once", HOUR_FIRST_SCAN="counts")
    assert [e["devices"].get("M8004") for e in once["expect"]] == [True, None, None]
    assert once["final"]["devices"]["M8004"] is False


def test_hour_first_scan_after_cpu_start(golden):
    """1.5 s on, 5 s off, 1.5 s on, preset 3 s: counts adds 1.5 + 1.5 (3 s, D2 on); from-next-scan adds
    nothing at either turn-on; after-cpu-start nothing at step 0 and 1.5 s at step 2 (1 s whole)."""
    v = by_id(golden, "fc6a-hour-meter")["fc6a-hour-meter/HOUR/input/off-on-off"]
    assert v["final"]["devices"]["D202"] == 3 and v["final"]["devices"]["M10"] is True
    later = alternative(v, HOUR_FIRST_SCAN="after-cpu-start", HOUR_INPUT_OFF="hold")
    assert _changes(later) == [{}, {}, {"D202": 1}]
    assert _changes(alternative(v, HOUR_FIRST_SCAN="from-next-scan", HOUR_INPUT_OFF="hold")) == [{}, {}, {}]


def test_hour_constant_above_its_range(golden):
    """65537 hours: an invalid preset (default), 65537:00:00 as it is (never reached), or 1 hour in
    its low 16 bits (reached by 0:59:59 + 1 s)."""
    v = by_id(golden, "fc6a-hour-meter")["fc6a-hour-meter/HOUR/constant/above-range/65537"]
    assert v["initial"]["operands"]["S1"] == {"constant": 65537}
    assert v["steps"][0]["expect"]["devices"] == {"D200": 1, "D201": 0, "D202": 0, "M8004": True}
    low = alternative(v, HOUR_S1_CONSTANT_RANGE="low-16-bits", HOUR_FIRST_SCAN="counts")
    assert _changes(low) == [{"D200": 1, "D201": 0, "D202": 0, "M10": True}, {"D202": 1}]
    assert _changes(alternative(v, HOUR_S1_CONSTANT_RANGE="as-is", HOUR_FIRST_SCAN="counts")) == [
        {"D200": 1, "D201": 0, "D202": 0}, {"D202": 1}]


def test_hour_special_relay_as_d2(golden):
    v = by_id(golden, "fc6a-hour-meter")["fc6a-hour-meter/HOUR/special-relay/reach"]
    assert v["initial"]["operands"]["D2"] == {"device": "M8003"}
    assert [s["expect"]["devices"].get("M8003") for s in v["steps"]] == [None, True, None]   # 2 s reached
    error = alternative(v, HOUR_D2_SPECIAL="error", HOUR_FIRST_SCAN="counts")
    assert _changes(error) == [{"D202": 1, "M8004": True}, {"D202": 2}, {"D202": 3}]        # never written
    undefined = alternative(v, HOUR_D2_SPECIAL="undefined", HOUR_FIRST_SCAN="counts")
    assert undefined["unjudged"] == {"HOUR-D2-SPECIAL": ["D200", "D201", "D202", "M8003", "M8004"]}


NEW = ["HOUR-D1-OUT-OF-RANGE", "HOUR-WRAP-REACH", "HOUR-M8004-REPEAT", "HOUR-D2-SPECIAL",
       "HOUR-S1-CONSTANT-RANGE", "HOUR-FIRST-SCAN"]


@pytest.mark.parametrize("iid", NEW)
def test_every_two_alternatives_are_told_apart_by_some_vector(iid, golden, families):
    """Each pair of alternatives of the interpretation expects something different of some vector
    (other interpretations at their defaults): a value, or a device one of them leaves unjudged."""
    defaults = families["fc6a-hour-meter"].default_choices()
    alternatives = [a["id"] for a in families["fc6a-hour-meter"].interpretations[iid]["alternatives"]]

    def expectation(v, alt):
        touched = v["outcome"].get("interpretations", [])
        choice = {i: (alt if i == iid else defaults[i]) for i in touched}
        if all(choice[i] == defaults[i] for i in touched):
            return [s["expect"] for s in v["steps"]], v["final"]["devices"], {}
        e = next(a for a in v["alternatives"] if a["choices"] == choice)
        return e["expect"], e["final"]["devices"], e.get("unjudged", {})

    vectors = [v for v in golden["fc6a-hour-meter"]["vectors"] if iid in v["outcome"].get("interpretations", [])]
    for x, a in enumerate(alternatives):
        for b in alternatives[x + 1:]:
            assert any(expectation(v, a) != expectation(v, b) for v in vectors), (iid, a, b)
def _words(vector, head, count=3, expect=None):
    devices = (expect or vector)["final"]["devices"]
    prefix, at = head[0], int(head[1:])
    return [devices[f"{prefix}{at + k}"] for k in range(count)]


def test_tadd_overlap_reads_what_each_reading_says(golden):
    """(s1) = 11:30:30 in D100-D102, (s2) = 15:39:39 in D200-D202; the sum 27:10:09 wraps to 3:10:09
    with carry. (d) one or two words off a source, worked word by word from the alternatives' wording."""
    vectors = by_id(golden, "fx5-time-add")
    v = vectors["fx5-time-add/TADD/overlap/d=s1+1"]
    assert v["initial"]["operands"]["d"] == {"device": "D101"}
    assert _words(v, "D100", 1) + [v["initial"]["devices"][d] for d in ("D101", "D102")] == [11, 30, 30]
    # sources-first: D101-D103 = 3:10:09, carry on.
    assert _words(v, "D101") == [3, 10, 9] and v["final"]["devices"]["SM700"] is True
    # second-first: D103 <- 30+39 = 69 -> 9 carry 1; D102 <- 30+39+1 = 70 -> 10 carry 1 (D102, (s1)+2, was
    # read already); D101 <- 11+15+1 = 27 -> 3: the same as sources-first.
    assert _words(v, "D101", expect=alternative(v, TADD_OVERLAP="second-first")) == [3, 10, 9]
    # hour-first: D101 <- 11+15 = 26; (s1)+1 is D101, now 26: D102 <- 26+39 = 65; (s1)+2 is D102, now 65:
    # D103 <- 65+39 = 104; 26:65:104 = 97,604 s, less 86,400 = 11,204 s = 3:06:44, carry on.
    hour_first = alternative(v, TADD_OVERLAP="hour-first")
    assert _words(v, "D101", expect=hour_first) == [3, 6, 44] and hour_first["final"]["devices"]["SM700"] is True

    v = vectors["fx5-time-add/TADD/overlap/d=s1-1"]
    assert _words(v, "D99") == [3, 10, 9]
    # second-first: D101 <- 30+39 = 69 -> 9 carry 1; (s1)+1 is D101, now 9: D100 <- 9+39+1 = 49 carry 0;
    # (s1) is D100, now 49: D99 <- (49+15) mod 24 = 16. The words as read, 64:48:69, pass 24:00:00: carry.
    second_first = alternative(v, TADD_OVERLAP="second-first")
    assert _words(v, "D99", expect=second_first) == [16, 49, 9] and second_first["final"]["devices"]["SM700"] is True
    # hour-first: D99 <- 26, D100 <- 30+39 = 69, D101 <- 30+39 = 69, each source word read before it is
    # written; 26:69:69 = 3:10:09 after the wrap, as sources-first.
    assert _words(v, "D99", expect=alternative(v, TADD_OVERLAP="hour-first")) == [3, 10, 9]

    v = vectors["fx5-time-add/TADD/overlap/d=s2-2"]
    assert v["initial"]["devices"]["SM700"] is False and _words(v, "D198") == [3, 10, 9]
    # second-first: D200 <- 9 carry 1 (D200 is (s2)); D199 <- 30+39+1 = 70 -> 10 carry 1; D198 <- 11+9+1 = 21.
    # The words as read, 20:69:69 = 76,209 s, stay below 24:00:00: no carry, the flags stay off.
    second_first = alternative(v, TADD_OVERLAP="second-first")
    assert _words(v, "D198", expect=second_first) == [21, 10, 9]
    assert second_first["expect"][0]["devices"] == {"D198": 21, "D199": 10, "D200": 9}


def test_tadd_same_device_is_alike_under_every_overlap_reading(golden):
    """(d) = (s1) shares every word at the same offset: each source word is read before its own word of
    (d) is written under every reading, so TADD-OVERLAP does not touch those vectors."""
    for v in golden["fx5-time-add"]["vectors"]:
        if "/same-device/" in v["id"] or "aliasing=s1=d" in v["id"] or "aliasing=s2=d" in v["id"]:
            assert "TADD-OVERLAP" not in v["outcome"].get("interpretations", []), v["id"]


def test_fx5_invalid_s3_with_an_operand_past_the_device_range(golden):
    """D holds 8000 points (D0 to D7999): (s1) or (s2) at D7998 has its third word past D7999, which turns
    SM709 on. (s3) = 0000H selects no field, 0008H sets reserved bit 3 alone, 4004H the top field with
    reserved bit 14: each gives non-continuity. SM709 is off before; the LD form's contact is the result.
    The vectors are the coverage model's rows for these selector classes with each operand past its range."""
    for family, form in (("fx5-time-compare", "LDTM"), ("fx5-date-compare", "LDDT")):
        vectors = by_id(golden, family)
        for symbol, selector, op, s3 in (("=", "reserved", "s1", 0x0008), (">=", "none", "s1", 0x0000),
                                         ("=", "reserved+fields", "s2", 0x4004), ("<", "none", "s2", 0x0000)):
            v = vectors[f"{family}/{form}{symbol}/model/selector={selector}/source=operands/ordering=none/"
                        f"data={op}.device-range/error-before=off"]
            assert v["initial"]["operands"][op] == {"device": "D7998"}, v["id"]
            assert v["initial"]["devices"]["D300"] == s3 and v["initial"]["devices"]["SM709"] is False
            # device-range-first: the device range turns SM709 on; non-continuity.
            assert v["steps"][0]["expect"] == {"devices": {"SM709": True}, "result": False}, v["id"]
            # s3-first: (s3) gives non-continuity before the range is looked at; SM709 keeps its value.
            s3_first = alternative(v, FX5_INVALID_S3_DEVICE_RANGE="s3-first")
            assert s3_first["expect"] == [{"devices": {}, "result": False}], v["id"]
        # A valid (s3) (0007H): the device range turns SM709 on under either order.
        v = vectors[f"{family}/{form}=/device-range/s1=D7999/0007H"]
        assert "FX5-INVALID-S3-DEVICE-RANGE" not in v["outcome"].get("interpretations", [])
        assert v["steps"][0]["expect"] == {"devices": {"SM709": True}, "result": False}


def test_cp1e_operand_past_the_end_of_the_data_area(golden):
    """D holds 8192 words (D0 to D8191). S1 or S2 at D8190 has S1+2 at D8192, at D8191 S1+1 and S1+2 past
    the end. The condition <>DT would conduct for any ordering a comparison found; the form's preceding
    logic lets the instruction decide (AND on, OR off). Before: P_ER off, the flags opposite of an equal
    result (P_NE, P_LT, P_GT on; P_EQ, P_LE, P_GE off)."""
    vectors = by_id(golden, "cp1e-time-compare")
    for form, rlo in (("LD", None), ("AND", True), ("OR", False)):
        for op, head in (("S1", "D8191"), ("S2", "D8190")):
            v = vectors[f"cp1e-time-compare/{form} <>DT/device-range/{op}={head}"]
            assert v["initial"]["operands"][op] == {"device": head} and v["steps"][0].get("rlo_in") == rlo
            assert v["initial"]["devices"]["P_ER"] is False
            # error: P_ER on, an OFF execution condition (AND: on AND off; OR: off OR off); the flags keep
            # their values (CP1E-ERROR-FLAGS=kept).
            assert v["steps"][0]["expect"] == {"devices": {"P_ER": True}, "result": False}, v["id"]
            # error with CP1E-ERROR-FLAGS=off: the three flags that were on are written off.
            off = alternative(v, CP1E_PAST_AREA_END="error", CP1E_ERROR_FLAGS="off")
            assert off["expect"] == [{"devices": {"P_ER": True, "P_GT": False, "P_LT": False, "P_NE": False},
                                      "result": False}]
            # program-error: not executed; nothing written, an OFF execution condition.
            for flags in ("kept", "off"):
                program = alternative(v, CP1E_PAST_AREA_END="program-error", CP1E_ERROR_FLAGS=flags)
                assert program["expect"] == [{"devices": {}, "result": False}], v["id"]
    # S1 at D8189 ends at the last word: compared as usual, the reading does not touch it.
    v = vectors["cp1e-time-compare/LD >DT/device-range/S1=D8189"]
    assert "CP1E-PAST-AREA-END" not in v["outcome"].get("interpretations", [])

