//! What a vector expects of an implementation that follows given interpretation alternatives.
//!
//! A vector stores, per step, only the devices that changed and the full state at the end. The
//! full expected state after every step is worked out here once (slot-aligned with the vector's
//! devices), and checked against the vector's own `final`, so an inconsistent file is refused
//! rather than trusted.

use std::collections::BTreeMap;

use crate::choices::Choices;
use crate::error::{Error, Result};
use crate::keys::INLINE_SLOTS;
use crate::small::Small;
use crate::value::Value;
use crate::vector::{Expectation, Vector};
use crate::Suite;

/// The expectation of one vector under one set of alternatives (what a run reads first, first:
/// `#[repr(C)]` keeps the order).
#[derive(Clone, Debug, PartialEq, Eq)]
#[repr(C)]
pub struct Expected {
    /// Per step: the contact result, for contact instructions.
    results: Small<Option<bool>, 4>,
    /// Every slot's value after each step, the steps one after the other (scratch slots hold
    /// their initial value and are never compared): one flat table, inline for a short vector.
    states: Small<Value, INLINE_SLOTS>,
    /// Slots per step.
    slots: usize,
    /// The interpretations the vector depends on, with the alternative it is judged by.
    pub choices: Vec<(String, String)>,
    /// The default alternative of each interpretation the vector depends on.
    pub(crate) defaults: Vec<(String, String)>,
    /// The outcome category under these alternatives (`value`, `error`, `implementation-defined`).
    pub category: String,
    /// The devices the followed alternative leaves unjudged (unjudged.md); `None` for most
    /// vectors, and one pointer beside the tables a run reads.
    unjudged: Option<Box<Unjudged>>,
}

/// What an expectation leaves unjudged.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Unjudged {
    /// Per interpretation whose followed alternative leaves devices unjudged, their slots.
    by: Vec<(String, Vec<usize>)>,
    /// Per slot, whether it is left unjudged.
    slots: Vec<bool>,
    /// Per slot, whether a comparison passes it over: scratch or unjudged.
    passed_over: Vec<bool>,
}

impl Expected {
    /// The expectation of `vector` for an implementation declaring `choices` (others: `defaults`).
    pub fn of(vector: &Vector, choices: &Choices, defaults: &BTreeMap<&str, &str>) -> Result<Expected> {
        let e = vector.expectations.as_ref().ok_or_else(|| {
            Error::new(format!("vector {}: has no expectations (a request, not a suite vector)", vector.id()))
        })?;
        let mut applied = Vec::with_capacity(e.touched.len());
        let mut touched_defaults = Vec::with_capacity(e.touched.len());
        let mut all_default = true;
        for i in &e.touched {
            let default = defaults.get(i.as_str()).copied().unwrap_or("");
            let alt = choices.declared(i).unwrap_or(default);
            all_default &= alt == default;
            applied.push((i.clone(), alt.to_owned()));
            touched_defaults.push((i.clone(), default.to_owned()));
        }
        let chosen: &Expectation = if all_default {
            &e.own
        } else {
            e.alternatives
                .iter()
                .find(|alt| applied.iter().all(|(i, a)| alt.choices.iter().any(|(ci, ca)| ci == i && ca == a)))
                .ok_or_else(|| {
                    let list: Vec<String> = applied.iter().map(|(i, a)| format!("{i}={a}")).collect();
                    Error::new(format!(
                        "vector {}: no expectation for {} (the vector file lists no such alternative)",
                        vector.id(),
                        list.join(", ")
                    ))
                })?
        };
        let mut state = vector.initial().to_vec();
        let mut states = Vec::with_capacity(chosen.steps.len() * state.len());
        let mut results = Vec::with_capacity(chosen.steps.len());
        for (step, expect) in vector.steps().iter().zip(&chosen.steps) {
            for &(slot, v) in step.set() {
                state[slot] = v;
            }
            for &(slot, v) in &expect.devices {
                state[slot] = v;
            }
            states.extend_from_slice(&state);
            results.push(expect.result);
        }
        let last = &state;
        let unjudged = (!chosen.unjudged.is_empty()).then(|| {
            let mut slots = vec![false; state.len()];
            for &slot in chosen.unjudged.iter().flat_map(|(_, slots)| slots) {
                slots[slot] = true;
            }
            let passed_over = vector.scratch().iter().zip(&slots).map(|(s, u)| *s || *u).collect();
            Box::new(Unjudged { by: chosen.unjudged.clone(), slots, passed_over })
        });
        let skip = unjudged.as_ref().map_or(vector.scratch(), |u| &u.passed_over);
        // The devices are sorted by name and unique (read from a JSON object into a map), as are
        // `final`'s keys (the same names): the two agree when they match pair by pair, which is
        // one comparison per device where a look-up in `final` took several (this runs once per
        // vector and set of alternatives).
        let listed = vector.devices().iter().zip(last).zip(skip).filter(|(_, &s)| !s).map(|((a, v), _)| (a.name(), v));
        let finals = chosen.final_devices.iter().map(|(name, v)| (name.as_str(), v));
        let consistent = listed.eq(finals);
        if !consistent {
            return Err(Error::new(format!(
                "vector {}: the per-step changes do not add up to `final` (the vector file is inconsistent; regenerate it)",
                vector.id()
            )));
        }
        Ok(Expected {
            results: Small::from_slice(&results),
            states: Small::from_slice(&states),
            slots: state.len(),
            choices: applied,
            defaults: touched_defaults,
            category: chosen.category.clone(),
            unjudged,
        })
    }

    /// Whether the expectation leaves a slot unjudged (an alternative's `unjudged`).
    #[inline]
    pub(crate) fn is_unjudged(&self, slot: usize) -> bool {
        self.unjudged.as_ref().is_some_and(|u| u.slots.get(slot).copied().unwrap_or(false))
    }

    /// Per interpretation whose followed alternative leaves devices unjudged, their slots.
    pub(crate) fn unjudged(&self) -> &[(String, Vec<usize>)] {
        self.unjudged.as_ref().map_or(&[], |u| &u.by)
    }

    /// Per slot of `vector`, whether a comparison passes it over: scratch, or unjudged.
    #[inline]
    pub(crate) fn passed_over<'a>(&'a self, vector: &'a Vector) -> &'a [bool] {
        match &self.unjudged {
            None => vector.scratch(),
            Some(u) => &u.passed_over,
        }
    }

    /// How many steps the vector has.
    pub fn steps(&self) -> usize {
        self.results.len()
    }

    /// Per step: the contact result the vector expects (`None` for an instruction that is no
    /// contact).
    pub fn results(&self) -> &[Option<bool>] {
        &self.results
    }

    /// Every slot's value after step `step`, slot-aligned with [`Vector::devices`].
    pub fn state(&self, step: usize) -> Option<&[Value]> {
        if step >= self.steps() {
            return None;
        }
        self.states.get(step * self.slots..(step + 1) * self.slots)
    }

    /// A slot's value before step `step` executed (after its `set`): shown beside a difference.
    /// Worked out only for a failure, so a passing run never pays for it.
    pub fn before(&self, vector: &Vector, step: usize, slot: usize) -> Value {
        let set = vector.steps().get(step).and_then(|s| s.set().iter().find(|(i, _)| *i == slot));
        match (set, step) {
            (Some(&(_, v)), _) => v,
            (None, 0) => vector.initial()[slot],
            (None, _) => self.state(step - 1).map_or(vector.initial()[slot], |s| s[slot]),
        }
    }
}

/// Refuse a declaration the suite cannot judge by: an unknown interpretation or alternative.
pub fn check_choices(suite: &Suite, choices: &Choices) -> Result<()> {
    let known = suite.interpretations()?;
    for (i, a) in choices.iter() {
        let Some((info, _)) = known.get(i) else {
            let names: Vec<&str> = known.keys().copied().collect();
            return Err(Error::new(format!(
                "the implementation declares interpretation {i:?}, which no vector file defines (known: {})",
                names.join(", ")
            )));
        };
        if !info.alternatives.iter().any(|x| x == a) {
            return Err(Error::new(format!(
                "the implementation declares {i}={a}, but {i} has the alternatives {}",
                info.alternatives.join(", ")
            )));
        }
    }
    Ok(())
}

impl Expected {
    /// Whether a vector that passes under `self` passes under `other` (unjudged.md): every step's
    /// result equal, and every device `other` judges expected alike (value and type) by both; a
    /// device `other` judges but `self` leaves unjudged is not known to be equal.
    pub(crate) fn same_outcome(&self, other: &Expected) -> bool {
        if self.results != other.results {
            return false;
        }
        if self.unjudged.is_none() && other.unjudged.is_none() {
            return self.states == other.states;
        }
        let slots = self.slots.max(1);
        self.states.iter().zip(other.states.iter()).enumerate().all(|(n, (a, b))| {
            let slot = n % slots;
            other.is_unjudged(slot) || (!self.is_unjudged(slot) && a == b)
        })
    }

    /// The combinations of alternatives the vector offers an expectation for: its own (every
    /// default), then each of its alternatives in file order (each as (interpretation,
    /// alternative) for the interpretations the vector depends on).
    pub(crate) fn offered(&self, vector: &Vector) -> Vec<Vec<(String, String)>> {
        let mut out = vec![self.defaults.clone()];
        if let Some(e) = &vector.expectations {
            for alt in &e.alternatives {
                let combination: Option<Vec<(String, String)>> =
                    self.defaults.iter().map(|(i, _)| alt.choices.iter().find(|(ci, _)| ci == i).cloned()).collect();
                out.extend(combination);
            }
        }
        out
    }

    /// The expectation of `vector` under `combination` (interpretation -> alternative for those
    /// the vector depends on), if the vector offers one.
    pub(crate) fn under(&self, vector: &Vector, combination: &[(String, String)]) -> Option<Expected> {
        let choices: Choices = combination.iter().map(|(i, a)| (i.as_str(), a.as_str())).collect();
        let defaults: BTreeMap<&str, &str> = self.defaults.iter().map(|(i, a)| (i.as_str(), a.as_str())).collect();
        Expected::of(vector, &choices, &defaults).ok()
    }
}
