//! The one failure text (verifiers/parity/TEXT.md): the shared cases of verifiers/parity/text/
//! judged by the plcvec crate's loading, comparison and text (its public API, as every test of
//! this crate reaches it), byte for byte against the expected text every plcvec runner must print.

use std::collections::BTreeMap;
use std::path::Path;

use plcvec::{Choices, Implementation, KnownFailures, Refusal, Selection, Steps, Suite, Value, Vector};

/// Answers each vector as `answers.json` says, declaring what its `hello` declares.
struct Answers {
    hello: serde_json::Value,
    answers: BTreeMap<String, serde_json::Value>,
}

impl Implementation for Answers {
    fn name(&self) -> String {
        self.hello["adapter"]["name"].as_str().unwrap_or("").to_owned()
    }
    fn interpretations(&self) -> Choices {
        let declared = self.hello["interpretations"].as_object().cloned().unwrap_or_default();
        declared.iter().map(|(i, a)| (i.as_str(), a.as_str().unwrap_or(""))).collect()
    }
    fn supports(&self, instruction: &str) -> bool {
        self.hello["instructions"].as_array().is_some_and(|list| list.iter().any(|i| i == instruction))
    }
    fn cpu_writes(&self) -> Vec<String> {
        let list = self.hello["cpu_writes"].as_array().cloned().unwrap_or_default();
        list.iter().filter_map(|d| d.as_str().map(str::to_owned)).collect()
    }
    fn run(&mut self, vector: &Vector, steps: &mut Steps<'_>) -> Result<(), Refusal> {
        let answer = &self.answers[vector.id()];
        if let Some(why) = answer.get("skip").and_then(|w| w.as_str()) {
            return Err(Refusal::Skip(why.to_owned()));
        }
        if let Some(why) = answer.get("error").and_then(|w| w.as_str()) {
            return Err(Refusal::Error(why.to_owned()));
        }
        for step in answer["steps"].as_array().expect("steps") {
            let devices = step["devices"].as_object().expect("devices");
            let values: Vec<(&str, Value)> = devices
                .iter()
                .map(|(n, v)| (n.as_str(), Value::from_json(v).expect("a bit or a word in the shared cases")))
                .collect();
            steps.devices(step.get("result").and_then(|r| r.as_bool()), values);
        }
        Ok(())
    }
}

/// The shared cases' run (verifiers/parity/text), with the known failures of `known.toml` when
/// `known`, in the text of that run that does not depend on the machine.
fn shared_text(known: bool) -> (String, String) {
    // The shared cases are the repository's: this test lives in the unpublished reference crate
    // for that reason. Without them there is nothing to compare, which is a failure, not a pass.
    let text = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../parity/text");
    assert!(text.is_dir(), "{}: the shared cases are not there", text.display());
    let suite = Suite::load(text.join("vectors")).unwrap();
    let answers: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(text.join("answers.json")).unwrap()).unwrap();
    let mut implementation = Answers {
        hello: answers["hello"].clone(),
        answers: answers["answers"].as_object().unwrap().clone().into_iter().collect(),
    };
    // The file as the expected text names it: `known.toml`, from the folder of the cases.
    let known = known.then(|| {
        KnownFailures::parse("known.toml", &std::fs::read_to_string(text.join("known.toml")).unwrap()).unwrap()
    });
    let report = plcvec::run(&suite, &mut implementation, &Selection::all(), known.as_ref()).unwrap();
    let expected = if known.is_some() { "expected-known.txt" } else { "expected.txt" };
    let expected = std::fs::read_to_string(text.join(expected)).unwrap();
    // The shared text carries `plcvec verify`'s declarations (`--choose`); this crate's own form
    // is checked against TEXT.md's table below.
    (report.text_as_plcvec_verify(false, None), expected)
}

fn assert_same(got: &str, expected: &str) {
    if got != expected {
        let first = got.lines().zip(expected.lines()).position(|(g, e)| g != e);
        panic!(
            "the text differs from expected.txt (first at line {:?}):\n--- got\n{got}\n--- expected\n{expected}",
            first.map(|n| n + 1)
        );
    }
}

#[test]
fn the_shared_cases_read_byte_for_byte_as_the_expected_text() {
    let (got, expected) = shared_text(false);
    assert!(got.len() > 1000 && got.contains("READINGS: 3 of 14"), "{got}");
    assert_same(&got, &expected);
}

#[test]
fn the_shared_cases_with_their_known_failures_read_as_the_expected_text() {
    let (got, expected) = shared_text(true);
    assert!(got.contains("KNOWN FAILURES: 1 of 2 known failures"), "{got}");
    assert_same(&got, &expected);
}

#[test]
fn the_declaration_is_the_one_text_md_gives_for_rust() {
    // TEXT.md, "The declaration in each runner": the row for Rust, read from the page itself.
    let page = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../parity/TEXT.md");
    let page = std::fs::read_to_string(&page).unwrap_or_else(|e| panic!("{}: {e}", page.display()));
    let row = page.lines().find(|l| l.starts_with("| Rust |")).expect("TEXT.md has a row for Rust");
    let cell = row.trim_start_matches("| Rust |").trim().trim_end_matches('|').trim();
    let declared = cell.trim_matches('`');
    assert!(declared.starts_with("plcvec::Choices::new()"), "{row}");
    let ours = plcvec::Report::declaration(&[("FX5-SM709-SCOPE", "all-words"), ("TADD-FLAGS-OFF", "set-only")]);
    assert_eq!(ours, declared);
}
