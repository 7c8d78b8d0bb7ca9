//! The roll-up by reading (verifiers/parity/TEXT.md, "The inference"): which alternatives the
//! implementation's answers follow, the failures another reading explains, grouped by the
//! smallest change that explains each, and the failures no reading explains, by their clauses.

use std::collections::{BTreeMap, BTreeSet};

use crate::compare::{compare, ReportedStep};
use crate::expect::Expected;
use crate::generated::names;
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
    /// Explained known failures (`xfail`) with their smallest change.
    pub explained_known: Vec<(usize, Combination)>,
    /// Known failures no reading explains.
    pub unexplained_known: Vec<usize>,
    /// Passing vectors that would fail under the choice.
    pub broken: Vec<usize>,
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
    let choice = choose(&judged, followed, alternatives, cpu_writes);
    let passes_under = |k: usize, choice: &BTreeMap<String, String>| {
        judged.iter().find(|(j, _)| *j == k).is_some_and(|(_, j)| j.passes(choice, cpu_writes))
    };
    let mut inference = Inference {
        choice: BTreeMap::new(),
        explained: Vec::new(),
        unexplained: Vec::new(),
        explained_known: Vec::new(),
        unexplained_known: Vec::new(),
        broken: Vec::new(),
    };
    for (k, case) in cases.iter().enumerate() {
        // TEXT.md, "The inference", step 5: a failing vector is explained when it is judged (it
        // failed: an error or a vector not run never is) and passes under the choice; so is a
        // known failure whose vector failed (one whose vector errored has no answer).
        let judged_failure = match case.status {
            Status::Fail => true,
            Status::XFail => case.answer.is_some(),
            _ => false,
        };
        let explained = judged_failure && passes_under(k, &choice);
        let smallest = || smallest_change(case, &choice, followed, |trial| passes_under(k, trial));
        match case.status {
            Status::Pass if !passes_under(k, &choice) => inference.broken.push(k),
            Status::XFail if explained => inference.explained_known.push((k, smallest())),
            Status::XFail => inference.unexplained_known.push(k),
            status if failing(status) && explained => inference.explained.push((k, smallest())),
            status if failing(status) => inference.unexplained.push(k),
            _ => {}
        }
    }
    inference.choice = choice;
    inference
}

/// TEXT.md, "The inference", step 4: from the followed alternatives, each interpretation a judged
/// vector touches (in ID order) moves to the first of its alternatives with the highest score,
/// when that is above the current one, until a round changes nothing. The rounds run twice: first
/// without the alternatives that leave devices unjudged (such a reading explains any answer there,
/// so it is taken only for what no reading that judges explains), then with every alternative.
fn choose(
    judged: &[(usize, Judged<'_>)],
    followed: &BTreeMap<String, String>,
    alternatives: &Alternatives,
    cpu_writes: &[String],
) -> BTreeMap<String, String> {
    let mut touched: Vec<String> = judged.iter().flat_map(|(_, j)| j.touched().cloned()).collect();
    touched.sort();
    touched.dedup();
    let leaving: BTreeSet<(&str, &str)> = judged
        .iter()
        .filter_map(|(_, j)| j.case.vector.expectations.as_ref())
        .flat_map(|e| &e.alternatives)
        .flat_map(|alt| {
            alt.unjudged.iter().filter_map(|(i, _)| {
                alt.choices.iter().find(|(ci, _)| ci == i).map(|(ci, ca)| (ci.as_str(), ca.as_str()))
            })
        })
        .collect();
    let first = rounds(judged, followed.clone(), &touched, alternatives, cpu_writes, |i, a| !leaving.contains(&(i, a)));
    rounds(judged, first, &touched, alternatives, cpu_writes, |_, _| true)
}

/// The rounds of step 4 from `choice`, over the alternatives `allowed` admits.
fn rounds(
    judged: &[(usize, Judged<'_>)],
    mut choice: BTreeMap<String, String>,
    touched: &[String],
    alternatives: &Alternatives,
    cpu_writes: &[String],
    allowed: impl Fn(&str, &str) -> bool,
) -> BTreeMap<String, String> {
    let score = |choice: &BTreeMap<String, String>, interpretation: &str| {
        judged.iter().filter(|(_, j)| j.touched().any(|i| i == interpretation) && j.passes(choice, cpu_writes)).count()
    };
    loop {
        let mut changed = false;
        for interpretation in touched {
            let current = score(&choice, interpretation);
            let mut best: Option<(usize, String)> = None;
            for alternative in alternatives.get(interpretation).into_iter().flatten() {
                if choice.get(interpretation) == Some(alternative) || !allowed(interpretation, alternative) {
                    continue;
                }
                let mut trial = choice.clone();
                trial.insert(interpretation.clone(), alternative.clone());
                let s = score(&trial, interpretation);
                if best.as_ref().is_none_or(|(b, _)| s > *b) {
                    best = Some((s, alternative.clone()));
                }
            }
            if let Some((_, alternative)) = best.filter(|(s, _)| *s > current) {
                choice.insert(interpretation.clone(), alternative);
                changed = true;
            }
        }
        if !changed {
            return choice;
        }
    }
}

/// TEXT.md, "The inference", step 6: the first subset, by size then in lexicographic order, of
/// the interpretations whose chosen alternative differs from the followed one under which the
/// vector passes.
fn smallest_change(
    case: &Case<'_>,
    choice: &BTreeMap<String, String>,
    followed: &BTreeMap<String, String>,
    passes: impl Fn(&BTreeMap<String, String>) -> bool,
) -> Combination {
    let differing: Combination = case
        .expected
        .choices
        .iter()
        .filter_map(|(i, a)| choice.get(i).filter(|c| *c != a).map(|c| (i.clone(), c.clone())))
        .collect();
    (1..=differing.len())
        .flat_map(|size| combinations(&differing, size))
        .find(|subset| {
            let mut trial = followed.clone();
            trial.extend(subset.iter().cloned());
            passes(&trial)
        })
        .unwrap_or(differing)
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

/// How the roll-up writes a declaration (TEXT.md, "The declaration in each runner").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Syntax {
    /// The crate's own: `plcvec::Choices::new().with(plcvec::names::TaddFlagsOff::SetOnly)`.
    Rust,
    /// `plcvec verify`'s: `--choose TADD-FLAGS-OFF=set-only` (the shared cases' expected text).
    Choose,
}

/// `changes` (sorted by interpretation) declared in `syntax`.
pub(crate) fn declaration(syntax: Syntax, changes: &[(String, String)]) -> String {
    match syntax {
        Syntax::Choose => changes.iter().map(|(i, a)| format!("--choose {i}={a}")).collect::<Vec<_>>().join(" "),
        Syntax::Rust => {
            let mut out = String::from("plcvec::Choices::new()");
            for (i, a) in changes {
                match names::declaration(i, a) {
                    Some((interpretation, alternative)) => {
                        out.push_str(&format!(".with(plcvec::names::{interpretation}::{alternative})"));
                    }
                    // An interpretation of a newer vector copy than this build's names know.
                    None => out.push_str(&format!(".with(/* {i}={a}: not in this build's plcvec::names */)")),
                }
            }
            out
        }
    }
}

/// What the roll-up is given besides the cases: the inference over them, the alternatives
/// followed, the declaration syntax and the known-failures file's name as given.
pub(crate) struct Rollup<'a> {
    pub inference: &'a Inference,
    pub followed: &'a BTreeMap<String, String>,
    pub syntax: Syntax,
    pub known_file: Option<&'a str>,
}

/// The roll-up's text (empty when no vector failed and none is a known failure).
pub(crate) fn rollup(cases: &[Case<'_>], r: &Rollup<'_>) -> String {
    let failing_count = cases.iter().filter(|c| failing(c.status)).count();
    let known_count = cases.iter().filter(|c| c.status == Status::XFail).count();
    if failing_count == 0 && known_count == 0 {
        return String::new();
    }
    let inference = r.inference;
    let mut out = String::new();
    if !inference.explained.is_empty() {
        out.push_str(&format!(
            "READINGS: {} of {failing_count} failing vectors pass under other alternatives:\n",
            inference.explained.len()
        ));
        out.push_str(&groups(cases, &inference.explained, &inference.unexplained, &inference.broken));
        let declare: Vec<(String, String)> = inference
            .choice
            .iter()
            .filter(|(i, a)| r.followed.get(*i) != Some(a))
            .map(|(i, a)| (i.clone(), a.clone()))
            .collect();
        out.push_str(&format!("    declare: {}\n", declaration(r.syntax, &declare)));
        if !inference.broken.is_empty() {
            out.push_str(&format!("    (so declared, {} vectors that pass now would fail)\n", inference.broken.len()));
        }
        // The vectors of the explained vectors' families that no reading explains, or that pass now
        // and the declaration would break.
        let families: BTreeSet<&str> = inference.explained.iter().map(|&(k, _)| cases[k].vector.family()).collect();
        let of = |list: &[usize]| list.iter().filter(|&&k| families.contains(cases[k].vector.family())).count();
        let (near, lost) = (of(&inference.unexplained), of(&inference.broken));
        if near + lost > 0 {
            out.push_str(&format!(
                "    partial: {near} vectors no reading explains and {lost} vectors that pass now are of the same \
                 families; the declaration may hide part of a bug there\n"
            ));
        }
    }
    out.push_str(&not_explained(cases, &inference.unexplained));
    if !inference.explained_known.is_empty() {
        out.push_str(&known_failures(cases, r, known_count));
    }
    out
}

/// The KNOWN FAILURES part: the known failures another reading explains, grouped as READINGS is,
/// the declaration of their changes, and the file to remove them from.
fn known_failures(cases: &[Case<'_>], r: &Rollup<'_>, known_count: usize) -> String {
    let inference = r.inference;
    let k = inference.explained_known.len();
    let mut out = format!("KNOWN FAILURES: {k} of {known_count} known failures pass under other alternatives:\n");
    let unexplained: Vec<usize> = inference.unexplained.iter().chain(&inference.unexplained_known).copied().collect();
    out.push_str(&groups(cases, &inference.explained_known, &unexplained, &inference.broken));
    let changed: BTreeSet<&String> =
        inference.explained_known.iter().flat_map(|(_, change)| change.iter().map(|(i, _)| i)).collect();
    let declare: Vec<(String, String)> =
        changed.into_iter().filter_map(|i| inference.choice.get(i).map(|a| (i.clone(), a.clone()))).collect();
    out.push_str(&format!("    declare: {}\n", declaration(r.syntax, &declare)));
    out.push_str(&format!("    then remove those {k} known failures from {}\n", r.known_file.unwrap_or("")));
    out
}

/// The group lines of explained vectors (by their smallest change, largest group first, then by
/// text), each marked partial when a vector of `unexplained` (not explained) or of `broken` (passes
/// now, would fail so declared) is of a family the group's vectors are of: the reading does not
/// account for everything the implementation does there.
fn groups(cases: &[Case<'_>], explained: &[(usize, Combination)], unexplained: &[usize], broken: &[usize]) -> String {
    let mut by_change: BTreeMap<String, Vec<usize>> = BTreeMap::new();
    for (k, change) in explained {
        let text: Vec<String> = change.iter().map(|(i, a)| format!("{i}={a}")).collect();
        by_change.entry(text.join(", ")).or_default().push(*k);
    }
    let mut sorted: Vec<(String, Vec<usize>)> = by_change.into_iter().collect();
    sorted.sort_by(|a, b| b.1.len().cmp(&a.1.len()).then_with(|| a.0.cmp(&b.0)));
    let family = |k: usize| cases[k].vector.family();
    let mut out = String::new();
    for (text, members) in sorted {
        let families: BTreeSet<&str> = members.iter().map(|&k| family(k)).collect();
        let near: Vec<usize> = unexplained.iter().copied().filter(|&k| families.contains(family(k))).collect();
        let lost: Vec<usize> = broken.iter().copied().filter(|&k| families.contains(family(k))).collect();
        out.push_str(&count_line(members.len(), &text));
        if !near.is_empty() || !lost.is_empty() {
            let named: BTreeSet<&str> = near.iter().chain(&lost).map(|&k| family(k)).collect();
            let named: Vec<&str> = named.into_iter().collect();
            out.push_str(&format!(
                " (partial: {} not explained, {} would fail, in {})",
                near.len(),
                lost.len(),
                named.join(", ")
            ));
        }
        out.push('\n');
    }
    out
}

/// The NOT EXPLAINED part: unexplained failing vectors grouped by the clauses they cite.
fn not_explained(cases: &[Case<'_>], unexplained: &[usize]) -> String {
    if unexplained.is_empty() {
        return String::new();
    }
    let mut out =
        format!("NOT EXPLAINED by any reading: {} failing vectors, by the clauses they cite:\n", unexplained.len());
    let mut groups: BTreeMap<String, Vec<&str>> = BTreeMap::new();
    for &k in unexplained {
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
