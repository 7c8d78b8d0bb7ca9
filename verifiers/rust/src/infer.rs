//! The roll-up by reading (verifiers/parity/TEXT.md, "The inference"): which alternatives the
//! implementation's answers follow, the failures another reading explains, grouped by the
//! smallest change that explains each, and the failures no reading explains, by their clauses.

use std::collections::BTreeMap;

use crate::compare::{compare, ReportedStep};
use crate::expect::Expected;
use crate::vector::Vector;
use crate::verdict::Status;

/// One vector of a run as the inference sees it.
pub(crate) struct Case<'a> {
    pub vector: &'a Vector,
    pub expected: &'a Expected,
    pub status: Status,
    /// The implementation's answer, for a vector that failed.
    pub answer: Option<&'a [ReportedStep]>,
}

type Combination = Vec<(String, String)>;

/// interpretation -> the alternatives the vector files list, in their order.
pub(crate) type Alternatives = BTreeMap<String, Vec<String>>;

struct Judged<'a> {
    case: &'a Case<'a>,
    /// combination of the vector's interpretations -> whether the vector passes under it.
    memo: std::cell::RefCell<BTreeMap<Combination, bool>>,
}

impl Judged<'_> {
    fn touched(&self) -> impl Iterator<Item = &String> {
        self.case.expected.choices.iter().map(|(i, _)| i)
    }

    fn passes(&self, choice: &BTreeMap<String, String>, cpu_writes: &[String]) -> bool {
        let combination: Combination =
            self.case.expected.choices.iter().map(|(i, a)| (i.clone(), choice.get(i).unwrap_or(a).clone())).collect();
        if let Some(&known) = self.memo.borrow().get(&combination) {
            return known;
        }
        let case = self.case;
        // Under the alternatives it was judged by, a vector passes exactly when it passed.
        let passed = if combination.is_empty() || combination == case.expected.choices {
            case.status == Status::Pass
        } else {
            match case.expected.under(case.vector, &combination) {
                None => false,
                Some(other) => match case.answer {
                    Some(answer) if case.status != Status::Pass => {
                        compare(case.vector, &other, cpu_writes, answer).is_empty()
                    }
                    _ => case.status == Status::Pass && other.same_outcome(case.expected),
                },
            }
        };
        self.memo.borrow_mut().insert(combination, passed);
        passed
    }
}

/// What the inference found.
pub(crate) struct Inference {
    /// interpretation -> the alternative chosen.
    pub choice: BTreeMap<String, String>,
    /// Explained failing vectors (index into the cases) with their smallest change.
    pub explained: Vec<(usize, Combination)>,
    /// Failing vectors no reading explains (indexes).
    pub unexplained: Vec<usize>,
    /// Passing vectors that would fail under the choice.
    pub broken: usize,
}

fn failing(status: Status) -> bool {
    matches!(status, Status::Fail | Status::Error | Status::NotRun)
}

/// Run the inference over the cases, from the followed alternatives.
pub(crate) fn infer(
    cases: &[Case<'_>],
    followed: &BTreeMap<String, String>,
    alternatives: &Alternatives,
    cpu_writes: &[String],
) -> Inference {
    let judged: Vec<(usize, Judged<'_>)> = cases
        .iter()
        .enumerate()
        .filter(|(_, c)| matches!(c.status, Status::Pass | Status::Fail | Status::XFail))
        .map(|(k, c)| (k, Judged { case: c, memo: Default::default() }))
        .collect();
    let mut choice = followed.clone();
    let touched: Vec<String> = {
        let mut t: Vec<String> = judged.iter().flat_map(|(_, j)| j.touched().cloned()).collect();
        t.sort();
        t.dedup();
        t
    };
    let score = |choice: &BTreeMap<String, String>, interpretation: &str| {
        judged.iter().filter(|(_, j)| j.touched().any(|i| i == interpretation) && j.passes(choice, cpu_writes)).count()
    };
    loop {
        let mut changed = false;
        for interpretation in &touched {
            let current = score(&choice, interpretation);
            let mut best: Option<(usize, String)> = None;
            for alternative in alternatives.get(interpretation).into_iter().flatten() {
                if choice.get(interpretation) == Some(alternative) {
                    continue;
                }
                let mut trial = choice.clone();
                trial.insert(interpretation.clone(), alternative.clone());
                let s = score(&trial, interpretation);
                if best.as_ref().is_none_or(|(b, _)| s > *b) {
                    best = Some((s, alternative.clone()));
                }
            }
            if let Some((s, alternative)) = best {
                if s > current {
                    choice.insert(interpretation.clone(), alternative);
                    changed = true;
                }
            }
        }
        if !changed {
            break;
        }
    }
    let mut explained = Vec::new();
    let mut unexplained = Vec::new();
    let mut broken = 0;
    let passes_under = |k: usize, choice: &BTreeMap<String, String>| {
        judged.iter().find(|(j, _)| *j == k).is_some_and(|(_, j)| j.passes(choice, cpu_writes))
    };
    for (k, case) in cases.iter().enumerate() {
        if case.status == Status::Pass {
            if !passes_under(k, &choice) {
                broken += 1;
            }
            continue;
        }
        if !failing(case.status) {
            continue;
        }
        if case.status == Status::Fail && passes_under(k, &choice) {
            let differing: Vec<(String, String)> = case
                .expected
                .choices
                .iter()
                .filter_map(|(i, a)| choice.get(i).filter(|c| *c != a).map(|c| (i.clone(), c.clone())))
                .collect();
            let smallest = (1..=differing.len())
                .flat_map(|size| combinations(&differing, size))
                .find(|subset| {
                    let mut trial = followed.clone();
                    trial.extend(subset.iter().cloned());
                    passes_under(k, &trial)
                })
                .unwrap_or(differing);
            explained.push((k, smallest));
        } else {
            unexplained.push(k);
        }
    }
    Inference { choice, explained, unexplained, broken }
}

/// The subsets of `items` of `size`, in lexicographic order (as itertools.combinations).
fn combinations<T: Clone>(items: &[T], size: usize) -> Vec<Vec<T>> {
    if size == 0 {
        return vec![Vec::new()];
    }
    let mut out = Vec::new();
    for first in 0..items.len() {
        for mut rest in combinations(&items[first + 1..], size - 1) {
            rest.insert(0, items[first].clone());
            out.push(rest);
        }
    }
    out
}

/// `{n:>6}` under the four-space indent, then two spaces: a count line of the roll-up.
fn count_line(n: usize, text: &str) -> String {
    format!("    {n:>6}  {text}")
}

/// The roll-up's text (empty when no vector failed).
pub(crate) fn rollup(cases: &[Case<'_>], inference: &Inference, followed: &BTreeMap<String, String>) -> String {
    let failing_count = cases.iter().filter(|c| failing(c.status)).count();
    if failing_count == 0 {
        return String::new();
    }
    let mut out = String::new();
    if !inference.explained.is_empty() {
        out.push_str(&format!(
            "READINGS: {} of {failing_count} failing vectors pass under other alternatives:\n",
            inference.explained.len()
        ));
        let mut groups: BTreeMap<String, usize> = BTreeMap::new();
        for (_, change) in &inference.explained {
            let text: Vec<String> = change.iter().map(|(i, a)| format!("{i}={a}")).collect();
            *groups.entry(text.join(", ")).or_default() += 1;
        }
        let mut groups: Vec<(String, usize)> = groups.into_iter().collect();
        groups.sort_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(&b.0)));
        for (text, n) in groups {
            out.push_str(&count_line(n, &text));
            out.push('\n');
        }
        let declare: Vec<String> = inference
            .choice
            .iter()
            .filter(|(i, a)| followed.get(*i) != Some(a))
            .map(|(i, a)| format!("--choose {i}={a}"))
            .collect();
        out.push_str(&format!("    declare: {}\n", declare.join(" ")));
        if inference.broken > 0 {
            out.push_str(&format!("    (so declared, {} vectors that pass now would fail)\n", inference.broken));
        }
    }
    if !inference.unexplained.is_empty() {
        out.push_str(&format!(
            "NOT EXPLAINED by any reading: {} failing vectors, by the clauses they cite:\n",
            inference.unexplained.len()
        ));
        let mut groups: BTreeMap<String, Vec<&str>> = BTreeMap::new();
        for &k in &inference.unexplained {
            let v = cases[k].vector;
            let clauses = if v.clauses().is_empty() { "(no clauses)".to_owned() } else { v.clauses().join(", ") };
            groups.entry(clauses).or_default().push(v.id());
        }
        let mut groups: Vec<(String, Vec<&str>)> = groups.into_iter().collect();
        groups.sort_by(|a, b| b.1.len().cmp(&a.1.len()).then_with(|| a.0.cmp(&b.0)));
        for (clauses, mut ids) in groups {
            ids.sort_unstable();
            out.push_str(&count_line(ids.len(), &clauses));
            out.push('\n');
            for id in ids.iter().take(5) {
                out.push_str(&format!("            {id}\n"));
            }
            if ids.len() > 5 {
                out.push_str(&format!("            ... and {} more\n", ids.len() - 5));
            }
        }
    }
    out
}

/// Skips by reason (empty when nothing was skipped); `selected` vectors in all.
pub(crate) fn skips(reasons: &[&str], selected: usize) -> String {
    if reasons.is_empty() || selected == 0 {
        return String::new();
    }
    let s = reasons.len();
    let t = (2000 * s + selected) / (2 * selected);
    let mut out = format!("SKIPPED {s} of {selected} vectors ({}.{}%):\n", t / 10, t % 10);
    let mut groups: BTreeMap<&str, usize> = BTreeMap::new();
    for r in reasons {
        *groups.entry(if r.is_empty() { "(no reason given)" } else { r }).or_default() += 1;
    }
    let mut groups: Vec<(&str, usize)> = groups.into_iter().collect();
    groups.sort_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(b.0)));
    for (reason, n) in groups.iter().take(12) {
        out.push_str(&count_line(*n, reason));
        out.push('\n');
    }
    if groups.len() > 12 {
        out.push_str(&format!("    ... and {} more reasons (--jsonl lists each vector)\n", groups.len() - 12));
    }
    out
}
