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
use std::fs::OpenOptions;
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::{Arc, Mutex, OnceLock};
use std::time::{Duration, Instant};

use libtest_mimic::Trial;
pub use libtest_mimic::{Arguments, Conclusion, FormatSetting};

use crate::error::{Error, Result};
use crate::implementation::Implementation;
use crate::known::{write_expectations, KnownFailures};
use crate::runner::Plan;
use crate::selection::{known_names, Kind, Selection};
use crate::settings;
use crate::Suite;

/// Exit status of a usage error: a bad environment, vector file or known-failures file.
pub const EXIT_USAGE: u8 = 2;
/// Exit status of a run that judged nothing.
pub const EXIT_EMPTY: u8 = 5;
/// Exit status of a failing run (cargo's test status).
pub const EXIT_FAILED: u8 = 101;
/// The seconds a vector may take unless `PLCVEC_TIMEOUT` says otherwise.
pub const DEFAULT_TIMEOUT_S: f64 = crate::generated::settings::TIMEOUT_DEFAULT_S;

mod record;
mod session;
mod supervisor;
mod watchdog;

use record::Record;
use session::Shared;
use supervisor::{supervise, Progress, EACH_VECTOR_ENV, PROGRESS_ENV};
#[doc(hidden)]
pub use watchdog::Guard;
use watchdog::Watch;

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

/// One setting's comma-separated names; `None` when unset or empty. An empty item
/// (`PLCVEC_FAMILY=,`) is kept, to be refused with the known names.
fn env_items(name: &str) -> Option<Vec<String>> {
    let (_, value) = settings::text(name)?;
    Some(value.split(',').map(|s| s.trim().to_owned()).collect())
}

/// A setting that names a file (under its name or its old name).
fn env_path(name: &str) -> Option<PathBuf> {
    settings::var(name).map(|(_, path)| PathBuf::from(path))
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

/// `PLCVEC_TIMEOUT`: the bound on a vector in seconds, default 10; one rule in every runner
/// (CONTRACT.md, "The environment"): digits with an optional fraction, above 0, at most a day.
pub fn timeout_from_env() -> Result<Duration> {
    match settings::text("PLCVEC_TIMEOUT") {
        None => Ok(Duration::from_secs_f64(DEFAULT_TIMEOUT_S)),
        Some((source, text)) => settings::seconds(source, &text),
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

    /// Read known failures from this file: the name [`Harness::known_failures`] had in plcvec 0.1.
    #[deprecated(since = "0.2.0", note = "renamed `known_failures`, after the known-failures file it reads")]
    pub fn expectations(self, path: impl Into<PathBuf>) -> Self {
        self.known_failures(path)
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
        settings::warn_once();
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
        let vectors = selected(suite, &selection)?;
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
        let watch = Arc::new(watch(&plan, timeout, progress)?);
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
        let trials = shared.trials(&supported);
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
        let progress_path = std::env::var_os(PROGRESS_ENV).filter(|p| !p.is_empty()).map(PathBuf::from);
        if progress_path.is_some() {
            settings::already_warned(); // the parent process did
        } else {
            settings::warn_once();
        }
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
            Some(Ok(file)) => Some(Progress { path: progress_path.clone().unwrap_or_default(), file, each_vector }),
            Some(Err(e)) => {
                eprintln!("plcvec: cannot write the harness's progress file: {e}");
                return ExitCode::from(EXIT_USAGE);
            }
            None => None,
        };
        let code = self.run_here(args, progress);
        // The supervisor reads this as "the run came to its end", not ended half way.
        if let Some(path) = &progress_path {
            Record::came_to_end_at(path);
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
        let mut code = if conclusion.has_failed() { EXIT_FAILED } else { 0 };
        let shortfall = (code == 0 && conclusion.num_passed == 0).then(|| {
            code = EXIT_EMPTY;
            shared.nothing_passed(&args, &conclusion)
        });
        // After libtest's own report (which shows each failure once, with its test): the
        // roll-up by reading, skips by reason and the summary lines of the one text.
        let seconds = Some(started.elapsed().as_secs_f64());
        match shared.report() {
            Ok(report) => {
                let not_passed = shortfall.as_ref().map(|why| format!("NOT PASSED (exit {EXIT_EMPTY}): {why}"));
                print!("\n{}", report.text_ending(true, seconds, not_passed.as_deref()));
            }
            Err(e) => eprintln!("plcvec: {e}"),
        }
        if let Some(why) = &shortfall {
            eprintln!("plcvec: {why}");
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
        settings::warn_once();
        let args = self.args.clone().unwrap_or_else(Arguments::from_args);
        let (trials, shared) = self.prepare(None).map_err(Stop::into_error)?;
        shared.choose(&args, &trials);
        shared.start_watchdog();
        Ok(libtest_mimic::run(&args, trials))
    }
}

/// The vectors `selection` keeps, refused when it names what the suite lacks or keeps none.
fn selected<'s>(suite: &'s Suite, selection: &Selection) -> std::result::Result<Vec<&'s crate::Vector>, Stop> {
    let unknown = selection.unknown_names(suite);
    if !unknown.is_empty() {
        let names = unknown.join("; ");
        return Err(Stop::Usage(Error::new(format!("the selection names what the suite does not have: {names}"))));
    }
    let vectors = selection.apply(suite.vectors());
    if vectors.is_empty() {
        return Err(Stop::Empty(format!(
            "the selection keeps none of the {} vectors of {}: nothing would be judged",
            suite.vectors().len(),
            suite.source()
        )));
    }
    Ok(vectors)
}

/// The watchdog's states for `plan`, with the supervised child's record when this child runs the
/// vectors again to find the one a run ended on.
fn watch(plan: &Plan<'_>, timeout: Duration, progress: Option<Progress>) -> Result<Watch> {
    let (progress, record) = match progress {
        Some(Progress { path, file, each_vector: true }) => {
            let record = Record::create(file, plan.vectors().iter().map(|v| v.id()))
                .map_err(|e| Error::new(format!("cannot write the harness's progress file: {e}")))?;
            (Some(path), Some(record))
        }
        Some(Progress { path, each_vector: false, .. }) => (Some(path), None),
        None => (None, None),
    };
    Ok(Watch::new(plan.len(), timeout, progress, record))
}

/// Whether a run judged nothing: no test passed or failed, and some were skipped or ignored.
pub fn judged_nothing(conclusion: &Conclusion) -> bool {
    conclusion.num_passed == 0 && conclusion.num_failed == 0 && conclusion.num_ignored > 0
}
