//! # plcvec: conformance test vectors for PLC clock and calendar instructions
//!
//! The golden vectors travel inside this crate. Implement [`Implementation`] (the contract:
//! a vector's initial state and steps in, the device image after each step out) or the thinner
//! [`Execute`] ("execute this instruction on my memory", wrapped in [`OnMemory`]), and run every
//! vector as its own test under `cargo test` with [`harness::run`]:
//!
//! ```no_run
//! // tests/plcvec.rs, with `[[test]] name = "plcvec"`, `harness = false` in Cargo.toml
//! # struct MyEmulator;
//! # impl plcvec::Execute for MyEmulator {
//! #     fn execute(&mut self, _: &plcvec::Vector, _: &plcvec::Step, _: &mut plcvec::Memory<'_>)
//! #         -> Result<Option<bool>, plcvec::Refusal> { Ok(None) }
//! # }
//! fn main() -> std::process::ExitCode {
//!     plcvec::harness::run(|| plcvec::OnMemory(MyEmulator))
//! }
//! ```
//!
//! What the vectors mean and how they are judged is the project's `verifiers/CONTRACT.md`;
//! the spec's names are generated into [`names`]; `PLCVEC_VECTORS` points at another copy.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod choices;
mod compare;
mod emulator;
mod error;
mod expect;
mod files;
// Rendered by `plcvec export --lang rust` (its folder holds nothing else; not formatted by hand).
#[rustfmt::skip]
mod generated {
    pub mod embedded;
    pub mod names;
    pub mod settings;
}
pub mod harness;
mod implementation;
mod infer;
mod keys;
mod known;
mod memory;
mod reports;
mod runner;
mod selection;
pub mod serve;
mod settings;
mod small;
mod suite;
mod unique;
mod value;
mod vector;
mod verdict;

pub use choices::{Alternative, Choices, Followed};
pub use compare::{ReportedStep, Steps};
pub use emulator::{Execute, OnMemory};
pub use error::{Error, Result};
pub use expect::Expected;
pub use generated::names;
pub use implementation::{Implementation, Refusal};
pub use known::{KnownFailure, KnownFailures};
pub use memory::Memory;
pub use runner::{judge, judge_plan, run, Plan, Report};
pub use selection::{shard_of, Selection};
#[allow(deprecated)]
pub use suite::FamilyInfo;
pub use suite::{FamilyHeader, InterpretationInfo, Suite, SCHEMA_MAJOR, VECTORS_ENV};
pub use value::{Address, Value};
pub use vector::{Clock, Operand, Step, Vector};
pub use verdict::{describe, Field, Problem, Status, Verdict};
