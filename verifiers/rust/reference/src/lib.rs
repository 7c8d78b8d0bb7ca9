//! A plain reference implementation of the five families, written from the manual excerpts and
//! the contract: the Rust oracle. It passes every vector under every combination of
//! interpretation alternatives, through `cargo test` and over the stdio protocol.
//!
//! It is an emulator like any other: a crate of its own that reaches `plcvec` only through the
//! public API the crate documents, so that a field of that API which is wrong (or missing) fails
//! its tests as it would fail an outside emulator. It is an [`Execute`]: it executes one
//! instruction on a vector's [`Memory`]. One module per family:
//!
//! - `fx5_compare`: FX5 LDTM□/ANDTM□/ORTM□ and LDDT□/ANDDT□/ORDT□
//! - `fx5_tadd`: FX5 TADD/TADDP
//! - `fc6a_hour`: FC6A HOUR
//! - `cp1e_dt`: CP1E LD/AND/OR =DT ... >=DT
//!
//! [`Mutant`]s are the same implementation with one plausible bug each; the suite must reject
//! every one of them (tests/mutants.rs).

mod cp1e_dt;
mod fc6a_hour;
mod fx5_compare;
mod fx5_tadd;
mod mutants;

use std::cmp::Ordering;

pub use mutants::Mutant;

use plcvec::names::{Condition, Family, Form, Instruction};
use plcvec::{Address, Choices, Execute, Memory, Operand, Refusal, Step, Vector};

/// The reference implementation, following the declared alternatives (default: every default).
#[derive(Clone, Debug)]
pub struct Reference {
    choices: Choices,
    mutant: Option<Mutant>,
    family: Option<Family>,
    fx5_compare: fx5_compare::Fx5Compare,
    tadd: fx5_tadd::Fx5TimeAdd,
    hour: fc6a_hour::Fc6aHourMeter,
    cp1e: cp1e_dt::Cp1eTimeCompare,
}

impl Reference {
    /// The reference following every default alternative.
    pub fn new() -> Reference {
        Reference::with_choices(Choices::new())
    }

    /// The reference following `choices` (and the defaults for the rest).
    pub fn with_choices(choices: Choices) -> Reference {
        Reference::build(choices, None)
    }

    /// The reference with one bug, declaring `choices`.
    pub fn mutant(mutant: Mutant, choices: Choices) -> Reference {
        Reference::build(choices, Some(mutant))
    }

    fn build(choices: Choices, mutant: Option<Mutant>) -> Reference {
        Reference {
            fx5_compare: fx5_compare::Fx5Compare::new(&choices, mutant),
            tadd: fx5_tadd::Fx5TimeAdd::new(&choices, mutant),
            hour: fc6a_hour::Fc6aHourMeter::new(&choices, mutant),
            cp1e: cp1e_dt::Cp1eTimeCompare::new(&choices, mutant),
            family: None,
            choices,
            mutant,
        }
    }
}

impl Default for Reference {
    fn default() -> Reference {
        Reference::new()
    }
}

impl Execute for Reference {
    fn name(&self) -> String {
        match self.mutant {
            Some(m) => format!("plcvec-reference (mutant {})", m.name()),
            None => "plcvec-reference".to_owned(),
        }
    }

    fn interpretations(&self) -> Choices {
        self.choices.clone()
    }

    fn supports(&self, instruction: &str) -> bool {
        Instruction::from_name(instruction).is_some()
    }

    fn begin(&mut self, vector: &Vector) -> Result<(), Refusal> {
        let family = vector.known_family().ok_or_else(|| Refusal::Skip(format!("no family {}", vector.family())))?;
        self.family = Some(family);
        // Each vector starts from its own initial state: nothing carries over.
        self.tadd.reset();
        self.hour.reset();
        Ok(())
    }

    fn execute(&mut self, vector: &Vector, step: &Step, memory: &mut Memory<'_>) -> Result<Option<bool>, Refusal> {
        // What the instruction is comes from the generated names (its form, condition and
        // execution as values), not from its spelling.
        let instruction = vector.known_instruction().ok_or_else(|| {
            Refusal::Error(format!("{}: an instruction this build does not know", vector.instruction()))
        })?;
        match self.family {
            Some(Family::Fx5TimeCompare) => {
                let (form, condition) = contact_of(instruction)?;
                self.fx5_compare.execute(fx5_compare::Kind::Time, form, condition, vector, step, memory).map(Some)
            }
            Some(Family::Fx5DateCompare) => {
                let (form, condition) = contact_of(instruction)?;
                self.fx5_compare.execute(fx5_compare::Kind::Date, form, condition, vector, step, memory).map(Some)
            }
            Some(Family::Fx5TimeAdd) => self.tadd.execute(instruction, vector, step, memory).map(|()| None),
            Some(Family::Fc6aHourMeter) => self.hour.execute(vector, step, memory).map(|()| None),
            Some(Family::Cp1eTimeCompare) => {
                let (form, condition) = contact_of(instruction)?;
                self.cp1e.execute(form, condition, step, vector, memory).map(Some)
            }
            None => Err(Refusal::Error("execute before begin".to_owned())),
        }
    }
}

// The three helpers below are always inlined: the operand's name at each call is a constant
// (`"s1"`), and inlined, the look-up of the operand by that name (plcvec's `Vector::operand`,
// `Memory::operand_words`) packs it at compile time. Called, each packed the name byte by byte
// at every execution.

/// An operand that must be a device.
#[inline(always)]
fn device<'v>(vector: &'v Vector, operand: &str) -> Result<&'v Address, Refusal> {
    vector.operand(operand).and_then(|o| o.device()).ok_or_else(|| not_a_device(vector, operand))
}

fn not_a_device(vector: &Vector, operand: &str) -> Refusal {
    Refusal::Error(format!("{}: operand {operand} must be a device", vector.instruction()))
}

/// A one-word operand: a K/H constant or the word in a device.
#[inline(always)]
fn word_operand(vector: &Vector, memory: &Memory<'_>, operand: &str) -> Result<u16, Refusal> {
    match vector.operand(operand) {
        Some(Operand::Constant(c)) => Ok(*c as u16), // the low 16 bits, as the CPU stores K/H
        Some(Operand::Device(_)) => memory.operand_word(operand, 0).ok_or_else(|| not_a_device(vector, operand)),
        None => Err(Refusal::Error(format!("{}: no operand {operand}", vector.instruction()))),
    }
}

/// Three consecutive words of the device operand `operand` ((s1), (s1)+1, (s1)+2).
#[inline(always)]
fn read3(vector: &Vector, memory: &Memory<'_>, operand: &str) -> Result<[u16; 3], Refusal> {
    memory.operand_words(operand).ok_or_else(|| not_a_device(vector, operand))
}

/// A word read as "16-bit signed binary".
fn signed(word: u16) -> i64 {
    i64::from(word as i16)
}

/// Whether `condition` holds for (s1) compared with (s2): each condition as the set of orders
/// it holds for, one bit per order. A table read, not a branch per condition: the condition
/// changes from one vector to the next, and a jump on it was mispredicted at every execution.
fn holds(condition: Condition, order: Ordering) -> bool {
    const LESS: u8 = 0b001;
    const EQUAL: u8 = 0b010;
    const GREATER: u8 = 0b100;
    let holding = match condition {
        Condition::Eq => EQUAL,
        Condition::Ne => LESS | GREATER,
        Condition::Lt => LESS,
        Condition::Le => LESS | EQUAL,
        Condition::Gt => GREATER,
        Condition::Ge => EQUAL | GREATER,
    };
    let bit = match order {
        Ordering::Less => LESS,
        Ordering::Equal => EQUAL,
        Ordering::Greater => GREATER,
    };
    holding & bit != 0
}

/// A contact instruction's form and condition, as the generated names give them.
fn contact_of(instruction: Instruction) -> Result<(Form, Condition), Refusal> {
    match (instruction.form(), instruction.condition()) {
        (Some(form), Some(condition)) => Ok((form, condition)),
        _ => Err(Refusal::Error(format!("{instruction} is no comparison contact"))),
    }
}

/// The logic state before an AND/OR form.
fn rlo_in(step: &Step) -> Result<bool, Refusal> {
    step.rlo_in.ok_or_else(|| Refusal::Error("an AND/OR form needs the step's rlo_in".to_owned()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each condition's entry in the table against the comparison it names, worked out with the
    /// integers' own operators for (s1) below, equal to and above (s2).
    #[test]
    fn each_condition_holds_for_the_comparison_it_names() {
        for (s1, s2) in [(1, 2), (2, 2), (3, 2)] {
            let named = [
                (Condition::Eq, s1 == s2),
                (Condition::Ne, s1 != s2),
                (Condition::Lt, s1 < s2),
                (Condition::Le, s1 <= s2),
                (Condition::Gt, s1 > s2),
                (Condition::Ge, s1 >= s2),
            ];
            assert_eq!(named.map(|(c, _)| c), Condition::ALL, "every condition, once");
            for (condition, want) in named {
                assert_eq!(holds(condition, s1.cmp(&s2)), want, "{condition:?} for {s1} against {s2}");
            }
        }
    }
}
