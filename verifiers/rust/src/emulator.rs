//! "Execute this instruction on my memory": the thin [`Execute`] helper for emulators that only
//! want to execute one instruction on their memory, and [`OnMemory`], which makes one an
//! [`Implementation`].

use crate::choices::Choices;
use crate::compare::Steps;
use crate::implementation::{Implementation, Refusal};
use crate::memory::Memory;
use crate::vector::{Step, Vector};

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
