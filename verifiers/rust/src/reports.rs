//! The text a person reads at the end of a run, as every plcvec runner prints it
//! (verifiers/parity/TEXT.md): each failing vector with its field diff, the roll-up by reading,
//! skips by reason, then the totals, with the suite version, the spec hash, and the alternative
//! followed for every interpretation.

use std::collections::BTreeMap;

use crate::infer::{Rollup, Syntax};
use crate::runner::Report;
use crate::verdict::{describe, Status};

impl Report<'_> {
    /// The summary a person reads: the run's text with its header line, without the time.
    pub fn summary(&self) -> String {
        self.text(true, None)
    }

    /// The run's text as every plcvec runner prints it (verifiers/parity/TEXT.md): each failing
    /// vector's block, the roll-up by reading, skips by reason, then the summary lines; the
    /// header line (which names the machine's paths) only with `header`, and the totals with
    /// ` in <t> s` only given the seconds.
    pub fn text(&self, header: bool, seconds: Option<f64>) -> String {
        self.blocks() + &self.text_after_blocks(header, seconds)
    }

    /// The failure blocks of the run's text, stale known failures the suite lacks last.
    fn blocks(&self) -> String {
        let mut out = String::new();
        for ((v, e), verdict) in self.plan.iter().zip(&self.verdicts) {
            if verdict.status.is_failing() {
                out.push_str(&describe(v, Some(e), verdict));
                out.push('\n');
            }
        }
        for line in &self.unknown_known {
            let (id, message) = line.split_once(": ").unwrap_or((line, ""));
            out.push_str(&format!("STALE {id}\n    {message}\n"));
        }
        out
    }

    /// The run's text after the failure blocks: the roll-up by reading, skips by reason and the
    /// summary lines (for a test harness that printed each block with its test).
    pub fn text_after_blocks(&self, header: bool, seconds: Option<f64>) -> String {
        self.text_ending(header, seconds, None)
    }

    /// [`Report::text_after_blocks`] with the line that says why a run without a failure did not
    /// pass (`NOT PASSED (exit 5): nothing passed ...`), printed where `ABORTED:` would be.
    pub(crate) fn text_ending(&self, header: bool, seconds: Option<f64>, not_passed: Option<&str>) -> String {
        self.ending(header, seconds, not_passed, Syntax::Rust)
    }

    /// The run's text with the roll-up's declarations written as `plcvec verify`'s `--choose`
    /// options, the form of the shared cases' expected text (verifiers/parity/text); for the
    /// project's own test of that text, not part of the API.
    #[doc(hidden)]
    pub fn text_as_plcvec_verify(&self, header: bool, seconds: Option<f64>) -> String {
        self.blocks() + &self.ending(header, seconds, None, Syntax::Choose)
    }

    /// The roll-up's declaration of `changes` (interpretation id, alternative) in this crate's
    /// syntax, as TEXT.md's table of declarations gives it; not part of the API.
    #[doc(hidden)]
    pub fn declaration(changes: &[(&str, &str)]) -> String {
        let changes: Vec<(String, String)> = changes.iter().map(|(i, a)| ((*i).to_owned(), (*a).to_owned())).collect();
        crate::infer::declaration(Syntax::Rust, &changes)
    }

    /// The roll-up by reading of this run (empty when nothing failed and nothing is a known
    /// failure).
    fn rollup(&self, syntax: Syntax) -> String {
        let followed: BTreeMap<String, String> =
            self.interpretations.iter().map(|f| (f.interpretation.clone(), f.alternative.clone())).collect();
        let alternatives: crate::infer::Alternatives = self
            .suite
            .interpretations()
            .map(|all| all.into_iter().map(|(id, (info, _))| (id.to_owned(), info.alternatives.clone())).collect())
            .unwrap_or_default();
        let cases: Vec<crate::infer::Case<'_>> = self
            .plan
            .iter()
            .zip(&self.verdicts)
            .zip(&self.answers)
            .map(|(((vector, expected), verdict), answer)| crate::infer::Case {
                vector,
                expected,
                status: verdict.status,
                answer: answer.as_deref(),
            })
            .collect();
        // The inference only has something to explain when a vector failed or is a known failure.
        if !cases.iter().any(|c| matches!(c.status, Status::Fail | Status::Error | Status::NotRun | Status::XFail)) {
            return String::new();
        }
        let inference = crate::infer::infer(&cases, &followed, &alternatives, &self.cpu_writes);
        let known_file = self.verdicts.iter().find(|v| v.status == Status::XFail).and_then(|v| known_file(&v.message));
        let r = Rollup { inference: &inference, followed: &followed, syntax, known_file };
        crate::infer::rollup(&cases, &r)
    }

    fn ending(&self, header: bool, seconds: Option<f64>, not_passed: Option<&str>, syntax: Syntax) -> String {
        let mut out = self.rollup(syntax);
        let skipped: Vec<&str> =
            self.verdicts.iter().filter(|v| v.status == Status::Skip).map(|v| v.message.as_str()).collect();
        out.push_str(&crate::infer::skips(&skipped, self.verdicts.len()));
        if let Some(why) = &self.aborted {
            out.push_str(&format!("ABORTED: {why}\n"));
        } else if let Some(line) = not_passed {
            out.push_str(&format!("{line}\n"));
        }
        out.push('\n');
        if header {
            let s = self.suite;
            out.push_str(&format!(
                "plcvec: {} against {} (suite {}, schema {}, spec sha256 {})\n",
                self.implementation,
                s.source(),
                if s.suite_version().is_empty() { "?" } else { s.suite_version() },
                s.schema_version(),
                s.spec_sha256().get(..12).unwrap_or("?"),
            ));
        }
        let interpretations: Vec<String> = self
            .interpretations
            .iter()
            .map(|f| {
                format!("{}={} ({})", f.interpretation, f.alternative, if f.declared { "declared" } else { "default" })
            })
            .collect();
        let interpretations = if interpretations.is_empty() { "(none)".to_owned() } else { interpretations.join(", ") };
        out.push_str(&format!("interpretations: {interpretations}\n"));
        if !self.cpu_writes.is_empty() {
            let mut devices = self.cpu_writes.clone();
            devices.sort();
            out.push_str(&format!("cpu_writes: {}\n", devices.join(", ")));
        }
        let counts: Vec<String> =
            [Status::Pass, Status::Fail, Status::Error, Status::Skip, Status::XFail, Status::Stale, Status::NotRun]
                .iter()
                .filter(|&&st| self.count(st) > 0 || matches!(st, Status::Pass | Status::Fail | Status::Skip))
                .map(|&st| format!("{} {}", self.count(st), st.as_str()))
                .collect();
        out.push_str(&format!("{} vectors: {}", self.verdicts.len() + self.unknown_known.len(), counts.join(", ")));
        if let Some(t) = seconds {
            out.push_str(&format!(" in {t:.2} s"));
        }
        out.push('\n');
        out
    }
}

/// The known-failures file's name as a known failure's message gives it
/// (`known failure (<file>:<line>): <reason>`).
fn known_file(message: &str) -> Option<&str> {
    let at = message.strip_prefix("known failure (")?.split_once("): ")?.0;
    Some(at.rsplit_once(':')?.0)
}
