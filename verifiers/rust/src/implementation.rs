//! What an implementation provides: the contract-level [`Implementation`] trait, and the thin
//! [`Execute`] helper for emulators that only want to execute one instruction on their memory.

use std::fmt;

use crate::choices::Choices;
use crate::compare::{Field, Problem};
use crate::expect::Expected;
use crate::memory::Memory;
use crate::small::Small;
use crate::value::Value;
use crate::vector::{Step, Vector, INLINE_SLOTS};

/// Why an implementation did not run a vector.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Refusal {
    /// It cannot run this vector (say why: "no R devices"); reported as skipped, not failed.
    Skip(String),
    /// It failed on this vector (an unsupported operand form, an internal error); fails the run.
    Error(String),
}

impl fmt::Display for Refusal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Refusal::Skip(why) => write!(f, "skipped: {why}"),
            Refusal::Error(why) => write!(f, "error: {why}"),
        }
    }
}

/// An implementation under test, at the level of the contract (CONTRACT.md): it gets one
/// vector's initial state and its steps' inputs, and reports after every step the device image
/// and, for contact instructions, the result.
pub trait Implementation {
    /// The name reports show.
    fn name(&self) -> String {
        "implementation".to_owned()
    }

    /// The interpretation alternatives it follows; undeclared ones take the default.
    fn interpretations(&self) -> Choices {
        Choices::new()
    }

    /// Whether it implements an instruction (`LDTM<=`); vectors of others are skipped.
    fn supports(&self, instruction: &str) -> bool {
        let _ = instruction;
        true
    }

    /// Run every step of `vector` from its initial state, and report each step to `steps`
    /// ([`Steps::memory`] or [`Steps::devices`]) as soon as it is executed. Nothing carries over
    /// from an earlier vector.
    fn run(&mut self, vector: &Vector, steps: &mut Steps<'_>) -> Result<(), Refusal>;
}

impl<I: Implementation + ?Sized> Implementation for Box<I> {
    fn name(&self) -> String {
        (**self).name()
    }
    fn interpretations(&self) -> Choices {
        (**self).interpretations()
    }
    fn supports(&self, instruction: &str) -> bool {
        (**self).supports(instruction)
    }
    fn run(&mut self, vector: &Vector, steps: &mut Steps<'_>) -> Result<(), Refusal> {
        (**self).run(vector, steps)
    }
}

/// "Execute this instruction on my memory": the thin way to implement the contract. Wrap it in
/// [`OnMemory`] to get an [`Implementation`]: the wrapper builds the vector's [`Memory`],
/// applies each step's `set`, calls [`Execute::execute`] and reports the image.
pub trait Execute {
    /// The name reports show.
    fn name(&self) -> String {
        "implementation".to_owned()
    }

    /// The interpretation alternatives it follows; undeclared ones take the default.
    fn interpretations(&self) -> Choices {
        Choices::new()
    }

    /// Whether it implements an instruction.
    fn supports(&self, instruction: &str) -> bool {
        let _ = instruction;
        true
    }

    /// A new vector starts: forget any state an earlier one left (the previous EN of TADDP, the
    /// HOUR work area), and refuse the vector if it cannot be run (an operand form you lack).
    fn begin(&mut self, vector: &Vector) -> Result<(), Refusal> {
        let _ = vector;
        Ok(())
    }

    /// Execute `vector.instruction()` once with the step's inputs on `memory`; return the logic
    /// state after it for LD/AND/OR forms, `None` for the others.
    fn execute(&mut self, vector: &Vector, step: &Step, memory: &mut Memory<'_>) -> Result<Option<bool>, Refusal>;
}

/// An [`Execute`] as an [`Implementation`].
#[derive(Clone, Debug, Default)]
pub struct OnMemory<E>(pub E);

impl<E: Execute> Implementation for OnMemory<E> {
    fn name(&self) -> String {
        self.0.name()
    }
    fn interpretations(&self) -> Choices {
        self.0.interpretations()
    }
    fn supports(&self, instruction: &str) -> bool {
        self.0.supports(instruction)
    }
    fn run(&mut self, vector: &Vector, steps: &mut Steps<'_>) -> Result<(), Refusal> {
        self.0.begin(vector)?;
        let mut memory = Memory::new(vector);
        for step in vector.steps() {
            memory.apply_set(step);
            let result = self.0.execute(vector, step, &mut memory)?;
            steps.memory(result, &memory);
        }
        Ok(())
    }
}

/// One step as an implementation reported it (what the protocol sends back).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReportedStep {
    /// The contact result, for contact instructions.
    pub result: Option<bool>,
    /// The device image after the step.
    pub devices: Vec<(String, Value)>,
}

enum Mode<'a> {
    Judge { expected: &'a Expected, problems: Vec<Problem> },
    Record { steps: Vec<ReportedStep> },
}

/// Where an implementation reports its steps. While judging, each step is compared as soon as
/// it is reported (nothing is copied for a step that matches); while serving the protocol, the
/// steps are recorded.
pub struct Steps<'a> {
    vector: &'a Vector,
    mode: Mode<'a>,
    count: usize,
}

impl<'a> Steps<'a> {
    pub(crate) fn judge(vector: &'a Vector, expected: &'a Expected) -> Steps<'a> {
        Steps { vector, mode: Mode::Judge { expected, problems: Vec::new() }, count: 0 }
    }

    pub(crate) fn record(vector: &'a Vector) -> Steps<'a> {
        Steps { vector, mode: Mode::Record { steps: Vec::with_capacity(vector.steps().len()) }, count: 0 }
    }

    /// Report a step from a [`Memory`] of this vector (the fast path).
    pub fn memory(&mut self, result: Option<bool>, memory: &Memory<'_>) {
        let step = self.count;
        self.count += 1;
        match &mut self.mode {
            Mode::Judge { expected, problems } => {
                let Some(want) = expected.state(step) else { return };
                check_result(step, expected.results()[step], result, problems);
                let got = memory.values();
                if got.len() != want.len() {
                    problems.push(Problem::new(
                        Some(step),
                        "devices",
                        Field::Text("this vector's memory".into()),
                        Field::Text("another vector's memory".into()),
                        None,
                    ));
                    return;
                }
                if got != want {
                    let scratch = self.vector.scratch();
                    for (i, (g, w)) in got.iter().zip(want).enumerate() {
                        if g != w && !scratch[i] {
                            let before = expected.before(self.vector, step, i);
                            problems.push(Problem::new(
                                Some(step),
                                self.vector.devices()[i].name(),
                                Field::Value(*w),
                                Field::Value(*g),
                                Some(before),
                            ));
                        }
                    }
                }
                for (name, v) in memory.outside() {
                    problems.push(Problem::new(Some(step), name, Field::Unlisted, Field::Value(*v), None));
                }
            }
            Mode::Record { steps } => {
                let devices = self
                    .vector
                    .devices()
                    .iter()
                    .zip(memory.values())
                    .map(|(a, v)| (a.name().to_owned(), *v))
                    .chain(memory.outside().iter().cloned())
                    .collect();
                steps.push(ReportedStep { result, devices });
            }
        }
    }

    /// Report a step as `(device, value)` pairs: every device the vector lists (scratch may be
    /// left out), plus any other device the step wrote.
    pub fn devices<'d>(&mut self, result: Option<bool>, devices: impl IntoIterator<Item = (&'d str, Value)>) {
        let step = self.count;
        self.count += 1;
        match &mut self.mode {
            Mode::Judge { expected, problems } => {
                let Some(want) = expected.state(step) else { return };
                check_result(step, expected.results()[step], result, problems);
                let mut got: Small<Option<Value>, INLINE_SLOTS> = Small::filled(None, want.len());
                for (name, v) in devices {
                    match self.vector.slot(name) {
                        Some(i) => got[i] = Some(v),
                        None => problems.push(Problem::new(Some(step), name, Field::Unlisted, Field::Value(v), None)),
                    }
                }
                let scratch = self.vector.scratch();
                for (i, (g, w)) in got.iter().zip(want).enumerate() {
                    if scratch[i] || *g == Some(*w) {
                        continue;
                    }
                    let actual = g.map_or(Field::Missing, Field::Value);
                    problems.push(Problem::new(
                        Some(step),
                        self.vector.devices()[i].name(),
                        Field::Value(*w),
                        actual,
                        Some(expected.before(self.vector, step, i)),
                    ));
                }
                problems.sort_by(|a, b| (a.step, &a.field).cmp(&(b.step, &b.field)));
            }
            Mode::Record { steps } => {
                steps.push(ReportedStep {
                    result,
                    devices: devices.into_iter().map(|(n, v)| (n.to_owned(), v)).collect(),
                });
            }
        }
    }

    /// The judged problems (with a step-count check), once the implementation is done.
    pub(crate) fn into_problems(self) -> Vec<Problem> {
        match self.mode {
            Mode::Judge { expected, mut problems } => {
                if self.count != expected.steps() {
                    problems.insert(
                        0,
                        Problem::new(
                            None,
                            "steps",
                            Field::Text(format!("{} steps", expected.steps())),
                            Field::Text(format!("{} steps", self.count)),
                            None,
                        ),
                    );
                }
                problems
            }
            Mode::Record { .. } => Vec::new(),
        }
    }

    pub(crate) fn into_recorded(self) -> Vec<ReportedStep> {
        match self.mode {
            Mode::Record { steps } => steps,
            Mode::Judge { .. } => Vec::new(),
        }
    }
}

fn check_result(step: usize, want: Option<bool>, got: Option<bool>, problems: &mut Vec<Problem>) {
    if let Some(w) = want {
        if got != Some(w) {
            let actual = got.map_or(Field::Missing, |g| Field::Value(Value::Bit(g)));
            problems.push(Problem::new(Some(step), "result", Field::Value(Value::Bit(w)), actual, None));
        }
    }
}
