//! A [`Vector`] from the shapes of its file, by concern: the device slots and their values, the
//! steps' inputs, the expectations (the vector's own and each alternative's, with the devices an
//! alternative leaves unjudged), and the fast layout the running implementation reads through.

use std::collections::BTreeMap;

use super::raw::{RawAlternative, RawExpect, RawFinal, RawInitial, RawStep, RawVector};
use super::{Clock, Expectation, Expectations, Operand, Step, StepExpect, Vector, NO_SLOT, OPERAND_WORDS};
use crate::error::{Error, Result};
use crate::generated::names::{Family, Instruction};
use crate::keys::SlotKeys;
use crate::small::Small;
use crate::unique::Unique;
use crate::value::{pack, Address, Value};

type Json = serde_json::Value;

const WORD_OR_BIT: &str = "is neither a word (an integer 0..65535) nor a bit (true/false)";

/// A device name as the vector schema writes one (`^[A-Za-z_]+[0-9]*$`).
fn is_device_name(name: &str) -> bool {
    let letters = name.trim_end_matches(|c: char| c.is_ascii_digit());
    !letters.is_empty() && letters.chars().all(|c| c.is_ascii_alphabetic() || c == '_')
}

/// The vector's devices: each slot's address, its initial value and whether it is scratch, and the
/// check of every other place that names a device (a device keeps one type throughout).
pub(super) struct Slots<'a> {
    id: &'a str,
    pub devices: Vec<Address>,
    pub initial: Vec<Value>,
    pub scratch: Vec<bool>,
}

impl<'a> Slots<'a> {
    fn bad(&self, what: String) -> Error {
        Error::new(format!("vector {}: {what}", self.id))
    }

    fn new(id: &'a str, initial: &RawInitial) -> Result<Slots<'a>> {
        let mut slots = Slots { id, devices: Vec::new(), initial: Vec::new(), scratch: Vec::new() };
        for (name, value) in &initial.devices {
            if name.is_empty() {
                return Err(slots.bad("initial.devices has an empty device name".into()));
            }
            let v = Value::from_json(value)
                .ok_or_else(|| slots.bad(format!("initial.devices.{name}: {value} {WORD_OR_BIT}")))?;
            slots.devices.push(Address::parse(name));
            slots.initial.push(v);
        }
        slots.scratch = vec![false; slots.devices.len()];
        for name in &initial.scratch {
            let i = slots
                .slot(name)
                .ok_or_else(|| slots.bad(format!("scratch device {name} is not in initial.devices")))?;
            slots.scratch[i] = true;
        }
        Ok(slots)
    }

    fn slot(&self, name: &str) -> Option<usize> {
        self.devices.binary_search_by(|a| a.name().cmp(name)).ok()
    }

    /// A device map of the vector (`set`, `expect.devices`, `final.devices`) as `(slot, value)`
    /// pairs: every device listed in `initial.devices`, with the type it has there.
    fn listed(&self, what: &str, map: &Unique<Json>) -> Result<Vec<(usize, Value)>> {
        map.iter()
            .map(|(name, value)| {
                let i = self.slot(name).ok_or_else(|| {
                    self.bad(format!("{what} names {name}, which initial.devices does not list (the vector must list every device it touches)"))
                })?;
                let v = Value::from_json(value).ok_or_else(|| self.bad(format!("{what}.{name}: {value} {WORD_OR_BIT}")))?;
                // A device is a word or a bit throughout a vector: a bit holding 2 in one place is a
                // damaged file, not something to blame on an implementation.
                let first = self.initial[i];
                if std::mem::discriminant(&v) != std::mem::discriminant(&first) {
                    return Err(self.bad(format!(
                        "{what}.{name}: {value} is a {}, but initial.devices.{name} is a {} ({first}); a device keeps one type",
                        kind_of(v),
                        kind_of(first),
                    )));
                }
                Ok((i, v))
            })
            .collect()
    }

    fn final_map(&self, what: &str, raw: &RawFinal) -> Result<BTreeMap<String, Value>> {
        Ok(self.listed(what, &raw.devices)?.into_iter().map(|(i, v)| (self.devices[i].name().to_owned(), v)).collect())
    }

    fn step_expect(&self, what: &str, e: &RawExpect) -> Result<StepExpect> {
        Ok(StepExpect { result: e.result, devices: self.listed(&format!("{what}.devices"), &e.devices)? })
    }
}

fn kind_of(value: Value) -> &'static str {
    match value {
        Value::Bit(_) => "bit",
        Value::Word(_) => "word",
    }
}

/// The steps' inputs, and (for a suite vector) the vector's own expectation of each step.
fn steps(slots: &Slots<'_>, raw: Vec<RawStep>, with_expectations: bool) -> Result<(Vec<Step>, Vec<StepExpect>)> {
    if raw.is_empty() {
        return Err(slots.bad("no steps".into()));
    }
    let mut steps = Vec::with_capacity(raw.len());
    let mut expects = Vec::with_capacity(raw.len());
    for (n, s) in raw.into_iter().enumerate() {
        let set = slots.listed(&format!("steps[{n}].set"), &s.set)?;
        if with_expectations {
            let e = s.expect.as_ref().ok_or_else(|| slots.bad(format!("steps[{n}] has no `expect`")))?;
            expects.push(slots.step_expect(&format!("steps[{n}].expect"), e)?);
        }
        let clock = s.clock.map(|c| Clock::new(c.into_iter().collect()));
        steps.push(Step { set, rlo_in: s.rlo_in, en: s.en, input: s.input, elapsed_ms: s.elapsed_ms, clock });
    }
    Ok((steps, expects))
}

/// The vector's own expectation and its alternatives'.
fn expectations(slots: &Slots<'_>, raw: &mut RawVector, own: Vec<StepExpect>, steps: usize) -> Result<Expectations> {
    let final_devices = raw.final_.take().ok_or_else(|| slots.bad("no `final`".into()))?;
    let outcome = raw.outcome.take().ok_or_else(|| slots.bad("no `outcome`".into()))?;
    let default_category = outcome.default.map_or(outcome.category.clone(), |d| d.category);
    let own = Expectation {
        choices: Vec::new(),
        steps: own,
        final_devices: slots.final_map("final.devices", &final_devices)?,
        category: if outcome.interpretations.is_empty() { outcome.category } else { default_category },
        unjudged: Vec::new(),
    };
    let alternatives = std::mem::take(&mut raw.alternatives)
        .into_iter()
        .enumerate()
        .map(|(k, alt)| alternative(slots, k, alt, steps))
        .collect::<Result<Vec<_>>>()?;
    Ok(Expectations { touched: outcome.interpretations, own, alternatives })
}

fn alternative(slots: &Slots<'_>, k: usize, alt: RawAlternative, steps: usize) -> Result<Expectation> {
    if alt.expect.len() != steps {
        return Err(slots.bad(format!("alternatives[{k}] has {} expectations for {steps} steps", alt.expect.len())));
    }
    let expects = alt
        .expect
        .iter()
        .enumerate()
        .map(|(n, e)| slots.step_expect(&format!("alternatives[{k}].expect[{n}]"), e))
        .collect::<Result<Vec<_>>>()?;
    let final_devices = slots.final_map(&format!("alternatives[{k}].final.devices"), &alt.final_)?;
    let choices: Vec<(String, String)> = alt.choices.into_iter().collect();
    let unjudged = match &alt.unjudged {
        Some(map) => unjudged(slots, k, map, &choices, &expects, &final_devices)?,
        None => Vec::new(),
    };
    Ok(Expectation { choices, steps: expects, final_devices, category: alt.outcome.category, unjudged })
}

/// An alternative's `unjudged` map (unjudged.md; schema 1.1) as (interpretation, slots), each
/// interpretation one of the entry's choices, each device listed in `initial.devices`, each list
/// sorted and without repeats, and none of the devices in the entry's `expect` or `final`.
fn unjudged(
    slots: &Slots<'_>,
    k: usize,
    map: &Unique<Json>,
    choices: &[(String, String)],
    expects: &[StepExpect],
    final_devices: &BTreeMap<String, Value>,
) -> Result<Vec<(String, Vec<usize>)>> {
    let at = |path: String, what: String| slots.bad(format!("at alternatives/{k}/unjudged{path}: {what}"));
    if map.is_empty() {
        return Err(at(
            String::new(),
            "{} should be non-empty (an entry that leaves nothing unjudged has no `unjudged`)".into(),
        ));
    }
    let mut out = Vec::with_capacity(map.len());
    for (interpretation, list) in map.iter() {
        let here = |what: String| at(format!("/{interpretation}"), what);
        if !choices.iter().any(|(i, _)| i == interpretation) {
            return Err(here(format!("{interpretation} is not one of the entry's choices")));
        }
        let names: Vec<&str> = match list.as_array() {
            Some(items) if !items.is_empty() => items.iter().map(|d| d.as_str().unwrap_or("")).collect(),
            _ => return Err(here(format!("{list} is not a non-empty list of device names"))),
        };
        let mut devices = Vec::with_capacity(names.len());
        for (n, name) in names.iter().enumerate() {
            let item = |what: String| at(format!("/{interpretation}/{n}"), what);
            if !is_device_name(name) {
                return Err(item(format!("{} is not a device name", list[n])));
            }
            if n > 0 && names[n - 1] >= *name {
                return Err(item(format!(
                    "{name:?} is not after {:?}: the list is sorted, without repeats",
                    names[n - 1]
                )));
            }
            let slot = slots.slot(name).ok_or_else(|| item(format!("{name} is not in initial.devices")))?;
            let expected = expects.iter().any(|e| e.devices.iter().any(|&(i, _)| i == slot));
            if expected || final_devices.contains_key(*name) {
                return Err(item(format!("{name} is unjudged, yet the entry's expect or final lists it")));
            }
            devices.push(slot);
        }
        out.push((interpretation.clone(), devices));
    }
    Ok(out)
}

/// The operands as the vector gives them.
fn operands(slots: &Slots<'_>, raw: Unique<super::raw::RawOperand>) -> Result<Vec<(String, Operand)>> {
    raw.into_iter()
        .map(|(name, op)| match (op.device, op.constant) {
            (Some(d), None) => Ok((name, Operand::Device(Address::parse(&d)))),
            (None, Some(c)) => Ok((name, Operand::Constant(c))),
            _ => Err(slots.bad(format!("operand {name} needs exactly one of `device` and `constant`"))),
        })
        .collect()
}

impl Vector {
    pub(crate) fn from_raw(mut raw: RawVector, with_expectations: bool) -> Result<Vector> {
        let id = std::mem::take(&mut raw.id);
        let slots = Slots::new(&id, &raw.initial)?;
        let operands = operands(&slots, std::mem::take(&mut raw.initial.operands))?;
        let mut device_sizes = Vec::new();
        for (kind, n) in std::mem::take(&mut raw.assumes.device_sizes) {
            let n =
                u32::try_from(n).map_err(|_| slots.bad(format!("assumes.device_sizes.{kind}: {n} is too large")))?;
            device_sizes.push((kind, n));
        }
        let (steps, own) = steps(&slots, std::mem::take(&mut raw.steps), with_expectations)?;
        let expectations =
            if with_expectations { Some(expectations(&slots, &mut raw, own, steps.len())?) } else { None };
        let Slots { devices, initial, scratch, .. } = slots;
        Ok(Vector::laid_out(Parts { id, raw, devices, initial, scratch, operands, device_sizes, steps, expectations }))
    }

    /// The vector with the tables a running implementation reads through (the slot keys, each
    /// operand's slots, the device sizes by packed kind), built once here.
    fn laid_out(p: Parts) -> Vector {
        let known_family = Family::from_name(&p.raw.family);
        let known_instruction = Instruction::from_name(&p.raw.instruction).filter(|i| Some(i.family()) == known_family);
        let operand_keys = p.operands.iter().map(|(n, _)| pack(n)).collect();
        let size_keys = p.device_sizes.iter().map(|(k, n)| (pack(k), *n)).collect();
        let name_keys = SlotKeys::new(&p.devices.iter().map(|a| pack(a.name())).collect::<Vec<_>>());
        let keys_spell_addresses = p.devices.iter().all(|a| a.number().is_none() || a.key_at(0) == pack(a.name()));
        let raw = p.raw;
        let mut vector = Vector {
            operand_keys,
            operand_slots: Small::default(),
            known_family,
            known_instruction,
            id: p.id,
            family: raw.family,
            instruction: raw.instruction,
            description: raw.description,
            tags: raw.tags,
            clauses: raw.clauses,
            device_sizes: p.device_sizes,
            size_keys,
            name_keys,
            keys_spell_addresses,
            devices: p.devices,
            initial: Small::from_slice(&p.initial),
            scratch: p.scratch,
            operands: p.operands.into(),
            steps: p.steps.into(),
            expectations: p.expectations,
        };
        vector.operand_slots = vector
            .operands
            .iter()
            .map(|(_, o)| {
                let slot = |offset: usize| {
                    let slot = o.device().and_then(|a| vector.slot_at(a, offset as u32));
                    slot.and_then(|s| u8::try_from(s).ok()).filter(|&s| s != NO_SLOT).unwrap_or(NO_SLOT)
                };
                std::array::from_fn::<u8, OPERAND_WORDS, _>(slot)
            })
            .collect();
        vector
    }
}

/// What `Vector::laid_out` is built from.
struct Parts {
    id: String,
    raw: RawVector,
    devices: Vec<Address>,
    initial: Vec<Value>,
    scratch: Vec<bool>,
    operands: Vec<(String, Operand)>,
    device_sizes: Vec<(String, u32)>,
    steps: Vec<Step>,
    expectations: Option<Expectations>,
}

#[cfg(test)]
mod tests {
    use super::*;

    fn vector(alternative: &str) -> Result<Vector> {
        let text = format!(
            r#"{{"id": "f/HOUR/x", "family": "f", "instruction": "HOUR",
                "initial": {{"devices": {{"D200": 0, "D201": 0, "M10": false, "M8004": false}}, "operands": {{}}}},
                "steps": [{{"input": true, "expect": {{"devices": {{"D200": 1}}}}}}],
                "final": {{"devices": {{"D200": 1, "D201": 0, "M10": false, "M8004": false}}}},
                "outcome": {{"category": "implementation-defined", "interpretations": ["HOUR-D1-OUT-OF-RANGE"],
                             "default": {{"category": "value"}}}},
                "alternatives": [{alternative}]}}"#
        );
        Vector::from_raw(serde_json::from_str(&text).unwrap(), true)
    }

    const ENTRY: &str = r#"{"choices": {"HOUR-D1-OUT-OF-RANGE": "error"}, "expect": [{"devices": {"M8004": true}}],
        "final": {"devices": {"M8004": true}}, "outcome": {"category": "error"}, "unjudged": UNJUDGED}"#;

    fn with(unjudged: &str) -> Result<Vector> {
        vector(&ENTRY.replace("UNJUDGED", unjudged))
    }

    #[test]
    fn an_unjudged_map_is_read_by_slot() {
        let v = with(r#"{"HOUR-D1-OUT-OF-RANGE": ["D200", "D201", "M10"]}"#).unwrap();
        let alt = &v.expectations.as_ref().unwrap().alternatives[0];
        assert_eq!(alt.unjudged, vec![("HOUR-D1-OUT-OF-RANGE".to_owned(), vec![0, 1, 2])]);
        assert!(vector(&ENTRY.replace(r#", "unjudged": UNJUDGED"#, "")).unwrap().expectations.unwrap().alternatives[0]
            .unjudged
            .is_empty());
    }

    #[test]
    fn a_malformed_unjudged_map_is_refused_by_vector_and_path() {
        let refused = |map: &str| with(map).unwrap_err().message().to_owned();
        let at = "vector f/HOUR/x: at alternatives/0/unjudged";
        assert!(refused("{}").starts_with(&format!("{at}: {{}} should be non-empty")));
        assert_eq!(
            refused(r#"{"TADD-ON-ERROR": ["M10"]}"#),
            format!("{at}/TADD-ON-ERROR: TADD-ON-ERROR is not one of the entry's choices")
        );
        assert!(
            refused(r#"{"HOUR-D1-OUT-OF-RANGE": []}"#).starts_with(&format!("{at}/HOUR-D1-OUT-OF-RANGE: [] is not"))
        );
        assert_eq!(
            refused(r#"{"HOUR-D1-OUT-OF-RANGE": ["D 1"]}"#),
            format!("{at}/HOUR-D1-OUT-OF-RANGE/0: \"D 1\" is not a device name")
        );
        assert!(refused(r#"{"HOUR-D1-OUT-OF-RANGE": ["M10", "D200"]}"#)
            .starts_with(&format!("{at}/HOUR-D1-OUT-OF-RANGE/1: \"D200\" is not after \"M10\"")));
        assert!(refused(r#"{"HOUR-D1-OUT-OF-RANGE": ["M10", "M10"]}"#)
            .starts_with(&format!("{at}/HOUR-D1-OUT-OF-RANGE/1: \"M10\" is not after")));
        assert_eq!(
            refused(r#"{"HOUR-D1-OUT-OF-RANGE": ["D300"]}"#),
            format!("{at}/HOUR-D1-OUT-OF-RANGE/0: D300 is not in initial.devices")
        );
        assert_eq!(
            refused(r#"{"HOUR-D1-OUT-OF-RANGE": ["M8004"]}"#),
            format!("{at}/HOUR-D1-OUT-OF-RANGE/0: M8004 is unjudged, yet the entry's expect or final lists it")
        );
    }
}
