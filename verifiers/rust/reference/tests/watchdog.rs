//! A run cut short by the per-vector bound (`PLCVEC_TIMEOUT`) ends as `plcvec verify` ends an
//! aborted run: the expectations file is written (whole), and the run's text has every failing
//! vector's block, the late vector as an error, the vectors not yet judged as not run,
//! `ABORTED: <why>` and the summary lines; the exit status is a failure's.
//!
//! The run to cut is this test binary once more (the watchdog ends the process it runs in): an
//! implementation that writes nothing for the manual's TADD example (so D30..D32 do not become
//! 13:40:15 and it fails) and never returns on the vector after it, one test thread, in order.

use std::path::PathBuf;
use std::process::Command;
use std::time::Duration;

use plcvec::harness::{Arguments, Harness};
use plcvec::{Execute, Memory, Refusal, Selection, Step, Suite, Vector};
use plcvec_reference::Reference;

/// Set for the child run: the expectations file it writes.
const CHILD: &str = "PLCVEC_TEST_CUT_RUN";
/// Set for the child run: cargo's name filter, if it has one.
const CHILD_FILTER: &str = "PLCVEC_TEST_CUT_RUN_FILTER";
const TEST: &str = "a_run_cut_by_the_watchdog_reports_what_it_judged_and_writes_the_expectations";
const WRONG: &str = "fx5-time-add/TADD/manual-example/program";

fn tadd() -> Selection {
    Selection::all().family("fx5-time-add")
}

/// The selected ids in the order the harness runs them (the vector files' order).
fn ids() -> Vec<String> {
    tadd().apply(Suite::embedded().unwrap().vectors()).iter().map(|v| v.id().to_owned()).collect()
}

/// The vector the implementation never returns on: the one after the manual example.
fn late(ids: &[String]) -> String {
    let wrong = ids.iter().position(|id| id == WRONG).expect("the manual example is a vector");
    ids.get(wrong + 1).expect("a vector after the manual example").clone()
}

struct CutShort {
    reference: Reference,
    late: String,
}

impl Execute for CutShort {
    fn supports(&self, instruction: &str) -> bool {
        self.reference.supports(instruction)
    }

    fn begin(&mut self, vector: &Vector) -> Result<(), Refusal> {
        self.reference.begin(vector)
    }

    fn execute(&mut self, vector: &Vector, step: &Step, memory: &mut Memory<'_>) -> Result<Option<bool>, Refusal> {
        if vector.id() == self.late {
            loop {
                std::thread::sleep(Duration::from_secs(1));
            }
        }
        if vector.id() == WRONG {
            return Ok(None);
        }
        self.reference.execute(vector, step, memory)
    }
}

/// The child: the run the watchdog cuts (it never returns from `run`).
fn cut_run(expectations: PathBuf) -> ! {
    let filter = std::env::var(CHILD_FILTER).ok();
    let late = late(&ids());
    let harness = Harness::new(move || plcvec::OnMemory(CutShort { reference: Reference::new(), late: late.clone() }))
        .suite(Suite::embedded().unwrap())
        .select(tadd())
        .timeout(Duration::from_millis(500))
        .write_expectations(expectations)
        .arguments(Arguments { test_threads: Some(1), filter, ..Arguments::default() })
        .in_process();
    let _ = harness.run();
    eprintln!("the run came to its end: the watchdog did not cut it");
    std::process::exit(3)
}

/// Run the cut run in a child (this binary, in the test below), with cargo's name filter
/// `filter`; its exit status, stdout and stderr, and the expectations file it wrote.
fn cut(filter: Option<&str>) -> (Option<i32>, String, String, Option<String>) {
    static RUN: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = RUN.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let scratch = std::env::temp_dir().join(format!("plcvec-rust-watchdog-{}-{n}", std::process::id()));
    std::fs::create_dir_all(&scratch).unwrap();
    let expectations = scratch.join("known.toml");
    let mut child = Command::new(std::env::current_exe().unwrap());
    child.args([&test_name(), "--exact", "--nocapture", "--test-threads=1"]).env(CHILD, &expectations);
    match filter {
        Some(f) => child.env(CHILD_FILTER, f),
        None => child.env_remove(CHILD_FILTER),
    };
    let out = child.env_remove("PLCVEC_KNOWN_FAILURES").output().unwrap();
    let written = std::fs::read_to_string(&expectations).ok();
    // Written whole or not at all: nothing but the file is left beside it.
    let left: Vec<_> = std::fs::read_dir(&scratch).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert!(left.iter().all(|name| name == "known.toml"), "left beside the expectations file: {left:?}");
    std::fs::remove_dir_all(&scratch).unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    (out.status.code(), stdout, stderr, written)
}

/// TEST's name as libtest knows it, for `--exact`: its module's path in the test binary (which
/// holds more than this file), without the binary's own name.
fn test_name() -> String {
    match module_path!().split_once("::") {
        Some((_, module)) => format!("{module}::{TEST}"),
        None => TEST.to_owned(),
    }
}

/// A known-failures file as every plcvec runner writes it, of `ids`.
fn expectations_of(ids: &[&str]) -> String {
    let mut ids = ids.to_vec();
    ids.sort();
    let entries: Vec<String> =
        ids.iter().map(|id| format!("[[known-failure]]\nid = \"{id}\"\nreason = \"not yet triaged\"\n")).collect();
    format!("# Known failures: each passing entry fails the run as stale, so fix and delete.\n\n{}", entries.join("\n"))
}

#[test]
fn a_run_cut_by_the_watchdog_reports_what_it_judged_and_writes_the_expectations() {
    if let Some(path) = std::env::var_os(CHILD) {
        cut_run(path.into());
    }
    let (code, stdout, stderr, written) = cut(None);
    let context = format!("stdout:\n{stdout}\nstderr:\n{stderr}");

    let ids = ids();
    let late = late(&ids);
    let at = ids.iter().position(|id| *id == late).unwrap();
    let (n, not_run) = (ids.len(), ids.len() - at - 1);
    assert!(not_run > 0, "no vector after {late}: the test needs one not run");
    assert_eq!(code, Some(101), "{context}");

    // The failure judged before the cut, once (libtest does not get to print it), the late
    // vector as an error, and every vector after it as not run, in the order they were run.
    assert_eq!(stdout.matches(&format!("\nFAIL {WRONG}\n")).count(), 1, "{context}");
    assert!(stdout.contains(&format!("\nERROR {late}\n")), "{context}");
    assert!(stdout.contains("the implementation did not return within 0.5 s (PLCVEC_TIMEOUT)"), "{context}");
    let blocks: Vec<&str> = stdout.lines().filter_map(|l| l.strip_prefix("NOT-RUN ")).collect();
    let expected: Vec<&str> = ids[at + 1..].iter().map(String::as_str).collect();
    assert_eq!(blocks, expected, "{context}");
    // The roll-up counts the not-run vectors among those no reading explains (TEXT.md).
    assert!(stdout.contains(&format!("NOT EXPLAINED by any reading: {} failing vectors", not_run + 2)), "{context}");

    // ABORTED: <why> after the roll-up and the skips, then an empty line and the summary lines.
    let why = format!("ABORTED: {late}: no answer within 0.5 s (PLCVEC_TIMEOUT): the run ends\n\nplcvec: ");
    let aborted = stdout.find(&why).unwrap_or_else(|| panic!("no ABORTED line before the summary\n{context}"));
    assert!(stdout.find("NOT EXPLAINED").is_some_and(|r| r < aborted), "{context}");
    let totals = format!("{n} vectors: {} pass, 1 fail, 1 error, 0 skip, {not_run} not-run in ", at - 1);
    let last = stdout.lines().last().unwrap_or("");
    assert!(last.starts_with(&totals) && last.ends_with(" s"), "{totals:?} is not the last line\n{context}");

    // The expectations file: the failure and the late vector (a vector not run is no known
    // failure), sorted by id.
    assert_eq!(written.as_deref(), Some(expectations_of(&[WRONG, &late]).as_str()), "{context}");
    assert!(stderr.contains("plcvec: 2 known failures written to "), "{context}");
}

#[test]
fn a_run_cut_by_the_watchdog_under_a_name_filter_reports_only_the_vectors_it_selects() {
    // TADD's ids sort before TADDP's ('/' before 'P'): the filter keeps every vector up to the
    // late one and leaves out the TADDP vectors after it, which are then not "not run".
    let filter = "fx5-time-add/TADD/";
    let (code, stdout, stderr, written) = cut(Some(filter));
    let context = format!("stdout:\n{stdout}\nstderr:\n{stderr}");
    let ids = ids();
    let late = late(&ids);
    let at = ids.iter().position(|id| *id == late).unwrap();
    assert!(ids[..=at].iter().all(|id| id.contains(filter)), "the filter leaves out a vector before {late}");
    let kept: Vec<&str> = ids[at + 1..].iter().map(String::as_str).filter(|id| id.contains(filter)).collect();
    assert!(kept.len() < ids.len() - at - 1, "the filter leaves out no vector after {late}");
    assert_eq!(code, Some(101), "{context}");
    let blocks: Vec<&str> = stdout.lines().filter_map(|l| l.strip_prefix("NOT-RUN ")).collect();
    assert_eq!(blocks, kept, "{context}");
    let totals = format!(
        "{} vectors: {} pass, 1 fail, 1 error, 0 skip, {} not-run in ",
        at + 1 + kept.len(),
        at - 1,
        kept.len()
    );
    assert!(stdout.lines().last().unwrap_or("").starts_with(&totals), "{totals:?} is not the last line\n{context}");
    assert_eq!(written.as_deref(), Some(expectations_of(&[WRONG, &late]).as_str()), "{context}");
}
