//! What an implementation provides: the contract-level [`Implementation`] trait (the thin
//! [`Execute`](crate::Execute) helper for emulators is `emulator`).

use std::fmt;

use crate::choices::Choices;
use crate::compare::Steps;
use crate::vector::Vector;

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

    /// The devices its CPU writes on its own account (diagnostic relays and registers such as
    /// `SM0`, `SD0`): a write to one of them outside a vector is not a stray write. A vector
    /// that lists one still compares it.
    fn cpu_writes(&self) -> Vec<String> {
        Vec::new()
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
    fn cpu_writes(&self) -> Vec<String> {
        (**self).cpu_writes()
    }
    fn run(&mut self, vector: &Vector, steps: &mut Steps<'_>) -> Result<(), Refusal> {
        (**self).run(vector, steps)
    }
}
