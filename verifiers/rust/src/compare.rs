//! Judging one vector: every field compared exactly (with its JSON type) as soon as the
//! implementation reports a step ([`Steps`]), each difference a [`Problem`].

use crate::expect::Expected;
use crate::keys::INLINE_SLOTS;
use crate::memory::Memory;
use crate::small::Small;
use crate::value::Value;
use crate::vector::Vector;
use crate::verdict::{Field, Problem};

/// One step as an implementation reported it (what the protocol sends back).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReportedStep {
    /// The contact result, for contact instructions.
    pub result: Option<bool>,
    /// The device image after the step.
    pub devices: Vec<(String, Value)>,
}

enum Mode<'a> {
    Judge {
        expected: &'a Expected,
        cpu_writes: &'a [String],
        problems: Vec<Problem>,
        /// The implementation's own report of the previous step (listed devices; `None` where it
        /// reported nothing), kept only for a vector of more than one step: what it held before
        /// the next step, shown beside a difference.
        previous: Option<Small<Option<Value>, INLINE_SLOTS>>,
    },
    Record {
        steps: Vec<ReportedStep>,
    },
}

/// Where an implementation reports its steps. While judging, each step is compared as soon as
/// it is reported (nothing is copied for a step that matches); while serving the protocol, the
/// steps are recorded.
pub struct Steps<'a> {
    vector: &'a Vector,
    mode: Mode<'a>,
    count: usize,
}

/// One listed device that differs: the problem with what the implementation held before the
/// step and whether the vector expects the step to leave it unchanged.
fn device_problem(
    vector: &Vector,
    expected: &Expected,
    previous: Option<&Small<Option<Value>, INLINE_SLOTS>>,
    step: usize,
    slot: usize,
    actual: Field,
) -> Problem {
    let before = expected.before(vector, step, slot);
    let want = expected.state(step).map_or(before, |s| s[slot]);
    let set = vector.steps().get(step).and_then(|s| s.set().iter().find(|(i, _)| *i == slot));
    let held = match (set, previous) {
        (Some(&(_, v)), _) => Field::Value(v),
        (None, Some(p)) if step > 0 => p[slot].map_or(Field::Missing, Field::Value),
        _ => Field::Value(before),
    };
    let mut p = Problem::new(Some(step), vector.devices()[slot].name(), Field::Value(want), actual, Some(held));
    p.keep = want == before;
    p
}

impl<'a> Steps<'a> {
    /// Steps judged against `expected`; a write outside the vector to one of `cpu_writes` (the
    /// devices the implementation's CPU writes on its own account) is not a stray write.
    #[inline]
    pub(crate) fn judge(vector: &'a Vector, expected: &'a Expected, cpu_writes: &'a [String]) -> Steps<'a> {
        let previous = (vector.steps().len() > 1).then(|| Small::filled(None, vector.devices().len()));
        Steps { vector, mode: Mode::Judge { expected, cpu_writes, problems: Vec::new(), previous }, count: 0 }
    }

    pub(crate) fn record(vector: &'a Vector) -> Steps<'a> {
        Steps { vector, mode: Mode::Record { steps: Vec::with_capacity(vector.steps().len()) }, count: 0 }
    }

    /// Count the next step and, while judging, check its result: the step's index and its
    /// expected image (`None` for a step past the vector's, found by the count at the end).
    /// Both ways of reporting a step begin here.
    #[inline]
    fn next_step(&mut self, result: Option<bool>) -> (usize, Option<&'a [Value]>) {
        let step = self.count;
        self.count += 1;
        let Mode::Judge { expected, problems, .. } = &mut self.mode else { return (step, None) };
        let expected: &'a Expected = expected;
        let want = expected.state(step);
        if want.is_some() {
            check_result(step, expected.results()[step], result, problems);
        }
        (step, want)
    }

    /// Report a step from a [`Memory`] of this vector (the fast path).
    pub fn memory(&mut self, result: Option<bool>, memory: &Memory<'_>) {
        let (step, want) = self.next_step(result);
        match &mut self.mode {
            Mode::Judge { expected, cpu_writes, problems, previous } => {
                let Some(want) = want else { return };
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
                    let skip = expected.passed_over(self.vector);
                    for (i, (g, w)) in got.iter().zip(want).enumerate() {
                        if g != w && !skip[i] {
                            let p = device_problem(self.vector, expected, previous.as_ref(), step, i, Field::Value(*g));
                            problems.push(p);
                        }
                    }
                }
                for (name, v) in memory.outside() {
                    if !cpu_writes.contains(name) {
                        problems.push(Problem::new(Some(step), name, Field::Unlisted, Field::Value(*v), None));
                    }
                }
                if let Some(previous) = previous {
                    for (p, g) in previous.iter_mut().zip(got) {
                        *p = Some(*g);
                    }
                }
            }
            Mode::Record { steps } => {
                let devices = memory.image().map(|(name, v)| (name.to_owned(), v)).collect();
                steps.push(ReportedStep { result, devices });
            }
        }
    }

    /// Report a step as `(device, value)` pairs: every device the vector lists (scratch may be
    /// left out), plus any other device the step wrote.
    pub fn devices<'d>(&mut self, result: Option<bool>, devices: impl IntoIterator<Item = (&'d str, Value)>) {
        let (step, want) = self.next_step(result);
        match &mut self.mode {
            Mode::Judge { expected, cpu_writes, problems, previous } => {
                let Some(want) = want else { return };
                let mut got: Small<Option<Value>, INLINE_SLOTS> = Small::filled(None, want.len());
                let mut twice: Vec<usize> = Vec::new();
                for (name, v) in devices {
                    match self.vector.slot(name) {
                        // A device reported twice is a broken report whichever value is meant:
                        // never settled by keeping the first or the last.
                        Some(i) if got[i].is_some() => {
                            if !twice.contains(&i) {
                                twice.push(i);
                                problems.push(Problem::new(
                                    Some(step),
                                    name,
                                    Field::Value(want[i]),
                                    Field::Text(format!("reported twice ({} and {v})", got[i].unwrap_or(v))),
                                    None,
                                ));
                            }
                        }
                        Some(i) => got[i] = Some(v),
                        None if cpu_writes.iter().any(|c| c == name) => {}
                        None => problems.push(Problem::new(Some(step), name, Field::Unlisted, Field::Value(v), None)),
                    }
                }
                let skip = expected.passed_over(self.vector);
                for (i, (g, w)) in got.iter().zip(want).enumerate() {
                    if skip[i] || *g == Some(*w) || twice.contains(&i) {
                        continue;
                    }
                    let actual = g.map_or(Field::Missing, Field::Value);
                    problems.push(device_problem(self.vector, expected, previous.as_ref(), step, i, actual));
                }
                if let Some(previous) = previous {
                    *previous = got;
                }
            }
            Mode::Record { steps } => {
                steps.push(ReportedStep {
                    result,
                    devices: devices.into_iter().map(|(n, v)| (n.to_owned(), v)).collect(),
                });
            }
        }
    }

    /// The judged problems, once the implementation is done: per step the result first, then
    /// the devices by name; a report with another number of steps is that one problem alone.
    /// Taken out by reference: the judging state is not moved (a copy of it per vector).
    #[inline]
    pub(crate) fn take_problems(&mut self) -> Vec<Problem> {
        match &mut self.mode {
            Mode::Judge { expected, problems, .. } => {
                if self.count != expected.steps() {
                    return vec![Problem::new(
                        None,
                        "steps",
                        Field::Text(format!("{} steps", expected.steps())),
                        Field::Text(format!("{} steps", self.count)),
                        None,
                    )];
                }
                let mut problems = std::mem::take(problems);
                problems.sort_by(|a, b| {
                    (a.step, a.field != "result", &a.field).cmp(&(b.step, b.field != "result", &b.field))
                });
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

/// The problems of a recorded answer against `expected` (the same comparison as a run's).
pub(crate) fn compare(
    vector: &Vector,
    expected: &Expected,
    cpu_writes: &[String],
    answer: &[ReportedStep],
) -> Vec<Problem> {
    let mut steps = Steps::judge(vector, expected, cpu_writes);
    for step in answer {
        steps.devices(step.result, step.devices.iter().map(|(n, v)| (n.as_str(), *v)));
    }
    steps.take_problems()
}

fn check_result(step: usize, want: Option<bool>, got: Option<bool>, problems: &mut Vec<Problem>) {
    if let Some(w) = want {
        if got != Some(w) {
            let actual = got.map_or(Field::Missing, |g| Field::Value(Value::Bit(g)));
            problems.push(Problem::new(Some(step), "result", Field::Value(Value::Bit(w)), actual, None));
        }
    }
}
