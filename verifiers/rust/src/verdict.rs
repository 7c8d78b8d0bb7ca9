//! The verdict on one vector and the text a person reads: each differing field ([`Problem`]),
//! the [`Status`], and [`describe`]. A leaf: judging (`compare`), the implementation interface
//! and the runner all build on it.

use std::fmt;

use crate::expect::Expected;
use crate::value::Value;
use crate::vector::Vector;

/// One side of a difference.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Field {
    /// A device value or a contact result.
    Value(Value),
    /// The implementation did not report it.
    Missing,
    /// The vector does not list the device: nothing may be written there.
    Unlisted,
    /// Anything else (a step count).
    Text(String),
}

impl fmt::Display for Field {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Field::Value(v) => write!(f, "{v}"),
            Field::Missing => f.write_str("<not reported>"),
            Field::Unlisted => f.write_str("<not in the vector>"),
            Field::Text(t) => f.write_str(t),
        }
    }
}

/// One field that differs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Problem {
    /// The step (0-based); `None` for the vector as a whole.
    pub step: Option<usize>,
    /// `result`, a device name, or `steps`.
    pub field: String,
    /// What the vector expects.
    pub expected: Field,
    /// What the implementation reported.
    pub actual: Field,
    /// The device's value before the step, when it is a device.
    pub before: Option<Value>,
}

impl Problem {
    pub(crate) fn new(
        step: Option<usize>,
        field: &str,
        expected: Field,
        actual: Field,
        before: Option<Value>,
    ) -> Problem {
        Problem { step, field: field.to_owned(), expected, actual, before }
    }
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(step) = self.step {
            write!(f, "step {step} ")?;
        }
        write!(f, "{}: expected {}, got {}", self.field, self.expected, self.actual)?;
        match (self.before, &self.expected) {
            (Some(b), Field::Value(e)) if b == *e => write!(f, " (the step must leave it unchanged)"),
            (Some(b), _) => write!(f, " (before the step: {b})"),
            _ => Ok(()),
        }
    }
}

/// The verdict on one vector.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Status {
    /// Every field matched.
    Pass,
    /// Some field differs.
    Fail,
    /// The implementation failed on the vector (a refusal with an error, a panic).
    Error,
    /// The implementation cannot run the vector.
    Skip,
    /// A known failure that fails (expectations file).
    XFail,
    /// A known failure that passes, or a listed id the suite lacks: fails the run.
    Stale,
}

impl Status {
    /// Whether this status fails a run.
    pub fn is_failing(self) -> bool {
        matches!(self, Status::Fail | Status::Error | Status::Stale)
    }

    /// The lower-case name (`pass`, `xfail`).
    pub fn as_str(self) -> &'static str {
        match self {
            Status::Pass => "pass",
            Status::Fail => "fail",
            Status::Error => "error",
            Status::Skip => "skip",
            Status::XFail => "xfail",
            Status::Stale => "stale",
        }
    }
}

/// The judgement of one vector.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Verdict {
    /// The status.
    pub status: Status,
    /// The differing fields, for [`Status::Fail`].
    pub problems: Vec<Problem>,
    /// Why: a skip or error reason, or the known failure's entry.
    pub message: String,
}

/// How many differing fields a report shows per vector.
pub const SHOW_PROBLEMS: usize = 12;

/// A failing (or otherwise notable) vector as a person reads it:
///
/// ```text
/// FAIL fx5-time-add/TADD/carry/below-wrap/flags-on-before
///     TADD: 23:00:00 + 00:00:00, flags on before the execution.
///     judged by: TADD-FLAGS-OFF=written-each-execution
///     step 0 SM700: expected false, got true (before the step: true)
///     spec clauses: fx5-time-add#sm700, ...
/// ```
pub fn describe(vector: &Vector, expected: Option<&Expected>, verdict: &Verdict) -> String {
    let mut lines = vec![format!("{} {}", verdict.status.as_str().to_uppercase(), vector.id())];
    if !vector.description().is_empty() {
        lines.push(format!("    {}: {}", vector.instruction(), vector.description()));
    }
    if let Some(e) = expected.filter(|e| !e.choices.is_empty()) {
        let choices: Vec<String> = e.choices.iter().map(|(i, a)| format!("{i}={a}")).collect();
        lines.push(format!("    judged by: {}", choices.join(", ")));
    }
    for p in verdict.problems.iter().take(SHOW_PROBLEMS) {
        lines.push(format!("    {p}"));
    }
    if verdict.problems.len() > SHOW_PROBLEMS {
        lines.push(format!("    ... and {} more differences", verdict.problems.len() - SHOW_PROBLEMS));
    }
    if !verdict.message.is_empty() {
        lines.push(format!("    {}", verdict.message));
    }
    if !vector.clauses().is_empty() {
        lines.push(format!("    spec clauses: {}", vector.clauses().join(", ")));
    }
    lines.join("\n")
}
