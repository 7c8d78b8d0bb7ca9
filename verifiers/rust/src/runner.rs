//! Running a selection of vectors through an implementation in process; the text a person reads
//! at the end of a run is `reports`.

use std::panic::{catch_unwind, AssertUnwindSafe};

use crate::choices::{Choices, Followed};
use crate::compare::{ReportedStep, Steps};
use crate::error::Result;
use crate::expect::{check_choices, Expected};
use crate::generated::names::Instruction;
use crate::implementation::{Implementation, Refusal};
use crate::known::KnownFailures;
use crate::selection::Selection;
use crate::vector::Vector;
use crate::verdict::{Status, Verdict};
use crate::Suite;

/// The expectations of the vectors of one run, worked out once: repeated runs (the benchmark,
/// one test per vector) do not pay for them again.
#[derive(Clone, Debug)]
pub struct Plan<'s> {
    vectors: Vec<&'s Vector>,
    expected: Vec<Expected>,
}

impl<'s> Plan<'s> {
    /// The plan of some of its vectors (by index, in the order given).
    pub(crate) fn subset(&self, indexes: &[usize]) -> Plan<'s> {
        Plan {
            vectors: indexes.iter().map(|&i| self.vectors[i]).collect(),
            expected: indexes.iter().map(|&i| self.expected[i].clone()).collect(),
        }
    }

    /// A report of this plan's vectors with their verdicts and failing answers.
    pub(crate) fn report(
        self,
        suite: &'s Suite,
        implementation: String,
        choices: &Choices,
        cpu_writes: Vec<String>,
        verdicts: Vec<Verdict>,
        answers: Vec<Option<Vec<ReportedStep>>>,
    ) -> Result<Report<'s>> {
        Ok(Report {
            suite,
            implementation,
            interpretations: followed(suite, &self, choices)?,
            plan: self,
            verdicts,
            unknown_known: Vec::new(),
            answers,
            cpu_writes,
            aborted: None,
        })
    }

    /// The expectations of `vectors` (from `suite`) under `choices`, checked against the suite's
    /// interpretations first: an unknown interpretation or alternative is refused.
    pub fn new(suite: &'s Suite, vectors: Vec<&'s Vector>, choices: &Choices) -> Result<Plan<'s>> {
        check_choices(suite, choices)?;
        let defaults = suite.defaults();
        let expected = vectors.iter().map(|v| Expected::of(v, choices, &defaults)).collect::<Result<Vec<_>>>()?;
        Ok(Plan { vectors, expected })
    }

    /// The vectors, in run order.
    pub fn vectors(&self) -> &[&'s Vector] {
        &self.vectors
    }

    /// Each vector with its expectation.
    pub fn iter(&self) -> impl Iterator<Item = (&'s Vector, &Expected)> {
        self.vectors.iter().copied().zip(&self.expected)
    }

    /// The `index`th vector with its expectation.
    pub fn get(&self, index: usize) -> Option<(&'s Vector, &Expected)> {
        Some((*self.vectors.get(index)?, &self.expected[index]))
    }

    /// How many vectors.
    pub fn len(&self) -> usize {
        self.vectors.len()
    }

    /// Whether the plan holds no vector.
    pub fn is_empty(&self) -> bool {
        self.vectors.is_empty()
    }
}

/// Run `vector` through `implementation` and judge it against `expected`. A panic of the
/// implementation is caught and reported as an error on this vector.
pub fn judge<I: Implementation + ?Sized>(implementation: &mut I, vector: &Vector, expected: &Expected) -> Verdict {
    let cpu_writes = implementation.cpu_writes();
    judge_declared(implementation, vector, expected, &cpu_writes)
}

/// [`judge`] with the implementation's `cpu_writes` asked once for many vectors.
fn judge_declared<I: Implementation + ?Sized>(
    implementation: &mut I,
    vector: &Vector,
    expected: &Expected,
    cpu_writes: &[String],
) -> Verdict {
    let outcome = catch_unwind(AssertUnwindSafe(|| {
        let mut steps = Steps::judge(vector, expected, cpu_writes);
        let ran = implementation.run(vector, &mut steps);
        (ran, steps.take_problems())
    }));
    match outcome {
        Ok((Ok(()), problems)) if problems.is_empty() => {
            Verdict { status: Status::Pass, problems, message: String::new() }
        }
        Ok((Ok(()), problems)) => Verdict { status: Status::Fail, problems, message: String::new() },
        Ok((Err(Refusal::Skip(why)), _)) => Verdict { status: Status::Skip, problems: Vec::new(), message: why },
        Ok((Err(Refusal::Error(why)), _)) => Verdict {
            status: Status::Error,
            problems: Vec::new(),
            message: format!("the implementation reported an error: {why}"),
        },
        Err(panic) => {
            let what = panic
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "(no message)".to_owned());
            Verdict {
                status: Status::Error,
                problems: Vec::new(),
                message: format!("the implementation panicked: {what}"),
            }
        }
    }
}

/// The result of a run.
#[derive(Debug)]
pub struct Report<'s> {
    /// The suite the run judged against.
    pub suite: &'s Suite,
    /// The implementation's name.
    pub implementation: String,
    /// Every interpretation of the run's families and the alternative it was judged by.
    pub interpretations: Vec<Followed>,
    /// The plan: the vectors run, with their expectations.
    pub plan: Plan<'s>,
    /// One verdict per vector of the plan, in order.
    pub verdicts: Vec<Verdict>,
    /// Listed known failures the suite has no vector for (each fails the run).
    pub unknown_known: Vec<String>,
    /// The implementation's answer to each vector that failed (for the roll-up by reading).
    pub answers: Vec<Option<Vec<ReportedStep>>>,
    /// The devices the implementation's CPU writes on its own account.
    pub cpu_writes: Vec<String>,
    /// Why the run ended before it judged every vector, if it did: printed as `ABORTED: <why>`.
    pub aborted: Option<String>,
}

/// Run the vectors `selection` keeps through `implementation`; `known` is the expectations file.
///
/// Refused before anything runs: a selection that names a family, instruction, tag or
/// interpretation the suite lacks, or that keeps no vector, and a declaration of an unknown
/// interpretation or alternative. A gate never passes by accident.
pub fn run<'s, I: Implementation + ?Sized>(
    suite: &'s Suite,
    implementation: &mut I,
    selection: &Selection,
    known: Option<&KnownFailures>,
) -> Result<Report<'s>> {
    crate::settings::warn_once();
    let vectors = selection.select(suite)?;
    let choices = implementation.interpretations();
    let plan = Plan::new(suite, vectors, &choices)?;
    let verdicts = judge_plan(&plan, implementation);
    // A failing vector's answer, recorded by running it once more (nothing carries over between
    // vectors): what the roll-up judges under the other alternatives.
    let answers = plan
        .iter()
        .zip(&verdicts)
        .map(|((v, _), verdict)| {
            (verdict.status == Status::Fail).then(|| {
                let mut steps = Steps::record(v);
                let ran = catch_unwind(AssertUnwindSafe(|| implementation.run(v, &mut steps).is_ok()));
                if ran.unwrap_or(false) {
                    steps.into_recorded()
                } else {
                    Vec::new()
                }
            })
        })
        .collect();
    let mut report = Report {
        suite,
        implementation: implementation.name(),
        interpretations: followed(suite, &plan, &choices)?,
        plan,
        verdicts,
        unknown_known: Vec::new(),
        answers,
        cpu_writes: implementation.cpu_writes(),
        aborted: None,
    };
    if let Some(known) = known {
        for (verdict, v) in report.verdicts.iter_mut().zip(report.plan.vectors()) {
            *verdict = known.apply(
                v.id(),
                std::mem::replace(
                    verdict,
                    Verdict { status: Status::Pass, problems: Vec::new(), message: String::new() },
                ),
            );
        }
        report.unknown_known = unknown_known(known, suite);
    }
    Ok(report)
}

/// `<id>: <message>` of each listed known failure the suite has no vector for.
pub(crate) fn unknown_known(known: &KnownFailures, suite: &Suite) -> Vec<String> {
    known
        .unknown_ids(|id| suite.get(id).is_some())
        .map(|e| format!("{}: {}", e.id, known.stale_message(e, suite.merged_into(&e.id))))
        .collect()
}

/// Judge every vector of a plan (the benchmark's loop): unsupported instructions are skipped.
pub fn judge_plan<I: Implementation + ?Sized>(plan: &Plan<'_>, implementation: &mut I) -> Vec<Verdict> {
    judge_plan_marked(plan, implementation, |_, _| ())
}

/// [`judge_plan`] calling `mark(index, true)` before and `mark(index, false)` after the judging of
/// each supported vector: the harness's guard around the same judging, for its benchmark
/// ([`judge_plan`] marks nothing, and the compiler removes the calls).
pub(crate) fn judge_plan_marked<I, M>(plan: &Plan<'_>, implementation: &mut I, mut mark: M) -> Vec<Verdict>
where
    I: Implementation + ?Sized,
    M: FnMut(usize, bool),
{
    // Ask once per instruction the build knows (an unknown one is asked every time), by the
    // enum's index: no hashing per vector.
    let mut asked: Vec<Option<bool>> = vec![None; Instruction::ALL.len()];
    let cpu_writes = implementation.cpu_writes();
    plan.iter()
        .enumerate()
        .map(|(index, (v, expected))| {
            let supported = match v.known_instruction().and_then(|i| asked.get_mut(i as usize)) {
                Some(answer) => *answer.get_or_insert_with(|| implementation.supports(v.instruction())),
                None => implementation.supports(v.instruction()),
            };
            if supported {
                mark(index, true);
                let verdict = judge_declared(implementation, v, expected, &cpu_writes);
                mark(index, false);
                verdict
            } else {
                Verdict {
                    status: Status::Skip,
                    problems: Vec::new(),
                    message: format!("the implementation does not support {}", v.instruction()),
                }
            }
        })
        .collect()
}

fn followed(suite: &Suite, plan: &Plan<'_>, choices: &Choices) -> Result<Vec<Followed>> {
    check_choices(suite, choices)?;
    let families: Vec<&str> = plan.vectors().iter().map(|v| v.family()).collect();
    Ok(suite
        .interpretations()?
        .into_iter()
        .filter(|(_, (_, fams))| fams.iter().any(|f| families.contains(f)))
        .map(|(id, (info, _))| {
            let declared = choices.declared(id);
            Followed {
                interpretation: id.to_owned(),
                alternative: declared.unwrap_or(&info.default).to_owned(),
                declared: declared.is_some(),
            }
        })
        .collect())
}

impl Report<'_> {
    /// How many vectors ended with `status`.
    pub fn count(&self, status: Status) -> usize {
        self.verdicts.iter().filter(|v| v.status == status).count()
            + if status == Status::Stale { self.unknown_known.len() } else { 0 }
    }

    /// The vectors that failed the run, with their verdicts.
    pub fn failures(&self) -> impl Iterator<Item = (&Vector, &Verdict)> {
        self.plan.vectors().iter().copied().zip(&self.verdicts).filter(|(_, v)| v.status.is_failing())
    }

    /// The verdict on one vector, by id.
    pub fn verdict(&self, id: &str) -> Option<&Verdict> {
        self.plan.vectors().iter().position(|v| v.id() == id).map(|i| &self.verdicts[i])
    }

    /// Whether the run passed: nothing failed, and something passed (an implementation that
    /// skips every vector, or fails only its known failures, proves nothing).
    pub fn passed(&self) -> bool {
        self.count(Status::Pass) > 0
            && self.unknown_known.is_empty()
            && !self.verdicts.iter().any(|v| v.status.is_failing())
    }
}
