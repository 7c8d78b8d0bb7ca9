//! The reference follows each alternative of TADD-OVERLAP, FX5-INVALID-S3-DEVICE-RANGE and
//! CP1E-PAST-AREA-END: it runs one vector's operands and initial state under each alternative,
//! and the devices it leaves are checked against values worked by hand from the alternative's
//! text in the spec (the sums and carries are written out beside each case), not against the
//! vector's own expectations, which tests/reference.rs checks under every combination.

use plcvec::{Choices, Execute, Memory, Suite, Value};
use plcvec_reference::Reference;

/// Run the vector `id` with the reference under `choices`: its devices after the last step, and
/// the last step's result (a contact's logic state; none for TADD).
fn run(id: &str, choices: &[(&str, &str)]) -> (Memory<'static>, Option<bool>) {
    static SUITE: std::sync::OnceLock<Suite> = std::sync::OnceLock::new();
    let suite = SUITE.get_or_init(|| Suite::embedded().expect("the embedded vectors load"));
    let vector = suite.get(id).unwrap_or_else(|| panic!("the suite has no vector {id}"));
    let mut reference = Reference::with_choices(choices.iter().copied().collect::<Choices>());
    reference.begin(vector).unwrap();
    let mut memory = Memory::new(vector);
    let mut result = None;
    for step in vector.steps() {
        memory.apply_set(step);
        result = reference.execute(vector, step, &mut memory).unwrap();
    }
    (memory, result)
}

fn words(memory: &Memory<'_>, names: &[&str]) -> Vec<u16> {
    names
        .iter()
        .map(|n| match memory.get(n) {
            Some(Value::Word(w)) => w,
            other => panic!("{n} is no word: {other:?}"),
        })
        .collect()
}

fn bits(memory: &Memory<'_>, names: &[&str]) -> Vec<bool> {
    names.iter().map(|n| memory.bit(n)).collect()
}

const TADD_FLAGS: [&str; 3] = ["SM700", "SM8022", "SM8020"];

/// (s1) = D100 11:30:30, (s2) = D200 15:39:39; (d) = D198, two words below (s2), so (d)+2 is (s2).
#[test]
fn tadd_overlap_d_two_below_s2() {
    let id = "fx5-time-add/TADD/overlap/d=s2-2";
    let d = ["D198", "D199", "D200"];
    // sources-first: 11:30:30 + 15:39:39 = 27:10:09, past 24:00:00 -> 3:10:09, carry on.
    let (m, _) = run(id, &[("TADD-OVERLAP", "sources-first")]);
    assert_eq!((words(&m, &d), bits(&m, &TADD_FLAGS)), (vec![3, 10, 9], vec![true, true, false]));
    // second-first: 30 + 39 = 69 -> D200 = 9, carry 1; 30 + 39 + 1 = 70 -> D199 = 10, carry 1;
    // then the hour reads (s2) = D200, now 9: 11 + 9 + 1 = 21 -> D198 = 21. The sum as read is
    // 20:69:69 = 21:10:09, below 24:00:00: no carry, not zero.
    let (m, _) = run(id, &[("TADD-OVERLAP", "second-first")]);
    assert_eq!((words(&m, &d), bits(&m, &TADD_FLAGS)), (vec![21, 10, 9], vec![false, false, false]));
    // hour-first: 11 + 15 = 26 -> D198 before D200 is written, so as sources-first: 3:10:09.
    let (m, _) = run(id, &[("TADD-OVERLAP", "hour-first")]);
    assert_eq!((words(&m, &d), bits(&m, &TADD_FLAGS)), (vec![3, 10, 9], vec![true, true, false]));
}

/// (s1) = D100 11:30:30, (s2) = D200 15:39:39; (d) = D102, so (d) is (s1)+2.
#[test]
fn tadd_overlap_d_two_above_s1() {
    let id = "fx5-time-add/TADD/overlap/d=s1+2";
    let d = ["D102", "D103", "D104"];
    // sources-first and second-first (D102 is written last, after (s1)+2 is read): 3:10:09, carry.
    for order in ["sources-first", "second-first"] {
        let (m, _) = run(id, &[("TADD-OVERLAP", order)]);
        assert_eq!((words(&m, &d), bits(&m, &TADD_FLAGS)), (vec![3, 10, 9], vec![true, true, false]), "{order}");
    }
    // hour-first: D102 = 11 + 15 = 26; D103 = 30 + 39 = 69; then (s1)+2 = D102 reads 26:
    // 26 + 39 = 65. 26:69:65 = 27:10:05 -> 3:10:05, carry on.
    let (m, _) = run(id, &[("TADD-OVERLAP", "hour-first")]);
    assert_eq!((words(&m, &d), bits(&m, &TADD_FLAGS)), (vec![3, 10, 5], vec![true, true, false]));
}

/// (s3) = D300 = 0000H selects no field, (s2) = D7998 runs past D7999; SM709 is off before.
#[test]
fn fx5_invalid_s3_with_s2_past_the_device_range() {
    let id = "fx5-time-compare/LDTM</model/selector=none/source=operands/ordering=none/data=s2.device-range/error-before=off";
    // device-range-first: 'SM709 turns on ... and the operation result will be non-continuity'.
    let (m, result) = run(id, &[("FX5-INVALID-S3-DEVICE-RANGE", "device-range-first")]);
    assert_eq!((m.bit("SM709"), result), (true, Some(false)));
    // s3-first: the selector compares nothing, non-continuity; SM709 is not written.
    let (m, result) = run(id, &[("FX5-INVALID-S3-DEVICE-RANGE", "s3-first")]);
    assert_eq!((m.bit("SM709"), result), (false, Some(false)));
}

/// AND <>DT with rlo_in on; S2 = D8191, the last D word, so S2+1 and S2+2 are past the area; S1 and
/// S2 differ in the second. Before: P_NE, P_LT and P_GT on (no comparison leaves both of the last
/// two on, so a write shows), the other flags and P_ER off.
#[test]
fn cp1e_s2_past_the_area_end() {
    let id = "cp1e-time-compare/AND <>DT/device-range/S2=D8191";
    let flags = ["P_ER", "P_EQ", "P_NE", "P_LT", "P_LE", "P_GT", "P_GE"];
    // error: P_ER on, the other flags kept (CP1E-ERROR-FLAGS=kept), an OFF execution condition
    // that AND combines with rlo_in on: off, although S1 <> S2 would conduct.
    let (m, result) = run(id, &[("CP1E-PAST-AREA-END", "error")]);
    assert_eq!(bits(&m, &flags), [true, false, true, true, false, true, false]);
    assert_eq!(result, Some(false));
    // error with CP1E-ERROR-FLAGS=off: P_ER on, the six arithmetic flags off.
    let (m, result) = run(id, &[("CP1E-PAST-AREA-END", "error"), ("CP1E-ERROR-FLAGS", "off")]);
    assert_eq!(bits(&m, &flags), [true, false, false, false, false, false, false]);
    assert_eq!(result, Some(false));
    // program-error: not executed, nothing written (P_ER stays off whatever CP1E-ERROR-FLAGS and
    // CP1E-ER-FLAG say), an OFF execution condition.
    for error_flags in ["kept", "off"] {
        let (m, result) = run(id, &[("CP1E-PAST-AREA-END", "program-error"), ("CP1E-ERROR-FLAGS", error_flags)]);
        assert_eq!(bits(&m, &flags), [false, false, true, true, false, true, false], "{error_flags}");
        assert_eq!(result, Some(false));
    }
}
