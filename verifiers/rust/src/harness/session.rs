//! One run of the tests in this process: each vector judged as its test, the verdicts kept for the
//! end of the run's text, and the end of a run the watchdog cuts short.

use std::collections::BTreeMap;
use std::io::Write;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::PathBuf;
use std::sync::{Arc, Mutex, OnceLock};
use std::time::Instant;

use libtest_mimic::{Arguments, Completion, Conclusion, Failed, Trial};

use super::record::Record;
use super::watchdog::Watch;
use super::EXIT_FAILED;
use crate::choices::Choices;
use crate::compare::{ReportedStep, Steps};
use crate::error::Result;
use crate::implementation::Implementation;
use crate::known::{write_expectations, KnownFailures};
use crate::runner::{judge, Plan};
use crate::verdict::{describe, Status, Verdict};
use crate::Suite;

/// A vector's verdict and, when it failed, the implementation's answer.
pub(super) type Judged = (Verdict, Option<Vec<ReportedStep>>);

pub(super) struct Shared<F> {
    pub(super) factory: F,
    pub(super) suite: &'static Suite,
    pub(super) plan: Plan<'static>,
    pub(super) known: Option<KnownFailures>,
    pub(super) write: Option<PathBuf>,
    pub(super) watch: Arc<Watch>,
    /// Ids for the expectations file: failures and known failures that still fail.
    pub(super) failing: Mutex<Vec<String>>,
    /// Skip reason -> how many.
    pub(super) skips: Mutex<BTreeMap<String, usize>>,
    /// Per vector of the plan: its verdict and, when it failed, the answer (for the roll-up).
    pub(super) results: Mutex<Vec<Option<Judged>>>,
    /// When the tests started, and per vector of the plan whether cargo's filter lets it run
    /// (unset: every vector does).
    pub(super) chosen: OnceLock<(Instant, Vec<bool>)>,
    /// The implementation's name, declared alternatives and CPU-wide devices.
    pub(super) name: String,
    pub(super) choices: Choices,
    pub(super) cpu_writes: Vec<String>,
}

impl<I, F> Shared<F>
where
    I: Implementation + 'static,
    F: Fn() -> I + Send + Sync + 'static,
{
    /// The tests: one per known failure the suite has no vector for (stale, named by the listed
    /// id), then one per vector of the plan (ignored when the implementation does not support its
    /// instruction, `supported` says).
    pub(super) fn trials(self: &Arc<Self>, supported: &[bool]) -> Vec<Trial> {
        let mut trials = Vec::new();
        if let Some(k) = &self.known {
            let suite = self.suite;
            for e in k.unknown_ids(|id| suite.get(id).is_some()) {
                let message = format!("STALE {}\n    {}", e.id, k.stale_message(e, suite.merged_into(&e.id)));
                trials.push(Trial::test(e.id.clone(), move || Err(Failed::from(message))));
            }
        }
        *self.results.lock().unwrap_or_else(|e| e.into_inner()) = vec![None; self.plan.len()];
        for (index, v) in self.plan.vectors().iter().enumerate() {
            let trial = if supported[index] {
                let shared = Arc::clone(self);
                Trial::ignorable_test(v.id(), move || shared.judge_one(index))
            } else {
                let why = format!("the implementation does not support {}", v.instruction());
                *self.skips.lock().unwrap_or_else(|e| e.into_inner()).entry(why.clone()).or_default() += 1;
                let skip = Verdict { status: Status::Skip, problems: Vec::new(), message: why };
                self.results.lock().unwrap_or_else(|e| e.into_inner())[index] = Some((skip, None));
                Trial::test(v.id(), || Ok(())).with_ignored_flag(true)
            };
            trials.push(trial);
        }
        trials
    }

    pub(super) fn judge_one(&self, index: usize) -> std::result::Result<Completion, Failed> {
        let (vector, expected) = self.plan.get(index).expect("index within the plan");
        // Everything of the implementation's runs under the guard: building it, judging, the
        // failing answer asked again, dropping them.
        self.watch.begin(index, 1);
        let mut implementation = (self.factory)();
        let mut verdict = judge(&mut implementation, vector, expected);
        drop(implementation);
        // The failing answer, once more from a new implementation: what the roll-up judges
        // under the other alternatives.
        let answer = (verdict.status == Status::Fail).then(|| {
            let mut steps = Steps::record(vector);
            let mut again = (self.factory)();
            let ran = catch_unwind(AssertUnwindSafe(|| again.run(vector, &mut steps).is_ok()));
            if ran.unwrap_or(false) {
                steps.into_recorded()
            } else {
                Vec::new()
            }
        });
        self.watch.end(index, 1);
        if matches!(verdict.status, Status::Fail | Status::Error) {
            self.failing.lock().unwrap_or_else(|e| e.into_inner()).push(vector.id().to_owned());
        }
        if let Some(k) = &self.known {
            verdict = k.apply(vector.id(), verdict);
            if verdict.status == Status::XFail {
                self.failing.lock().unwrap_or_else(|e| e.into_inner()).push(vector.id().to_owned());
            }
        }
        let outcome = match verdict.status {
            Status::Pass => Ok(Completion::Completed),
            Status::Skip => {
                *self.skips.lock().unwrap_or_else(|e| e.into_inner()).entry(verdict.message.clone()).or_default() += 1;
                Ok(Completion::ignored_with(verdict.message.clone()))
            }
            Status::XFail => Ok(Completion::ignored_with(verdict.message.clone())),
            _ => Err(Failed::from(describe(vector, Some(expected), &verdict))),
        };
        if let Some(slot) = self.results.lock().unwrap_or_else(|e| e.into_inner()).get_mut(index) {
            *slot = Some((verdict, answer));
        }
        outcome
    }
}

impl<F: Send + Sync + 'static> Shared<F> {
    /// The watchdog: a vector that takes longer than the timeout ends the run.
    pub(super) fn start_watchdog(self: &Arc<Self>) {
        let shared = Arc::clone(self);
        Watch::start(&self.watch, move |late| shared.end_on_timeout(late));
    }
}

impl<F> Shared<F> {
    /// Note when the tests start and which vectors cargo's own filter leaves to run: those a run
    /// cut short reports as not run.
    pub(super) fn choose(&self, args: &Arguments, trials: &[Trial]) {
        let chosen: std::collections::BTreeSet<&str> =
            trials.iter().filter(|t| !args.is_filtered_out(t)).map(Trial::name).collect();
        let chosen = self.plan.vectors().iter().map(|v| chosen.contains(v.id())).collect();
        let _ = self.chosen.set((Instant::now(), chosen));
    }

    /// The report of the vectors this run judged (those cargo's filter left out are not in it).
    pub(super) fn report(&self) -> Result<crate::runner::Report<'static>> {
        self.report_of(&self.results.lock().unwrap_or_else(|e| e.into_inner()))
    }

    pub(super) fn report_of(&self, results: &[Option<Judged>]) -> Result<crate::runner::Report<'static>> {
        let suite = self.suite;
        let ran: Vec<usize> = (0..results.len()).filter(|&i| results[i].is_some()).collect();
        let (verdicts, answers) = ran.iter().filter_map(|&i| results[i].clone()).unzip();
        self.plan.subset(&ran).report(
            suite,
            self.name.clone(),
            &self.choices,
            self.cpu_writes.clone(),
            verdicts,
            answers,
        )
    }

    /// The end of a run cut short by the watchdog, as `plcvec verify` ends an aborted run: the
    /// expectations file first (written whole or not at all), then the run's text with every
    /// failing vector's block (libtest will not print its own: the process ends here), the late
    /// vector an error, the vectors not yet judged not run, and `ABORTED: <why>` before the
    /// summary lines. Exit 101, as for a failure.
    pub(super) fn end_on_timeout(&self, late: usize) -> ! {
        let id = self.plan.vectors()[late].id();
        let seconds = self.watch.timeout.as_secs_f64();
        let why = format!("{id}: no answer within {seconds} s (PLCVEC_TIMEOUT): the run ends");
        // Held to the end: a test thread that finishes meanwhile adds nothing to what is reported.
        let mut results = self.results.lock().unwrap_or_else(|e| e.into_inner());
        let mut failing = self.failing.lock().unwrap_or_else(|e| e.into_inner()).clone();
        let mut verdict = Verdict {
            status: Status::Error,
            problems: Vec::new(),
            message: format!(
                "the implementation did not return within {seconds} s (PLCVEC_TIMEOUT); the run ends here, \
                 the vectors not yet judged are not run"
            ),
        };
        failing.push(id.to_owned());
        if let Some(k) = &self.known {
            verdict = k.apply(id, verdict);
        }
        results[late] = Some((verdict, None));
        let chosen = self.chosen.get();
        for (index, slot) in results.iter_mut().enumerate() {
            if slot.is_none() && chosen.is_none_or(|(_, c)| c[index]) {
                let message = "not run: the run ended before it".to_owned();
                *slot = Some((Verdict { status: Status::NotRun, problems: Vec::new(), message }, None));
            }
        }
        let mut lines = Vec::new();
        if let Some(path) = &self.write {
            match write_expectations(path, failing.iter().map(String::as_str), "not yet triaged") {
                Ok(n) => lines.push(format!("plcvec: {n} known failures written to {}", path.display())),
                Err(e) => lines.push(format!("plcvec: {e}")),
            }
        }
        let text = self.report_of(&results).map(|mut report| {
            if let Some(k) = &self.known {
                report.unknown_known = crate::runner::unknown_known(k, self.suite);
            }
            report.aborted = Some(why.clone());
            report.text(true, chosen.map(|(started, _)| started.elapsed().as_secs_f64()))
        });
        let _ = std::io::stdout().flush();
        match text {
            Ok(text) => print!("\n\n{text}"),
            Err(e) => lines.push(format!("plcvec: {e}")),
        }
        let _ = std::io::stdout().flush();
        for line in lines {
            eprintln!("{line}");
        }
        eprintln!("plcvec: {why}");
        if let Some(path) = &self.watch.progress {
            Record::came_to_end_at(path);
        }
        std::process::exit(i32::from(EXIT_FAILED));
    }

    /// Why a run with no failure and no pass proves nothing, and what to do: cargo's filter left
    /// no vector, or every vector run was skipped or a known failure (a list of known failures on
    /// an implementation that fails them all proves nothing).
    pub(super) fn nothing_passed(&self, args: &Arguments, conclusion: &Conclusion) -> String {
        let filtered = conclusion.num_filtered_out > 0 && conclusion.num_ignored == 0;
        if filtered && (args.filter.is_some() || !args.skip.is_empty() || args.ignored) {
            let filter = args.filter.as_deref().unwrap_or("");
            return format!(
                "nothing passed: the test filter {filter:?} (or --skip/--ignored) left no vector to judge. \
                 Select vectors with PLCVEC_ID (exact ids or globs, comma-separated: PLCVEC_ID='fx5-time-add/TADD/*'), \
                 PLCVEC_FAMILY or PLCVEC_INSTRUCTION, and run `cargo test --test <this test>` so that other \
                 tests' filters do not reach it"
            );
        }
        let results = self.results.lock().unwrap_or_else(|e| e.into_inner());
        let count = |status: Status| results.iter().flatten().filter(|(v, _)| v.status == status).count();
        let counts: Vec<String> = [(Status::Skip, "skipped"), (Status::XFail, "known failures")]
            .iter()
            .filter(|(status, _)| count(*status) > 0)
            .map(|(status, word)| format!("{} {word}", count(*status)))
            .collect();
        format!("nothing passed ({}): the run proves nothing", counts.join(", "))
    }
}
