//! What an implementation provides: the contract-level [`Implementation`] trait, and the thin
//! [`Execute`] helper for emulators that only want to execute one instruction on their memory.

use std::fmt;

use crate::choices::Choices;
use crate::compare::Steps;
use crate::memory::Memory;
use crate::vector::{Step, Vector};

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

/// "Execute this instruction on my memory": the thin way to implement the contract. Wrap it in
/// [`OnMemory`] to get an [`Implementation`]: the wrapper builds the vector's [`Memory`],
/// applies each step's `set`, calls [`Execute::execute`] and reports the image.
pub trait Execute {
    /// The name reports show.
    fn name(&self) -> String {
        "implementation".to_owned()
    }

    /// The interpretation alternatives it follows; undeclared ones take the default.
    fn interpretations(&self) -> Choices {
        Choices::new()
    }

    /// Whether it implements an instruction.
    fn supports(&self, instruction: &str) -> bool {
        let _ = instruction;
        true
    }

    /// The devices its CPU writes on its own account ([`Implementation::cpu_writes`]).
    fn cpu_writes(&self) -> Vec<String> {
        Vec::new()
    }

    /// A new vector starts: forget any state an earlier one left (the previous EN of TADDP, the
    /// HOUR work area), and refuse the vector if it cannot be run (an operand form you lack).
    fn begin(&mut self, vector: &Vector) -> Result<(), Refusal> {
        let _ = vector;
        Ok(())
    }

    /// Execute `vector.instruction()` once with the step's inputs on `memory`; return the logic
    /// state after it for LD/AND/OR forms, `None` for the others.
    fn execute(&mut self, vector: &Vector, step: &Step, memory: &mut Memory<'_>) -> Result<Option<bool>, Refusal>;
}

/// An [`Execute`] as an [`Implementation`].
#[derive(Clone, Debug, Default)]
pub struct OnMemory<E>(pub E);

impl<E: Execute> Implementation for OnMemory<E> {
    fn name(&self) -> String {
        self.0.name()
    }
    fn interpretations(&self) -> Choices {
        self.0.interpretations()
    }
    fn supports(&self, instruction: &str) -> bool {
        self.0.supports(instruction)
    }
    fn cpu_writes(&self) -> Vec<String> {
        self.0.cpu_writes()
    }
    fn run(&mut self, vector: &Vector, steps: &mut Steps<'_>) -> Result<(), Refusal> {
        self.0.begin(vector)?;
        let mut memory = Memory::new(vector);
        for step in vector.steps() {
            memory.apply_set(step);
            let result = self.0.execute(vector, step, &mut memory)?;
            steps.memory(result, &memory);
        }
        Ok(())
    }
}
