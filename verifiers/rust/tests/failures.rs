//! How a failure reads: the vector id, the step, the device, expected and actual, the
//! alternatives it was judged by and the spec clauses. The manual's TADD example program adds
//! 3:10:05 to 10:30:10 and stores 13:40:15 in D30..D32.

use plcvec::{Execute, Memory, OnMemory, Refusal, Selection, Status, Step, Suite, Value, Vector};

const MANUAL_EXAMPLE: &str = "fx5-time-add/TADD/manual-example/program";

/// Writes the manual's result with one wrong minute, and a word past the vector.
struct OffByOneMinute {
    outside: bool,
}

impl Execute for OffByOneMinute {
    fn execute(&mut self, vector: &Vector, _: &Step, memory: &mut Memory<'_>) -> Result<Option<bool>, Refusal> {
        let d = vector.operand("d").and_then(|o| o.device()).ok_or_else(|| Refusal::Error("no d".into()))?.clone();
        for (offset, word) in [13, 41, 15].into_iter().enumerate() {
            memory.set_word(&d, offset as u32, word);
        }
        if self.outside {
            memory.set_word(&d, 3, 0);
        }
        Ok(None)
    }
}

fn only_the_manual_example() -> Selection {
    Selection::all().id_glob(MANUAL_EXAMPLE).unwrap()
}

#[test]
fn a_wrong_word_reads_as_a_field_diff() {
    let suite = Suite::embedded().unwrap();
    let mut implementation = OnMemory(OffByOneMinute { outside: false });
    let report = plcvec::run(&suite, &mut implementation, &only_the_manual_example(), None).unwrap();
    assert!(!report.passed());
    let (vector, verdict) = report.failures().next().unwrap();
    assert_eq!(vector.id(), MANUAL_EXAMPLE);
    assert_eq!(verdict.status, Status::Fail);
    assert_eq!(verdict.problems.len(), 1);
    assert_eq!(verdict.problems[0].to_string(), "step 0 D31: expected 40, got 41 (before the step: 65535)");
    let summary = report.summary();
    assert!(summary.starts_with(&format!("FAIL {MANUAL_EXAMPLE}\n    TADD: 10:30:10 + 03:10:05")), "{summary}");
    assert!(summary.contains("    step 0 D31: expected 40, got 41 (before the step: 65535)\n"), "{summary}");
    assert!(summary.contains("    spec clauses: fx5-time-add#data-type, "), "{summary}");
    assert!(summary.contains("1 vectors: 0 pass, 1 fail"), "{summary}");
}

#[test]
fn a_write_outside_the_vector_is_reported() {
    let suite = Suite::embedded().unwrap();
    let mut implementation = OnMemory(OffByOneMinute { outside: true });
    let report = plcvec::run(&suite, &mut implementation, &only_the_manual_example(), None).unwrap();
    let (_, verdict) = report.failures().next().unwrap();
    let lines: Vec<String> = verdict.problems.iter().map(|p| p.to_string()).collect();
    assert!(lines.contains(&"step 0 D33: expected <not in the vector>, got 0".to_owned()), "{lines:?}");
}

#[test]
fn a_bit_reported_as_a_word_fails() {
    // SM700 is a bit: the word 0 is not `false`.
    struct WordFlags;
    impl plcvec::Implementation for WordFlags {
        fn run(&mut self, vector: &Vector, steps: &mut plcvec::Steps<'_>) -> Result<(), Refusal> {
            let mut devices: Vec<(&str, Value)> =
                vector.devices().iter().map(|a| a.name()).zip(vector.initial().iter().copied()).collect();
            for (name, value) in devices.iter_mut() {
                *value = match (*name, *value) {
                    ("D30", _) => Value::Word(13),
                    ("D31", _) => Value::Word(40),
                    ("D32", _) => Value::Word(15),
                    ("SM700", Value::Bit(b)) => Value::Word(u16::from(b)),
                    (_, v) => v,
                };
            }
            steps.devices(None, devices);
            Ok(())
        }
    }
    let suite = Suite::embedded().unwrap();
    let report = plcvec::run(&suite, &mut WordFlags, &only_the_manual_example(), None).unwrap();
    let (_, verdict) = report.failures().next().unwrap();
    let lines: Vec<String> = verdict.problems.iter().map(|p| p.to_string()).collect();
    assert_eq!(lines, ["step 0 SM700: expected false, got 0 (the step must leave it unchanged)"]);
}

#[test]
fn a_panic_is_an_error_on_its_vector() {
    struct Panics;
    impl plcvec::Implementation for Panics {
        fn run(&mut self, _: &Vector, _: &mut plcvec::Steps<'_>) -> Result<(), Refusal> {
            panic!("index out of bounds")
        }
    }
    let suite = Suite::embedded().unwrap();
    let report = plcvec::run(&suite, &mut Panics, &only_the_manual_example(), None).unwrap();
    let (_, verdict) = report.failures().next().unwrap();
    assert_eq!(verdict.status, Status::Error);
    assert_eq!(verdict.message, "the implementation panicked: index out of bounds");
}
