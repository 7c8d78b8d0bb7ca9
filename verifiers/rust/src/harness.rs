//! One test per vector under `cargo test`, named by its id: a custom test harness on
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
//! The environment chooses what to run without touching the code: `PLCVEC_VECTORS` (another copy
//! of the vectors), `PLCVEC_EXPECTATIONS` (the known-failures TOML file), and the selections
//! `PLCVEC_FAMILY`, `PLCVEC_INSTRUCTION`, `PLCVEC_TAG`, `PLCVEC_INTERPRETATION` (comma-separated
//! lists), `PLCVEC_ID` (a glob) and `PLCVEC_SHARD` (`K/N`).

use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::Arc;

pub use libtest_mimic::{Arguments, Conclusion};
use libtest_mimic::{Completion, Failed, Trial};

use crate::compare::{describe, judge, Status};
use crate::error::{Error, Result};
use crate::expect::Plan;
use crate::implementation::Implementation;
use crate::known::KnownFailures;
use crate::select::Selection;
use crate::Suite;

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
    expectations: Option<PathBuf>,
    args: Option<Arguments>,
}

struct Shared<F> {
    factory: F,
    plan: Plan<'static>,
    known: Option<KnownFailures>,
}

fn env_list(name: &str) -> Vec<String> {
    std::env::var(name)
        .map(|v| v.split(',').map(str::trim).filter(|s| !s.is_empty()).map(str::to_owned).collect())
        .unwrap_or_default()
}

/// The selection the `PLCVEC_*` environment variables give.
pub fn selection_from_env() -> Result<Selection> {
    let mut s = Selection::all();
    for f in env_list("PLCVEC_FAMILY") {
        s = s.family(f);
    }
    for i in env_list("PLCVEC_INSTRUCTION") {
        s = s.instruction(i);
    }
    for t in env_list("PLCVEC_TAG") {
        s = s.tag(t);
    }
    for i in env_list("PLCVEC_INTERPRETATION") {
        s = s.interpretation(i);
    }
    if let Ok(glob) = std::env::var("PLCVEC_ID") {
        if !glob.is_empty() {
            s = s.id_glob(&glob)?;
        }
    }
    if let Ok(shard) = std::env::var("PLCVEC_SHARD") {
        if !shard.is_empty() {
            s = s.shard_text(&shard).map_err(|e| Error::new(format!("PLCVEC_SHARD: {e}")))?;
        }
    }
    Ok(s)
}

impl<I, F> Harness<F>
where
    I: Implementation + 'static,
    F: Fn() -> I + Send + Sync + 'static,
{
    /// A harness for the implementations `factory` builds.
    pub fn new(factory: F) -> Harness<F> {
        Harness { factory, suite: None, selection: None, expectations: None, args: None }
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

    /// Read known failures from this file (instead of `PLCVEC_EXPECTATIONS`).
    pub fn expectations(mut self, path: impl Into<PathBuf>) -> Self {
        self.expectations = Some(path.into());
        self
    }

    /// Use these arguments instead of the process's (`cargo test -- ARGS`).
    pub fn arguments(mut self, args: Arguments) -> Self {
        self.args = Some(args);
        self
    }

    /// The tests, one per selected vector (plus one per stale expectations entry).
    pub fn trials(self) -> Result<Vec<Trial>> {
        let suite = match self.suite {
            Some(s) => s,
            None => Suite::from_env()?,
        };
        // The suite lives as long as the test process; every test borrows it.
        let suite: &'static Suite = Box::leak(Box::new(suite));
        let selection = match self.selection {
            Some(s) => s,
            None => selection_from_env()?,
        };
        let expectations = self
            .expectations
            .or_else(|| std::env::var_os("PLCVEC_EXPECTATIONS").filter(|p| !p.is_empty()).map(PathBuf::from));
        let known = expectations.map(KnownFailures::load).transpose()?;
        let vectors = selection.select(suite)?;
        let probe = (self.factory)();
        let plan = Plan::new(suite, vectors, &probe.interpretations())?;
        let supported: Vec<bool> = plan.vectors().iter().map(|v| probe.supports(v.instruction())).collect();
        if !supported.contains(&true) {
            return Err(Error::new(format!(
                "{} supports none of the selected instructions: nothing would be judged",
                probe.name()
            )));
        }
        drop(probe);
        let mut trials = Vec::new();
        if let Some(k) = &known {
            for e in k.unknown_ids(|id| suite.get(id).is_some()) {
                let message = k.unknown_message(e);
                trials.push(Trial::test(format!("plcvec-expectations/{}", e.id), move || Err(Failed::from(message))));
            }
        }
        let shared = Arc::new(Shared { factory: self.factory, plan, known });
        for (index, v) in shared.plan.vectors().iter().enumerate() {
            let trial = if supported[index] {
                let shared = Arc::clone(&shared);
                Trial::ignorable_test(v.id(), move || shared.judge_one(index))
            } else {
                Trial::test(v.id(), || Ok(())).with_ignored_flag(true)
            };
            trials.push(trial);
        }
        Ok(trials)
    }

    /// Parse the arguments, run the tests, and give the exit code (101 on a failure, 2 when the
    /// vectors, the selection or the expectations file cannot be used).
    pub fn run(self) -> ExitCode {
        let listing = self.args.as_ref().map_or_else(|| Arguments::from_args().list, |a| a.list);
        match self.conclude() {
            Ok(conclusion) if !listing && judged_nothing(&conclusion) => {
                eprintln!("plcvec: nothing was judged: every test that ran was skipped or ignored");
                ExitCode::from(101)
            }
            Ok(conclusion) => conclusion.exit_code(),
            Err(e) => {
                eprintln!("plcvec: {e}");
                ExitCode::from(2)
            }
        }
    }

    /// Run the tests and give libtest-mimic's conclusion (for a caller that decides itself).
    pub fn conclude(self) -> Result<Conclusion> {
        let args = self.args.clone().unwrap_or_else(Arguments::from_args);
        let trials = self.trials()?;
        Ok(libtest_mimic::run(&args, trials))
    }
}

/// Whether a run judged nothing: no test passed or failed, and some were skipped or ignored.
pub fn judged_nothing(conclusion: &Conclusion) -> bool {
    conclusion.num_passed == 0 && conclusion.num_failed == 0 && conclusion.num_ignored > 0
}

impl<I, F> Shared<F>
where
    I: Implementation,
    F: Fn() -> I,
{
    fn judge_one(&self, index: usize) -> std::result::Result<Completion, Failed> {
        let (vector, expected) = self.plan.get(index).expect("index within the plan");
        let mut implementation = (self.factory)();
        let mut verdict = judge(&mut implementation, vector, expected);
        if let Some(k) = &self.known {
            verdict = k.apply(vector.id(), verdict);
        }
        match verdict.status {
            Status::Pass => Ok(Completion::Completed),
            Status::Skip | Status::XFail => Ok(Completion::ignored_with(verdict.message)),
            _ => Err(Failed::from(describe(vector, Some(expected), &verdict))),
        }
    }
}
