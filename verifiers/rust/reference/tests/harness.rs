//! The cargo test harness: one test per vector, known failures as ignored tests, stale entries
//! and mutants as failing tests, and selections that select nothing refused.

use std::sync::atomic::{AtomicUsize, Ordering};

use plcvec::harness::{judged_nothing, Arguments, Conclusion, Harness};
use plcvec::{Choices, Implementation, KnownFailures, OnMemory, Selection, Suite};
use plcvec_reference::{Mutant, Reference};

/// Run a harness; its report goes to a log file (removed after), so that the nested runs'
/// deliberate failures do not read as this test's in the output.
fn conclude<I, F>(harness: Harness<F>) -> Conclusion
where
    I: Implementation + 'static,
    F: Fn() -> I + Send + Sync + 'static,
{
    static RUN: AtomicUsize = AtomicUsize::new(0);
    let n = RUN.fetch_add(1, Ordering::Relaxed);
    let log = std::env::temp_dir().join(format!("plcvec-rust-harness-{}-{n}.log", std::process::id()));
    let args = Arguments {
        quiet: true,
        test_threads: Some(2),
        logfile: Some(log.display().to_string()),
        ..Arguments::default()
    };
    let conclusion = harness.arguments(args).conclude().unwrap();
    let _ = std::fs::remove_file(&log);
    conclusion
}

fn tadd() -> Selection {
    Selection::all().family("fx5-time-add")
}

fn failing_ids(mutant: Mutant) -> Vec<String> {
    let suite = Suite::embedded().unwrap();
    let mut implementation = OnMemory(Reference::mutant(mutant, Choices::new()));
    let report = plcvec::run(&suite, &mut implementation, &tadd(), None).unwrap();
    report.failures().map(|(v, _)| v.id().to_owned()).collect()
}

#[test]
fn every_selected_vector_is_a_test() {
    let conclusion = conclude(Harness::new(|| OnMemory(Reference::new())).select(tadd()));
    let expected = tadd().apply(Suite::embedded().unwrap().vectors()).len() as u64;
    assert_eq!((conclusion.num_passed, conclusion.num_failed), (expected, 0));
}

#[test]
fn a_mutant_fails_exactly_the_vectors_that_catch_it() {
    let failing = failing_ids(Mutant::TaddpEveryScan);
    assert!(!failing.is_empty());
    let harness = Harness::new(|| OnMemory(Reference::mutant(Mutant::TaddpEveryScan, Choices::new()))).select(tadd());
    assert_eq!(conclude(harness).num_failed, failing.len() as u64);
}

#[test]
fn known_failures_are_ignored_and_stale_ones_fail() {
    let failing = failing_ids(Mutant::TaddSm8022NotWritten);
    let dir = std::env::temp_dir().join(format!("plcvec-rust-harness-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("known.toml");
    let mut text: String = failing
        .iter()
        .map(|id| format!("[[known-failure]]\nid = {id:?}\nreason = \"SM8022 not modelled\"\n\n"))
        .collect();
    std::fs::write(&path, &text).unwrap();
    KnownFailures::load(&path).unwrap();
    let mutant = || OnMemory(Reference::mutant(Mutant::TaddSm8022NotWritten, Choices::new()));
    let conclusion = conclude(Harness::new(mutant).select(tadd()).known_failures(&path));
    assert_eq!((conclusion.num_failed, conclusion.num_ignored), (0, failing.len() as u64));

    // The same list against the reference: every entry passes, so every entry is stale.
    let conclusion = conclude(Harness::new(|| OnMemory(Reference::new())).select(tadd()).known_failures(&path));
    assert_eq!(conclusion.num_failed, failing.len() as u64);

    // An id the suite does not have is a failing test of its own.
    text.push_str("[[known-failure]]\nid = \"fx5-time-add/no/such/vector\"\nreason = \"gone\"\n");
    std::fs::write(&path, &text).unwrap();
    let conclusion = conclude(Harness::new(mutant).select(tadd()).known_failures(&path));
    assert_eq!(conclusion.num_failed, 1);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn nothing_to_judge_is_an_error() {
    let err =
        Harness::new(|| OnMemory(Reference::new())).select(Selection::all().family("nope")).trials().err().unwrap();
    assert!(err.to_string().contains("family \"nope\""), "{err}");

    struct Nothing;
    impl plcvec::Implementation for Nothing {
        fn supports(&self, _: &str) -> bool {
            false
        }
        fn run(&mut self, _: &plcvec::Vector, _: &mut plcvec::Steps<'_>) -> Result<(), plcvec::Refusal> {
            Ok(())
        }
    }
    let err = Harness::new(|| Nothing).select(tadd()).trials().err().unwrap();
    assert!(err.to_string().contains("supports none of the selected instructions"), "{err}");

    struct SkipsAll;
    impl plcvec::Implementation for SkipsAll {
        fn run(&mut self, _: &plcvec::Vector, _: &mut plcvec::Steps<'_>) -> Result<(), plcvec::Refusal> {
            Err(plcvec::Refusal::Skip("not yet".into()))
        }
    }
    let conclusion = conclude(Harness::new(|| SkipsAll).select(tadd()));
    assert!(judged_nothing(&conclusion));
}
