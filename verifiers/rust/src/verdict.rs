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
    /// For a device the vector lists: what the implementation held before the step (the
    /// vector's value at step 0; its own report of the step before, with this step's `set`).
    pub before: Option<Field>,
    /// For a device the vector lists: whether the vector expects the step to leave it as it was.
    pub keep: bool,
}

impl Problem {
    pub(crate) fn new(
        step: Option<usize>,
        field: &str,
        expected: Field,
        actual: Field,
        before: Option<Field>,
    ) -> Problem {
        Problem { step, field: field.to_owned(), expected, actual, before, keep: false }
    }
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(step) = self.step {
            write!(f, "step {step} ")?;
        }
        write!(f, "{}: expected {}, got {}", self.field, self.expected, self.actual)?;
        let Some(held) = &self.before else { return Ok(()) };
        // "Must leave it unchanged" only where the implementation wrote the device this step.
        let wrote = self.actual != Field::Missing && self.actual != *held;
        match (self.keep && wrote, *held == self.expected) {
            (true, true) => write!(f, " (the step must leave it unchanged)"),
            (true, false) => write!(f, " (before the step: {held}; the step must leave it unchanged)"),
            (false, _) => write!(f, " (before the step: {held})"),
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
    /// Selected but never judged: the run ended before it (a vector took longer than
    /// `PLCVEC_TIMEOUT`). Fails the run; never written as a known failure.
    NotRun,
}

impl Status {
    /// Whether this status fails a run.
    pub fn is_failing(self) -> bool {
        matches!(self, Status::Fail | Status::Error | Status::Stale | Status::NotRun)
    }

    /// The lower-case name (`pass`, `xfail`, `not-run`).
    pub fn as_str(self) -> &'static str {
        match self {
            Status::Pass => "pass",
            Status::Fail => "fail",
            Status::Error => "error",
            Status::Skip => "skip",
            Status::XFail => "xfail",
            Status::Stale => "stale",
            Status::NotRun => "not-run",
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

const INDENT: &str = "    ";

/// A failing (or otherwise notable) vector as a person reads it, in the one text every plcvec
/// runner prints (verifiers/parity/TEXT.md, "The failure block"):
///
/// ```text
/// FAIL fx5-time-add/TADD/carry/below-wrap/flags-on-before
///     TADD: 23:00:00 + 00:00:00, flags on before the execution.
///     judged by: TADD-FLAGS-OFF=written-each-execution
///     step 0 inputs: en=true
///     step 0 operands: d D300=65535 65535 65535, s1 D100=23 0 0, s2 D200=0 0 0
///     step 0 SM700: expected false, got true (before the step: true)
///     spec clauses: fx5-time-add#data-type, ...
/// ```
pub fn describe(vector: &Vector, expected: Option<&Expected>, verdict: &Verdict) -> String {
    let mut lines = vec![format!("{} {}", verdict.status.as_str().to_uppercase(), vector.id())];
    if !vector.description().is_empty() {
        lines.push(format!("{INDENT}{}: {}", vector.instruction(), vector.description()));
    }
    if let Some(e) = expected {
        let deciding = judged_by(vector, e, &verdict.problems);
        if !deciding.is_empty() {
            let list: Vec<String> = deciding.iter().map(|(i, a)| format!("{i}={a}")).collect();
            lines.push(format!("{INDENT}judged by: {}", list.join(", ")));
        }
        lines.extend(not_judged(vector, e));
    }
    let mut shown_step = None;
    for p in verdict.problems.iter().take(SHOW_PROBLEMS) {
        if let (Some(step), Some(e)) = (p.step, expected) {
            if shown_step != Some(step) {
                shown_step = Some(step);
                lines.push(format!("{INDENT}step {step} inputs: {}", inputs(vector, step)));
                lines.push(format!("{INDENT}step {step} operands: {}", operands(vector, e, step)));
            }
        }
        lines.push(format!("{INDENT}{p}"));
    }
    if verdict.problems.len() > SHOW_PROBLEMS {
        lines.push(format!("{INDENT}... and {} more differences", verdict.problems.len() - SHOW_PROBLEMS));
    }
    if !verdict.message.is_empty() {
        lines.push(format!("{INDENT}{}", verdict.message));
    }
    if !vector.clauses().is_empty() {
        lines.push(format!("{INDENT}spec clauses: {}", vector.clauses().join(", ")));
    }
    lines.join("\n")
}

/// The interpretations that decide a differing field: those for which the vector offers an
/// expectation differing from the followed one in that interpretation only, and differing at
/// the field. Each with the alternative followed, sorted.
pub(crate) fn judged_by(vector: &Vector, expected: &Expected, problems: &[Problem]) -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = Vec::new();
    if expected.choices.is_empty() || problems.is_empty() {
        return out;
    }
    for combination in expected.offered(vector) {
        let differing: Vec<&(String, String)> = combination.iter().filter(|c| !expected.choices.contains(c)).collect();
        let [(interpretation, _)] = differing.as_slice() else { continue };
        if out.iter().any(|(i, _)| i == interpretation) {
            continue;
        }
        let Some(other) = expected.under(vector, &combination) else { continue };
        let decides = problems.iter().any(|p| {
            let Some(step) = p.step else { return false };
            if p.field == "result" {
                return expected.results().get(step) != other.results().get(step);
            }
            // unjudged.md: it decides a field the other reading leaves unjudged, too.
            match (vector.slot(&p.field), expected.state(step), other.state(step)) {
                (Some(slot), Some(a), Some(b)) => a[slot] != b[slot] || other.is_unjudged(slot),
                _ => false,
            }
        });
        if decides {
            let followed = expected.choices.iter().find(|(i, _)| i == interpretation).cloned();
            out.extend(followed);
        }
    }
    out.sort();
    out
}

/// `not judged under <ID>=<alternative>: <device>, ...`, one line per interpretation whose
/// followed alternative leaves devices unjudged, sorted by ID (unjudged.md, "The failure block").
fn not_judged(vector: &Vector, expected: &Expected) -> Vec<String> {
    let mut lines: Vec<(&str, String)> = expected
        .unjudged()
        .iter()
        .map(|(interpretation, slots)| {
            let alternative =
                expected.choices.iter().find(|(i, _)| i == interpretation).map_or("", |(_, a)| a.as_str());
            let mut devices: Vec<&str> = slots.iter().map(|&s| vector.devices()[s].name()).collect();
            devices.sort_unstable();
            let line = format!("{INDENT}not judged under {interpretation}={alternative}: {}", devices.join(", "));
            (interpretation.as_str(), line)
        })
        .collect();
    lines.sort();
    lines.into_iter().map(|(_, line)| line).collect()
}

/// A step's inputs: `clock=4:02:41, rlo_in=true`, then its `set`.
fn inputs(vector: &Vector, step: usize) -> String {
    let Some(s) = vector.steps().get(step) else { return "(none)".into() };
    let mut parts: Vec<String> = Vec::new();
    if let Some(clock) = &s.clock {
        let fields: Vec<(&str, i64)> = clock.fields().collect();
        let get = |name: &str| fields.iter().find(|(n, _)| *n == name).map(|&(_, v)| v);
        let date: Vec<String> = ["year", "month", "day"].iter().filter_map(|f| get(f)).map(|v| v.to_string()).collect();
        let time: Vec<String> = ["hour", "minute", "second"]
            .iter()
            .filter_map(|f| get(f))
            .enumerate()
            .map(|(k, v)| if k == 0 { v.to_string() } else { format!("{v:02}") })
            .collect();
        let mut text =
            [date.join("/"), time.join(":")].into_iter().filter(|t| !t.is_empty()).collect::<Vec<_>>().join(" ");
        for (name, v) in &fields {
            if !["year", "month", "day", "hour", "minute", "second"].contains(name) {
                text.push_str(&format!(" {name}={v}"));
            }
        }
        parts.push(format!("clock={text}"));
    }
    for (name, v) in [("rlo_in", s.rlo_in), ("en", s.en), ("input", s.input)] {
        if let Some(b) = v {
            parts.push(format!("{name}={b}"));
        }
    }
    if let Some(ms) = s.elapsed_ms {
        parts.push(format!("elapsed_ms={ms}"));
    }
    if !s.set().is_empty() {
        let mut set: Vec<(&str, Value)> = s.set().iter().map(|&(i, v)| (vector.devices()[i].name(), v)).collect();
        set.sort_by(|a, b| a.0.cmp(b.0));
        let set: Vec<String> = set.iter().map(|(n, v)| format!("{n}={v}")).collect();
        parts.push(format!("set {}", set.join(" ")));
    }
    if parts.is_empty() {
        return "(none)".into();
    }
    parts.join(", ")
}

/// Each operand with its words in the vector's state before the step.
fn operands(vector: &Vector, expected: &Expected, step: usize) -> String {
    let slots = vector.devices().len();
    let state: Vec<Value> = (0..slots).map(|i| expected.before(vector, step, i)).collect();
    let operand_devices: Vec<&str> =
        vector.operands().iter().filter_map(|(_, o)| o.device()).map(|a| a.name()).collect();
    let scratch = vector.scratch();
    let parts: Vec<String> = vector
        .operands()
        .iter()
        .map(|(name, o)| match o {
            crate::vector::Operand::Constant(c) => format!("{name} constant {c}"),
            crate::vector::Operand::Device(a) => {
                let Some(first) = vector.slot(a.name()) else { return format!("{name} {a} (not in the vector)") };
                if scratch[first] {
                    return format!("{name} {a} (scratch)");
                }
                let mut words = vec![state[first].to_string()];
                if state[first].word().is_some() {
                    let mut offset = 1;
                    while let Some(slot) = vector.slot_at(a, offset) {
                        let next = vector.devices()[slot].name();
                        if scratch[slot] || state[slot].word().is_none() || operand_devices.contains(&next) {
                            break;
                        }
                        words.push(state[slot].to_string());
                        offset += 1;
                    }
                }
                format!("{name} {a}={}", words.join(" "))
            }
        })
        .collect();
    parts.join(", ")
}
