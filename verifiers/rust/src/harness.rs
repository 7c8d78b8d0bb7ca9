//! One test per vector under `cargo test`, named by its id exactly: a custom test harness on
//! libtest-mimic, so cargo's own filters (`cargo test -- fx5-time-add`, `--exact`, `--skip`),
//! `--list`, parallelism and output formats apply, and nextest sees every vector.
//!
//! In your crate (`Cargo.toml`: `[[test]] name = "plcvec"`, `harness = false`):
//!
//! ```no_run
//! # struct MyEmulator;
//! # impl plcvec::Execute for MyEmulator {
//! #     fn execute(&mut self, _: &plcvec::Vector, _: &plcvec::Step, _: &mut plcvec::Memory<'_>)
//! #         -> Result<Option<bool>, plcvec::Refusal> { Ok(None) }
//! # }
//! fn main() -> std::process::ExitCode {
//!     plcvec::harness::run(|| plcvec::OnMemory(MyEmulator))
//! }
//! ```
//!
//! The environment chooses what to run without touching the code (every plcvec runner reads
//! the same variables, with the same errors): `PLCVEC_VECTORS` (another copy of the vectors),
//! `PLCVEC_ID` (exact ids or globs), `PLCVEC_FAMILY`, `PLCVEC_INSTRUCTION`, `PLCVEC_TAG`,
//! `PLCVEC_INTERPRETATION` (comma-separated names; an unknown or empty name is a usage error
//! that lists the known ones), `PLCVEC_SHARD` (`K/N`), `PLCVEC_KNOWN_FAILURES` (the TOML file of
//! known failures), `PLCVEC_WRITE_EXPECTATIONS` (write this run's failures to that file) and
//! `PLCVEC_TIMEOUT` (seconds a vector may take, default 10).
//!
//! A gate never passes by accident:
//!
//! - The vectors run in a child process of the test binary (the binary starts itself once
//!   more), so an implementation that ends the process half way (`exit(0)`, an abort) fails
//!   the run, naming the vector it was running. `main` therefore runs twice: keep it to the call
//!   of [`run`]. [`Harness::in_process`] gives that guard up. The child records nothing per
//!   vector (that would cost more than judging it): when it ends early, the vectors are run once
//!   more, each recorded, that run's output set aside (`main` runs a third time), and the vector
//!   that run ends on is named; when it does not end early, the run still fails, saying that the
//!   vector cannot be named.
//! - A vector that takes longer than `PLCVEC_TIMEOUT` ends the run, naming the vector: an
//!   error, the vectors not yet judged not run, the run's text with `ABORTED: <why>`, and the
//!   expectations file written with the failures so far, as `plcvec verify` reports an aborted run.
//! - A run that judges nothing (every vector skipped, an implementation that supports none of
//!   the selected instructions, cargo's own filter matching no vector) fails.
//!
//! Exit status: 0 passed; 101 (cargo's) some vector failed, or the run ended early; 2 a usage
//! error (the environment, a vector or known-failures file); 5 nothing was judged.

use std::collections::BTreeMap;
use std::fs::{File, OpenOptions};
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};
use std::sync::{Arc, Mutex, OnceLock};
use std::time::{Duration, Instant};

pub use libtest_mimic::{Arguments, Conclusion, FormatSetting};
use libtest_mimic::{Completion, Failed, Trial};

use crate::error::{Error, Result};
use std::panic::{catch_unwind, AssertUnwindSafe};

use crate::choices::Choices;
use crate::compare::{ReportedStep, Steps};
use crate::implementation::Implementation;
use crate::known::{write_expectations, KnownFailures};
use crate::runner::{judge, Plan};
use crate::select::{known_names, Kind, Selection};
use crate::verdict::{describe, Status, Verdict};
use crate::Suite;

/// Exit status of a usage error: a bad environment, vector file or known-failures file.
pub const EXIT_USAGE: u8 = 2;
/// Exit status of a run that judged nothing.
pub const EXIT_EMPTY: u8 = 5;
/// Exit status of a failing run (cargo's test status).
pub const EXIT_FAILED: u8 = 101;
/// The seconds a vector may take unless `PLCVEC_TIMEOUT` says otherwise.
pub const DEFAULT_TIMEOUT_S: f64 = 10.0;

/// Set by the supervising process for the child that runs the vectors: the file in which the
/// child notes that the run came to its end (internal; not for users).
const PROGRESS_ENV: &str = "PLCVEC_HARNESS_PROGRESS";
/// Set by the supervising process, with `PROGRESS_ENV`, for the child that runs the vectors once
/// more to find the one a run ended on: it records each vector as it starts and ends, and writes
/// no expectations file (internal; not for users).
const EACH_VECTOR_ENV: &str = "PLCVEC_HARNESS_EACH_VECTOR";

/// The file a supervised child tells its parent through, and whether it records each vector.
struct Progress {
    file: File,
    each_vector: bool,
}

/// Run every selected vector as its own test with implementations `factory` builds (one per
/// vector, so nothing carries over), and return the process's exit code.
pub fn run<I, F>(factory: F) -> ExitCode
where
    I: Implementation + 'static,
    F: Fn() -> I + Send + Sync + 'static,
{
    Harness::new(factory).run()
}

/// The harness with its options (the environment's, unless set here).
pub struct Harness<F> {
    factory: F,
    suite: Option<Suite>,
    selection: Option<Selection>,
    known_failures: Option<PathBuf>,
    write_expectations: Option<PathBuf>,
    timeout: Option<Duration>,
    args: Option<Arguments>,
    isolated: bool,
}

/// Why a run stops before judging anything.
enum Stop {
    /// A usage error (exit 2).
    Usage(Error),
    /// Nothing to judge (exit 5).
    Empty(String),
}

impl From<Error> for Stop {
    fn from(e: Error) -> Stop {
        Stop::Usage(e)
    }
}

impl Stop {
    fn into_error(self) -> Error {
        match self {
            Stop::Usage(e) => e,
            Stop::Empty(why) => Error::new(why),
        }
    }
}

/// One environment variable's comma-separated names; `None` when unset or empty. An empty item
/// (`PLCVEC_FAMILY=,`) is kept, to be refused with the known names.
fn env_items(name: &str) -> Option<Vec<String>> {
    let value = std::env::var(name).ok().filter(|v| !v.is_empty())?;
    Some(value.split(',').map(|s| s.trim().to_owned()).collect())
}

fn env_path(name: &str) -> Option<PathBuf> {
    std::env::var_os(name).filter(|p| !p.is_empty()).map(PathBuf::from)
}

/// The selection the `PLCVEC_*` environment variables give, checked against `suite`: an unknown
/// or empty name, a `PLCVEC_ID` item that matches no id, or a malformed `PLCVEC_SHARD` is an
/// error naming the variable (and listing the known names).
pub fn selection_from_env(suite: &Suite) -> Result<Selection> {
    let mut s = Selection::all();
    for (var, kind) in [
        ("PLCVEC_FAMILY", Kind::Family),
        ("PLCVEC_INSTRUCTION", Kind::Instruction),
        ("PLCVEC_TAG", Kind::Tag),
        ("PLCVEC_INTERPRETATION", Kind::Interpretation),
    ] {
        let Some(items) = env_items(var) else { continue };
        let known = known_names(suite, kind);
        for name in items {
            if !known.contains(&name) {
                let what = if name.is_empty() {
                    format!("{var}={}: an empty {} name", std::env::var(var).unwrap_or_default(), kind.as_str())
                } else {
                    format!("{var}={name}: {} has no such {}", suite.source(), kind.as_str())
                };
                return Err(Error::new(format!("{what}; known: {}", known.join(", "))));
            }
            s = match kind {
                Kind::Family => s.family(name),
                Kind::Instruction => s.instruction(name),
                Kind::Tag => s.tag(name),
                Kind::Interpretation => s.interpretation(name),
            };
        }
    }
    if let Some(items) = env_items("PLCVEC_ID") {
        let example = suite.vectors().first().map_or("", |v| v.id());
        for item in items {
            if item.is_empty() {
                return Err(Error::new(format!(
                    "PLCVEC_ID={}: an empty id (ids look like {example})",
                    std::env::var("PLCVEC_ID").unwrap_or_default()
                )));
            }
            // An exact id is taken as it is, whatever characters it holds.
            let pattern = if suite.get(&item).is_some() { glob::Pattern::escape(&item) } else { item.clone() };
            let one = Selection::all().id_glob(&pattern).map_err(|e| Error::new(format!("PLCVEC_ID={item}: {e}")))?;
            if !suite.vectors().iter().any(|v| one.matches(v)) {
                return Err(Error::new(format!(
                    "PLCVEC_ID={item}: matches no vector id in {} (ids look like {example}; a glob matches the whole id)",
                    suite.source()
                )));
            }
            s = s.id_glob(&pattern)?;
        }
    }
    if let Some(shard) = std::env::var("PLCVEC_SHARD").ok().filter(|v| !v.is_empty()) {
        s = s.shard_text(&shard).map_err(|e| Error::new(format!("PLCVEC_SHARD={shard}: {e}")))?;
    }
    Ok(s)
}

/// `PLCVEC_TIMEOUT`: seconds, a positive number; default 10.
pub fn timeout_from_env() -> Result<Duration> {
    let Some(text) = std::env::var("PLCVEC_TIMEOUT").ok().filter(|v| !v.trim().is_empty()) else {
        return Ok(Duration::from_secs_f64(DEFAULT_TIMEOUT_S));
    };
    match text.trim().parse::<f64>() {
        Ok(s) if s.is_finite() && s > 0.0 && s < 1e9 => Ok(Duration::from_secs_f64(s)),
        _ => Err(Error::new(format!(
            "PLCVEC_TIMEOUT={text}: the seconds a vector may take must be a positive number (default {DEFAULT_TIMEOUT_S})"
        ))),
    }
}

impl<I, F> Harness<F>
where
    I: Implementation + 'static,
    F: Fn() -> I + Send + Sync + 'static,
{
    /// A harness for the implementations `factory` builds.
    pub fn new(factory: F) -> Harness<F> {
        Harness {
            factory,
            suite: None,
            selection: None,
            known_failures: None,
            write_expectations: None,
            timeout: None,
            args: None,
            isolated: true,
        }
    }

    /// Judge against this suite instead of `PLCVEC_VECTORS` or the embedded one.
    pub fn suite(mut self, suite: Suite) -> Self {
        self.suite = Some(suite);
        self
    }

    /// Run only these vectors (instead of the `PLCVEC_*` selection).
    pub fn select(mut self, selection: Selection) -> Self {
        self.selection = Some(selection);
        self
    }

    /// Read known failures from this file (instead of `PLCVEC_KNOWN_FAILURES`).
    pub fn known_failures(mut self, path: impl Into<PathBuf>) -> Self {
        self.known_failures = Some(path.into());
        self
    }

    /// Write the run's failures to this file as known failures (instead of
    /// `PLCVEC_WRITE_EXPECTATIONS`), for adopting the suite.
    pub fn write_expectations(mut self, path: impl Into<PathBuf>) -> Self {
        self.write_expectations = Some(path.into());
        self
    }

    /// The time a vector may take (instead of `PLCVEC_TIMEOUT`).
    pub fn timeout(mut self, timeout: Duration) -> Self {
        self.timeout = Some(timeout);
        self
    }

    /// Use these arguments instead of the process's (`cargo test -- ARGS`).
    pub fn arguments(mut self, args: Arguments) -> Self {
        self.args = Some(args);
        self
    }

    /// Run the vectors in this process, not in a child: an implementation that ends the process
    /// then ends the run with whatever status it gives (`exit(0)` reads as a pass). For a test
    /// binary that cannot be started twice.
    pub fn in_process(mut self) -> Self {
        self.isolated = false;
        self
    }

    /// The tests, one per selected vector (plus one per known failure the suite has no vector
    /// for, named by the listed id).
    pub fn trials(self) -> Result<Vec<Trial>> {
        Ok(self.prepare(None).map_err(Stop::into_error)?.0)
    }

    fn prepare(self, progress: Option<Progress>) -> std::result::Result<(Vec<Trial>, Arc<Shared<F>>), Stop> {
        let suite = match self.suite {
            Some(s) => s,
            None => Suite::from_env()?,
        };
        // The suite lives as long as the test process; every test borrows it.
        let suite: &'static Suite = Box::leak(Box::new(suite));
        let selection = match self.selection {
            Some(s) => s,
            None => selection_from_env(suite)?,
        };
        let timeout = match self.timeout {
            Some(t) => t,
            None => timeout_from_env()?,
        };
        let known_path = self.known_failures.or_else(|| env_path("PLCVEC_KNOWN_FAILURES"));
        let known = known_path.map(KnownFailures::load).transpose()?;
        // The run again to find a vector writes no expectations: the run it repeats ended early.
        let write = match &progress {
            Some(p) if p.each_vector => None,
            _ => self.write_expectations.or_else(|| env_path("PLCVEC_WRITE_EXPECTATIONS")),
        };
        let unknown = selection.unknown_names(suite);
        if !unknown.is_empty() {
            return Err(Stop::Usage(Error::new(format!(
                "the selection names what the suite does not have: {}",
                unknown.join("; ")
            ))));
        }
        let vectors = selection.apply(suite.vectors());
        if vectors.is_empty() {
            return Err(Stop::Empty(format!(
                "the selection keeps none of the {} vectors of {}: nothing would be judged",
                suite.vectors().len(),
                suite.source()
            )));
        }
        let probe = (self.factory)();
        let plan = Plan::new(suite, vectors, &probe.interpretations())?;
        let supported: Vec<bool> = plan.vectors().iter().map(|v| probe.supports(v.instruction())).collect();
        if !supported.contains(&true) {
            return Err(Stop::Empty(format!(
                "{} supports none of the selected instructions: nothing would be judged",
                probe.name()
            )));
        }
        let (name, choices, cpu_writes) = (probe.name(), probe.interpretations(), probe.cpu_writes());
        drop(probe);
        let (progress, record) = match progress {
            Some(Progress { file, each_vector: true }) => {
                let record = file
                    .try_clone()
                    .and_then(|copy| Record::create(copy, plan.vectors().iter().map(|v| v.id())))
                    .map_err(|e| Error::new(format!("cannot write the harness's progress file: {e}")))?;
                (Some(file), Some(record))
            }
            Some(Progress { file, each_vector: false }) => (Some(file), None),
            None => (None, None),
        };
        let watch = Arc::new(Watch::new(plan.len(), timeout, progress, record));
        let mut trials = Vec::new();
        if let Some(k) = &known {
            for e in k.unknown_ids(|id| suite.get(id).is_some()) {
                let message = format!("STALE {}\n    {}", e.id, k.unknown_message(e));
                trials.push(Trial::test(e.id.clone(), move || Err(Failed::from(message))));
            }
        }
        let shared = Arc::new(Shared {
            factory: self.factory,
            suite,
            plan,
            known,
            write,
            watch,
            failing: Mutex::new(Vec::new()),
            skips: Mutex::new(BTreeMap::new()),
            results: Mutex::new(Vec::new()),
            chosen: OnceLock::new(),
            name,
            choices,
            cpu_writes,
        });
        *shared.results.lock().unwrap_or_else(|e| e.into_inner()) = vec![None; shared.plan.len()];
        for (index, v) in shared.plan.vectors().iter().enumerate() {
            let trial = if supported[index] {
                let shared = Arc::clone(&shared);
                Trial::ignorable_test(v.id(), move || shared.judge_one(index))
            } else {
                let why = format!("the implementation does not support {}", v.instruction());
                *shared.skips.lock().unwrap_or_else(|e| e.into_inner()).entry(why.clone()).or_default() += 1;
                let skip = Verdict { status: Status::Skip, problems: Vec::new(), message: why };
                shared.results.lock().unwrap_or_else(|e| e.into_inner())[index] = Some((skip, None));
                Trial::test(v.id(), || Ok(())).with_ignored_flag(true)
            };
            trials.push(trial);
        }
        Ok((trials, shared))
    }

    /// Parse the arguments, run the tests (in a child process, unless [`Harness::in_process`]),
    /// and give the exit code: 0, 101 on a failure or a run that ended early, 2 on a usage
    /// error, 5 when nothing was judged.
    pub fn run(self) -> ExitCode {
        let mut args = self.args.clone().unwrap_or_else(Arguments::from_args);
        // libtest-mimic pads each name to the longest in its "test NAME ... ok" lines, and a
        // name copied with its padding is no vector id: the terse format (a character per test,
        // the failures listed by their exact ids) unless a format is asked for.
        if args.format.is_none() && !args.quiet {
            args.format = Some(FormatSetting::Terse);
        }
        let progress_path = env_path(PROGRESS_ENV);
        if self.isolated && progress_path.is_none() && !args.list {
            return supervise();
        }
        let each_vector = std::env::var_os(EACH_VECTOR_ENV).is_some();
        if each_vector {
            // The run again to find a vector leaves the first run's log as it is (its output is
            // set aside).
            args.logfile = None;
        }
        let progress = match progress_path.as_deref().map(|p| OpenOptions::new().write(true).open(p)) {
            Some(Ok(file)) => Some(Progress { file, each_vector }),
            Some(Err(e)) => {
                eprintln!("plcvec: cannot write the harness's progress file: {e}");
                return ExitCode::from(EXIT_USAGE);
            }
            None => None,
        };
        let marker = progress.as_ref().and_then(|p| p.file.try_clone().ok());
        let code = self.run_here(args, progress);
        // The supervisor reads this line as "the run came to its end", not ended half way.
        if let Some(f) = marker {
            Record::came_to_end(&f);
        }
        ExitCode::from(code)
    }

    fn run_here(self, args: Arguments, progress: Option<Progress>) -> u8 {
        let (trials, shared) = match self.prepare(progress) {
            Ok(prepared) => prepared,
            Err(Stop::Usage(e)) => {
                eprintln!("plcvec: {e}");
                return EXIT_USAGE;
            }
            Err(Stop::Empty(why)) => {
                eprintln!("plcvec: {why}");
                return EXIT_EMPTY;
            }
        };
        if !args.list {
            shared.choose(&args, &trials);
            shared.start_watchdog();
        }
        let started = Instant::now();
        let conclusion = libtest_mimic::run(&args, trials);
        if args.list {
            return 0;
        }
        // After libtest's own report (which shows each failure once, with its test): the
        // roll-up by reading, skips by reason and the summary lines of the one text.
        match shared.report() {
            Ok(report) => print!("\n{}", report.text_after_blocks(true, Some(started.elapsed().as_secs_f64()))),
            Err(e) => eprintln!("plcvec: {e}"),
        }
        let mut code = if conclusion.has_failed() { EXIT_FAILED } else { 0 };
        if code == 0 && conclusion.num_passed == 0 {
            eprintln!("plcvec: {}", shared.nothing_judged(&args, &conclusion));
            code = EXIT_EMPTY;
        }
        if let Some(path) = &shared.write {
            let failing = shared.failing.lock().unwrap_or_else(|e| e.into_inner());
            match write_expectations(path, failing.iter().map(String::as_str), "not yet triaged") {
                Ok(n) => eprintln!("plcvec: {n} known failures written to {}", path.display()),
                Err(e) => {
                    eprintln!("plcvec: {e}");
                    code = code.max(EXIT_USAGE);
                }
            }
        }
        code
    }

    /// Run the tests in this process and give libtest-mimic's conclusion (for a caller that
    /// decides itself; no child process, no check that something was judged).
    pub fn conclude(self) -> Result<Conclusion> {
        let args = self.args.clone().unwrap_or_else(Arguments::from_args);
        let (trials, shared) = self.prepare(None).map_err(Stop::into_error)?;
        shared.choose(&args, &trials);
        shared.start_watchdog();
        Ok(libtest_mimic::run(&args, trials))
    }
}

/// Whether a run judged nothing: no test passed or failed, and some were skipped or ignored.
pub fn judged_nothing(conclusion: &Conclusion) -> bool {
    conclusion.num_passed == 0 && conclusion.num_failed == 0 && conclusion.num_ignored > 0
}

/// A vector's verdict and, when it failed, the implementation's answer.
type Judged = (Verdict, Option<Vec<ReportedStep>>);

struct Shared<F> {
    factory: F,
    suite: &'static Suite,
    plan: Plan<'static>,
    known: Option<KnownFailures>,
    write: Option<PathBuf>,
    watch: Arc<Watch>,
    /// Ids for the expectations file: failures and known failures that still fail.
    failing: Mutex<Vec<String>>,
    /// Skip reason -> how many.
    skips: Mutex<BTreeMap<String, usize>>,
    /// Per vector of the plan: its verdict and, when it failed, the answer (for the roll-up).
    results: Mutex<Vec<Option<Judged>>>,
    /// When the tests started, and per vector of the plan whether cargo's filter lets it run
    /// (unset: every vector does).
    chosen: OnceLock<(Instant, Vec<bool>)>,
    /// The implementation's name, declared alternatives and CPU-wide devices.
    name: String,
    choices: Choices,
    cpu_writes: Vec<String>,
}

impl<I, F> Shared<F>
where
    I: Implementation,
    F: Fn() -> I,
{
    fn judge_one(&self, index: usize) -> std::result::Result<Completion, Failed> {
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
    fn start_watchdog(self: &Arc<Self>) {
        let shared = Arc::clone(self);
        Watch::start(&self.watch, move |late| shared.end_on_timeout(late));
    }
}

impl<F> Shared<F> {
    /// Note when the tests start and which vectors cargo's own filter leaves to run: those a run
    /// cut short reports as not run.
    fn choose(&self, args: &Arguments, trials: &[Trial]) {
        let chosen: std::collections::BTreeSet<&str> =
            trials.iter().filter(|t| !args.is_filtered_out(t)).map(Trial::name).collect();
        let chosen = self.plan.vectors().iter().map(|v| chosen.contains(v.id())).collect();
        let _ = self.chosen.set((Instant::now(), chosen));
    }

    /// The report of the vectors this run judged (those cargo's filter left out are not in it).
    fn report(&self) -> Result<crate::runner::Report<'static>> {
        self.report_of(&self.results.lock().unwrap_or_else(|e| e.into_inner()))
    }

    fn report_of(&self, results: &[Option<Judged>]) -> Result<crate::runner::Report<'static>> {
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
    fn end_on_timeout(&self, late: usize) -> ! {
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
        if let Some(file) = &self.watch.progress {
            Record::came_to_end(file);
        }
        std::process::exit(i32::from(EXIT_FAILED));
    }

    /// Why a run with no failure and no pass judged nothing, and what to do.
    fn nothing_judged(&self, args: &Arguments, conclusion: &Conclusion) -> String {
        let filtered = conclusion.num_filtered_out > 0;
        if filtered && (args.filter.is_some() || !args.skip.is_empty() || args.ignored) {
            let filter = args.filter.as_deref().unwrap_or("");
            return format!(
                "the test filter {filter:?} (or --skip/--ignored) left no vector to judge: nothing was judged. \
                 Select vectors with PLCVEC_ID (exact ids or globs, comma-separated: PLCVEC_ID='fx5-time-add/TADD/*'), \
                 PLCVEC_FAMILY or PLCVEC_INSTRUCTION, and run `cargo test --test <this test>` so that other \
                 tests' filters do not reach it"
            );
        }
        let skips = self.skips.lock().unwrap_or_else(|e| e.into_inner());
        let mut text = String::from("nothing was judged: every selected vector was skipped");
        for (why, n) in skips.iter() {
            text.push_str(&format!("\n    {n} skipped: {why}"));
        }
        text
    }
}

/// The per-vector bound and the record of what is running: a thread ends the run when a
/// vector takes longer than the timeout, naming it; the supervising process reads the record
/// when the process ends early.
///
/// Judging a vector of the golden set takes well under a microsecond, and a system call takes
/// longer: what the guard does per vector is two atomic stores. No lock, no clock, no allocation,
/// no system call: the watchdog reads the vectors' states on its tick and times a vector from the
/// tick that first saw it running. Only the child that runs the vectors again to find the one a
/// run ended on (`supervise`) also writes each vector's start and end to its record.
struct Watch {
    /// Per vector of the plan: `pass << 1 | 1` while it is judged, `pass << 1` once judged (0:
    /// not yet started). The pass tells the watchdog a vector judged again (the bench's guard
    /// judges a plan many times; the harness, once) from one still running.
    states: Box<[AtomicU32]>,
    timeout: Duration,
    /// The supervised child's file, for the note that the run came to its end.
    progress: Option<File>,
    /// The record of each vector, when this child runs the vectors again to find one.
    record: Option<Record>,
    /// Set when the watchdog is to end (the bench's guard, dropped).
    stopped: AtomicBool,
}

impl Watch {
    fn new(vectors: usize, timeout: Duration, progress: Option<File>, record: Option<Record>) -> Watch {
        let states = (0..vectors).map(|_| AtomicU32::new(0)).collect();
        Watch { states, timeout, progress, record, stopped: AtomicBool::new(false) }
    }

    fn begin(&self, index: usize, pass: u32) {
        if let Some(record) = &self.record {
            record.mark(index, Record::RUNNING);
        }
        self.states[index].store(pass << 1 | 1, Ordering::Relaxed);
    }

    fn end(&self, index: usize, pass: u32) {
        self.states[index].store(pass << 1, Ordering::Relaxed);
        if let Some(record) = &self.record {
            record.mark(index, Record::JUDGED);
        }
    }

    /// The watchdog thread, which calls `late` with a vector that took longer than the timeout:
    /// it never holds the process (a thread does not keep it running). A vector started at most
    /// one tick before the tick that first sees it running, and is late once that tick is a
    /// timeout old: never before it has taken the timeout, at most two ticks after.
    fn start(watch: &Arc<Watch>, late: impl Fn(usize) + Send + 'static) {
        let watch = Arc::clone(watch);
        let tick = (watch.timeout / 10).clamp(Duration::from_millis(5), Duration::from_millis(250));
        let spawned = std::thread::Builder::new().name("plcvec-watchdog".into()).spawn(move || {
            // (index, its state, the tick that first saw it running in that state)
            let mut running: Vec<(usize, u32, Instant)> = Vec::new();
            loop {
                std::thread::sleep(tick);
                if watch.stopped.load(Ordering::Relaxed) {
                    return;
                }
                let now = Instant::now();
                running.retain(|&(i, state, _)| watch.states[i].load(Ordering::Relaxed) == state);
                for (i, state) in watch.states.iter().enumerate() {
                    let state = state.load(Ordering::Relaxed);
                    if state & 1 == 1 && !running.iter().any(|&(j, s, _)| j == i && s == state) {
                        running.push((i, state, now));
                    }
                }
                if let Some(&(index, _, _)) = running.iter().find(|(_, _, seen)| now - *seen >= watch.timeout) {
                    late(index);
                }
            }
        });
        if let Err(e) = spawned {
            eprintln!("plcvec: cannot start the watchdog thread ({e}); vectors run without a time bound");
        }
    }
}

/// The file the supervised child shares with its parent (`PROGRESS_ENV`), which the parent reads
/// when the child has ended: the number of vectors (8 bytes, little-endian), a byte that says the
/// run came to its end, a byte per vector (not started, being judged, judged), then each vector's
/// id (its length in bytes, 4 bytes little-endian, then the id: an id may hold any character). A child that runs the vectors for the first time writes only the byte that
/// says it came to its end (the rest reads as no vector); the child that runs them again to find
/// the one a run ended on writes it all: each mark is one write of one byte at the vector's own
/// place, so that the file says exactly what was running whatever the test threads.
struct Record {
    file: File,
}

impl Record {
    const RUNNING: u8 = 1;
    const JUDGED: u8 = 2;
    /// Where the byte that says the run came to its end is.
    const END_AT: u64 = 8;
    /// Where the vectors' bytes begin.
    const MARKS_AT: u64 = 9;

    /// The record of a plan of these ids, written whole before any vector starts.
    fn create<'a>(file: File, ids: impl ExactSizeIterator<Item = &'a str>) -> std::io::Result<Record> {
        let mut head = Vec::new();
        head.extend_from_slice(&(ids.len() as u64).to_le_bytes());
        head.push(0);
        head.resize(head.len() + ids.len(), 0);
        for id in ids {
            head.extend_from_slice(&u32::try_from(id.len()).unwrap_or(u32::MAX).to_le_bytes());
            head.extend_from_slice(id.as_bytes());
        }
        write_at(&file, &head, 0)?;
        Ok(Record { file })
    }

    fn mark(&self, index: usize, state: u8) {
        let _ = write_at(&self.file, &[state], Record::MARKS_AT + index as u64);
    }

    /// Note in `file` that the run came to its end (not ended half way).
    fn came_to_end(file: &File) {
        let _ = write_at(file, &[1], Record::END_AT);
    }

    /// What a record says: the ids of the vectors being judged, how many were judged, and
    /// whether the run came to its end.
    fn read(bytes: &[u8]) -> (Vec<String>, usize, bool) {
        let Some((n, rest)) = bytes.split_first_chunk::<8>() else { return (Vec::new(), 0, false) };
        let Some((&end, rest)) = rest.split_first() else { return (Vec::new(), 0, false) };
        let n = usize::try_from(u64::from_le_bytes(*n)).unwrap_or(usize::MAX).min(rest.len());
        let (marks, mut rest) = rest.split_at(n);
        let mut ids = Vec::new();
        while let Some((len, after)) = rest.split_first_chunk::<4>() {
            let len = usize::try_from(u32::from_le_bytes(*len)).unwrap_or(usize::MAX).min(after.len());
            let (id, after) = after.split_at(len);
            ids.push(id);
            rest = after;
        }
        let running = (0..n)
            .filter(|&i| marks[i] == Record::RUNNING)
            .map(|i| {
                ids.get(i).map_or_else(
                    || format!("the vector at {i} of the plan"),
                    |id| String::from_utf8_lossy(id).into_owned(),
                )
            })
            .collect();
        (running, marks.iter().filter(|&&m| m == Record::JUDGED).count(), end != 0)
    }
}

/// One write of `bytes` at `offset` in `file` (whatever the file's position).
fn write_at(file: &File, bytes: &[u8], offset: u64) -> std::io::Result<()> {
    #[cfg(unix)]
    {
        std::os::unix::fs::FileExt::write_all_at(file, bytes, offset)
    }
    #[cfg(windows)]
    {
        let written = std::os::windows::fs::FileExt::seek_write(file, bytes, offset)?;
        if written == bytes.len() {
            Ok(())
        } else {
            Err(std::io::Error::new(std::io::ErrorKind::WriteZero, "a short write to the progress record"))
        }
    }
    #[cfg(not(any(unix, windows)))]
    {
        let _ = (file, bytes, offset);
        Err(std::io::Error::new(std::io::ErrorKind::Unsupported, "no positioned writes on this platform"))
    }
}

/// The guard the harness puts around each vector (the watchdog's states, and the record of each
/// vector in the child that runs the vectors again after a run ended early), driven from outside
/// the harness around [`judge_plan`]'s judging: the crate's benchmark sets the judging with it
/// beside the same judging without. Not part of the API; it may change in any release.
///
/// [`judge_plan`]: crate::judge_plan
#[doc(hidden)]
pub struct Guard {
    watch: Arc<Watch>,
    /// The passes judged so far.
    passes: AtomicU32,
}

#[doc(hidden)]
impl Guard {
    /// The guard a supervised child puts on a run of `plan`: the watchdog started with
    /// `timeout`, and `progress` (an existing file), when given, opened as the child opens the
    /// file its parent made; with `each_vector`, each vector recorded in it, as the child that
    /// runs the vectors again to find the one a run ended on records them. A vector that takes
    /// longer ends the process (status 101).
    pub fn start(
        plan: &Plan<'_>,
        timeout: Duration,
        progress: Option<&std::path::Path>,
        each_vector: bool,
    ) -> std::io::Result<Guard> {
        let progress = progress.map(|path| OpenOptions::new().write(true).open(path)).transpose()?;
        let record = match (&progress, each_vector) {
            (Some(file), true) => Some(Record::create(file.try_clone()?, plan.vectors().iter().map(|v| v.id()))?),
            _ => None,
        };
        let watch = Arc::new(Watch::new(plan.len(), timeout, progress, record));
        Watch::start(&watch, move |late| {
            eprintln!("plcvec: the vector at {late} of the plan took longer than {} s", timeout.as_secs_f64());
            std::process::exit(i32::from(EXIT_FAILED));
        });
        Ok(Guard { watch, passes: AtomicU32::new(0) })
    }

    /// [`judge_plan`](crate::judge_plan) of the plan the guard was started with, the guard around
    /// each vector as the harness puts it around each test.
    pub fn judge_plan<I: Implementation + ?Sized>(&self, plan: &Plan<'_>, implementation: &mut I) -> Vec<Verdict> {
        assert_eq!(plan.len(), self.watch.states.len(), "the plan the guard was started with");
        let pass = self.passes.fetch_add(1, Ordering::Relaxed).wrapping_add(1) & (u32::MAX >> 1);
        crate::runner::judge_plan_marked(plan, implementation, |index, starts| {
            if starts {
                self.watch.begin(index, pass);
            } else {
                self.watch.end(index, pass);
            }
        })
    }
}

impl Drop for Guard {
    fn drop(&mut self) {
        self.watch.stopped.store(true, Ordering::Relaxed);
    }
}

/// Run this test binary once more as a child that runs the vectors, and judge how it ended:
/// a child that exits (with any status, 0 included) or dies before the run came to its end
/// fails the run, naming the vector(s) it was running.
///
/// The child records nothing per vector (a system call per vector costs more than judging it,
/// and nothing else a safe program can write outlives a process that dies): when it ends early,
/// the vectors are run once more by a child that records each as it starts and ends, its output
/// set aside, and the vector that child ends on is named. An implementation that ends the process
/// on a vector does so again; when the second run does not end early, the run still fails, and
/// says that the vector cannot be named. A child stopped from outside (`stopped_from_outside`) is
/// not run again.
fn supervise() -> ExitCode {
    let (status, record) = match run_child(false) {
        Ok(ended) => ended,
        Err(code) => return code,
    };
    if Record::read(&record).2 {
        return ExitCode::from(status.code().map_or(EXIT_FAILED, |c| u8::try_from(c).unwrap_or(EXIT_FAILED)));
    }
    let how = describe_status(&status);
    if stopped_from_outside(&status) {
        let _ = std::io::stdout().flush();
        println!(
            "\n\nFAIL the run\n    the test process ended ({how}) before the run came to its end, stopped from outside \
             (a signal that asks a process to stop, or the kernel's out-of-memory killer), so the vectors are not run \
             again to name the one it was running; a run that ends early is never a pass"
        );
        eprintln!("plcvec: the test process ended early ({how})");
        return ExitCode::from(EXIT_FAILED);
    }
    eprintln!("plcvec: the test process ended early ({how}); running the vectors again, each recorded, to find the one it ended on");
    let again = run_child(true);
    let _ = std::io::stdout().flush();
    let ended_again = match &again {
        Ok((status, record)) => {
            let (running, finished, done) = Record::read(record);
            let how_again = describe_status(status);
            let same = if how_again == how { "the same way".to_owned() } else { format!("({how_again})") };
            (!done).then_some((running, finished, same))
        }
        Err(_) => None,
    };
    match ended_again {
        Some((running, finished, same)) if running.is_empty() => println!(
            "\n\nFAIL the run\n    the test process ended ({how}) before the run came to its end; run again with each \
             vector recorded, it ended {same} after {finished} vectors and while none was being judged; a run that \
             ends early is never a pass"
        ),
        Some((running, _, same)) => {
            for id in &running {
                println!(
                    "\n\nFAIL {id}\n    the test process ended ({how}) before the run came to its end; run again with \
                     each vector recorded, it ended {same} while the implementation ran this vector; a run that ends \
                     early is never a pass"
                );
            }
        }
        None => println!(
            "\n\nFAIL the run\n    the test process ended ({how}) before the run came to its end; run again with each \
             vector recorded, it did not end early, so the vector it ended on cannot be named; a run that ends early \
             is never a pass"
        ),
    }
    eprintln!("plcvec: the test process ended early ({how})");
    ExitCode::from(EXIT_FAILED)
}

/// Run this test binary as the child that runs the vectors (with `each_vector`, recording each,
/// its output set aside): how it ended, and its record.
fn run_child(each_vector: bool) -> std::result::Result<(std::process::ExitStatus, Vec<u8>), ExitCode> {
    let progress = std::env::temp_dir().join(format!(
        "plcvec-progress-{}-{}",
        std::process::id(),
        std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_nanos())
    ));
    if let Err(e) = File::create(&progress) {
        eprintln!("plcvec: cannot create {}: {e}", progress.display());
        return Err(ExitCode::from(EXIT_USAGE));
    }
    let status = std::env::current_exe().and_then(|exe| {
        let mut child = std::process::Command::new(exe);
        child.args(std::env::args_os().skip(1)).env(PROGRESS_ENV, &progress);
        if each_vector {
            child.env(EACH_VECTOR_ENV, "1").stdout(std::process::Stdio::null()).stderr(std::process::Stdio::null());
        } else {
            child.env_remove(EACH_VECTOR_ENV);
        }
        child.status()
    });
    let record = std::fs::read(&progress).unwrap_or_default();
    let _ = std::fs::remove_file(&progress);
    match status {
        Ok(s) => Ok((s, record)),
        Err(e) => {
            eprintln!("plcvec: cannot start the test binary again to run the vectors: {e}");
            Err(ExitCode::from(EXIT_USAGE))
        }
    }
}

/// Whether the child was stopped by a signal that comes from outside, not from the implementation
/// (which ends the process by exiting, aborting or crashing): SIGHUP, SIGINT, SIGTERM, or SIGKILL
/// (a person's `kill -9`, or the kernel's out-of-memory killer). Running the vectors again then
/// would only be stopped again, or fill the memory again.
fn stopped_from_outside(status: &std::process::ExitStatus) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        matches!(status.signal(), Some(1 | 2 | 9 | 15))
    }
    #[cfg(not(unix))]
    {
        let _ = status;
        false
    }
}

fn describe_status(status: &std::process::ExitStatus) -> String {
    if let Some(code) = status.code() {
        return format!("exit status {code}");
    }
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        if let Some(signal) = status.signal() {
            let name = match signal {
                1 => " (SIGHUP)",
                2 => " (SIGINT)",
                6 => " (SIGABRT)",
                9 => " (SIGKILL)",
                11 => " (SIGSEGV)",
                15 => " (SIGTERM)",
                _ => "",
            };
            return format!("killed by signal {signal}{name}");
        }
    }
    status.to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        std::env::temp_dir().join(format!("plcvec-harness-{name}-{}", std::process::id()))
    }

    #[test]
    fn the_record_says_which_vectors_were_running_whatever_their_ids() {
        let path = scratch("record");
        let ids = ["a/1", "b\nwith a line break", "", "d/4"];
        let record = Record::create(File::create(&path).unwrap(), ids.iter().copied()).unwrap();
        // Nothing started yet, the run not at its end.
        assert_eq!(Record::read(&std::fs::read(&path).unwrap()), (vec![], 0, false));
        record.mark(0, Record::RUNNING);
        record.mark(1, Record::RUNNING);
        record.mark(3, Record::RUNNING);
        record.mark(0, Record::JUDGED);
        let expected = vec!["b\nwith a line break".to_owned(), "d/4".to_owned()];
        assert_eq!(Record::read(&std::fs::read(&path).unwrap()), (expected.clone(), 1, false));
        Record::came_to_end(&record.file);
        assert_eq!(Record::read(&std::fs::read(&path).unwrap()), (expected, 1, true));
        std::fs::remove_file(&path).unwrap();
    }

    #[test]
    fn a_first_run_notes_only_its_end() {
        // A child that records no vector writes the end's byte alone (into the empty file its
        // parent made); one that ended early, nothing.
        assert_eq!(Record::read(&[]), (vec![], 0, false));
        let path = scratch("end");
        let file = File::create(&path).unwrap();
        Record::came_to_end(&file);
        assert_eq!(Record::read(&std::fs::read(&path).unwrap()), (vec![], 0, true));
        std::fs::remove_file(&path).unwrap();
    }

    #[test]
    fn the_watchdog_names_a_vector_late_only_once_it_took_the_timeout() {
        let timeout = Duration::from_millis(100);
        let watch = Arc::new(Watch::new(3, timeout, None, None));
        let (tx, rx) = std::sync::mpsc::channel();
        let started = Instant::now();
        Watch::start(&watch, move |late| {
            let _ = tx.send((late, started.elapsed()));
            std::thread::sleep(Duration::from_secs(3600));
        });
        // Vector 0 judged over and over, each time quickly (a new pass each time), for longer than
        // the timeout; vector 2 never returns.
        watch.begin(2, 1);
        let mut pass = 0;
        while started.elapsed() < timeout * 3 {
            pass += 1;
            watch.begin(0, pass);
            watch.end(0, pass);
        }
        let (late, after) = rx.recv_timeout(Duration::from_secs(10)).expect("the watchdog named no vector");
        assert_eq!(late, 2);
        assert!(after >= timeout, "named after {after:?}, before the timeout");
        watch.stopped.store(true, Ordering::Relaxed);
    }
}
