//! Devices an alternative leaves unjudged (schema 1.1, the vector's alternatives' `unjudged`): not
//! compared under that alternative, named in the failure block, and weighed by the inference.
//! A hand-made HOUR vector: D1 (D200..D202) holds a minute of 75; the default reading counts it
//! as seconds and rewrites D1, the `error` reading turns M8004 on and leaves D1 and D2 (M10)
//! unjudged.

use plcvec::{Choices, Implementation, Refusal, Selection, Status, Steps, Suite, Value, Vector};

const HEADER: &str = r#"{"family": "fc6a-hour-meter", "kind": "hour_meter", "schema_version": "1.1.0", "interpretations": [{"id": "HOUR-D1-OUT-OF-RANGE", "question": "q", "default": "as-seconds", "alternatives": [{"id": "as-seconds", "says": "s"}, {"id": "error", "says": "e"}]}]}"#;
const VECTOR: &str = r#"{"id": "fc6a-hour-meter/HOUR/d1-out-of-range", "family": "fc6a-hour-meter", "instruction": "HOUR", "description": "D1 holds minute 75.", "clauses": ["fc6a-hour-meter#d1"], "initial": {"devices": {"D200": 0, "D201": 75, "D202": 0, "M10": false, "M8004": false}, "operands": {"D1": {"device": "D200"}, "D2": {"device": "M10"}, "S1": {"constant": 5}}}, "steps": [{"input": true, "elapsed_ms": 0, "expect": {"devices": {"D200": 1, "D201": 15}}}], "final": {"devices": {"D200": 1, "D201": 15, "D202": 0, "M10": false, "M8004": false}}, "outcome": {"category": "implementation-defined", "interpretations": ["HOUR-D1-OUT-OF-RANGE"], "default": {"category": "value"}}, "alternatives": [{"choices": {"HOUR-D1-OUT-OF-RANGE": "error"}, "expect": [{"devices": {"M8004": true}}], "final": {"devices": {"M8004": true}}, "outcome": {"category": "error"}, "unjudged": {"HOUR-D1-OUT-OF-RANGE": ["D200", "D201", "D202", "M10"]}}]}"#;
const ID: &str = "fc6a-hour-meter/HOUR/d1-out-of-range";

fn suite() -> Suite {
    // One folder per call: the tests run at once.
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("plcvec-unjudged-{}-{call}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("fc6a-hour-meter.jsonl");
    std::fs::write(&file, format!("{HEADER}\n{VECTOR}\n")).unwrap();
    let suite = Suite::load(&file).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    suite
}

/// Answers the `error` reading: M8004 on, D1 overwritten with `d1` (which that reading does not
/// judge), and a write outside the vector when `stray`.
struct ErrorReading {
    declares: bool,
    m8004: bool,
    d1: u16,
    stray: bool,
}

impl Implementation for ErrorReading {
    fn interpretations(&self) -> Choices {
        if self.declares {
            [("HOUR-D1-OUT-OF-RANGE", "error")].into_iter().collect()
        } else {
            Choices::new()
        }
    }
    fn run(&mut self, _: &Vector, steps: &mut Steps<'_>) -> Result<(), Refusal> {
        let mut devices = vec![
            ("D200", Value::Word(self.d1)),
            ("D201", Value::Word(self.d1)),
            ("D202", Value::Word(0)),
            ("M10", Value::Bit(true)),
            ("M8004", Value::Bit(self.m8004)),
        ];
        if self.stray {
            devices.push(("D7777", Value::Word(1)));
        }
        steps.devices(None, devices);
        Ok(())
    }
}

fn run(implementation: ErrorReading) -> (Status, String) {
    let suite = suite();
    let mut implementation = implementation;
    let report = plcvec::run(&suite, &mut implementation, &Selection::all(), None).unwrap();
    (report.verdict(ID).unwrap().status, report.summary())
}

#[test]
fn devices_left_unjudged_are_not_compared() {
    // D1 and D2 hold anything under `error`: only M8004 is judged.
    let (status, text) = run(ErrorReading { declares: true, m8004: true, d1: 9999, stray: false });
    assert_eq!(status, Status::Pass, "{text}");
}

#[test]
fn the_block_says_what_is_not_judged_and_a_stray_write_still_fails() {
    let (status, text) = run(ErrorReading { declares: true, m8004: true, d1: 9999, stray: true });
    assert_eq!(status, Status::Fail, "{text}");
    let block = format!(
        "FAIL {ID}\n    HOUR: D1 holds minute 75.\n    not judged under HOUR-D1-OUT-OF-RANGE=error: D200, D201, D202, M10\n    \
         step 0 inputs: input=true, elapsed_ms=0\n    step 0 operands: D1 D200=0 75 0, D2 M10=false, S1 constant 5\n    \
         step 0 D7777: expected <not in the vector>, got 1\n"
    );
    assert!(text.starts_with(&block), "{text}");
}

#[test]
fn a_judged_device_that_differs_names_the_reading_that_decides_it() {
    // M8004 off under `error`: the default reading expects it off, so it decides the field.
    let (status, text) = run(ErrorReading { declares: true, m8004: false, d1: 0, stray: false });
    assert_eq!(status, Status::Fail, "{text}");
    assert!(text.contains("    judged by: HOUR-D1-OUT-OF-RANGE=error\n    not judged under HOUR-D1-OUT-OF-RANGE=error: D200, D201, D202, M10\n"), "{text}");
    assert!(text.contains("    step 0 M8004: expected true, got false (before the step: false)\n"), "{text}");
}

#[test]
fn the_inference_explains_an_answer_that_follows_the_reading_undeclared() {
    // Declaring nothing (the default, as-seconds), answering as `error` does: D200 and D201 differ
    // from the default's expectation, but the `error` reading leaves them unjudged (so it decides
    // them) and expects M8004 on, so the vector passes under it.
    let (status, text) = run(ErrorReading { declares: false, m8004: true, d1: 9999, stray: false });
    assert_eq!(status, Status::Fail, "{text}");
    assert!(text.contains("    judged by: HOUR-D1-OUT-OF-RANGE=as-seconds\n"), "{text}");
    assert!(!text.contains("not judged under"), "the default leaves nothing unjudged: {text}");
    assert!(
        text.contains(
            "READINGS: 1 of 1 failing vectors pass under other alternatives:\n         1  HOUR-D1-OUT-OF-RANGE=error\n"
        ),
        "{text}"
    );
    assert!(
        text.contains("    declare: plcvec::Choices::new().with(plcvec::names::HourD1OutOfRange::Error)\n"),
        "{text}"
    );
}

/// `FamilyInfo`, the header's name before 0.3.0, still names the same header (until 0.4.0).
#[test]
#[allow(deprecated)]
fn the_header_reads_the_same_by_its_old_name() {
    let suite = suite();
    let old: Option<&plcvec::FamilyInfo> = suite.family("fc6a-hour-meter");
    let new: Option<&plcvec::FamilyHeader> = suite.family("fc6a-hour-meter");
    let old = old.expect("the hand-made file's family");
    assert_eq!(old, new.unwrap());
    assert_eq!((old.kind.as_str(), old.schema_version.as_str()), ("hour_meter", "1.1.0"));
    assert_eq!(old.interpretations[0].default, "as-seconds");
}
