//! The reference crate's integration tests that libtest runs, one module per concern, in one test
//! binary: each binary cargo builds is linked on its own, and a binary per file made most of
//! `cargo test`'s build time. `vectors` and `early_end` have a `main` of their own (`harness =
//! false`) and stay binaries of their own.

mod harness;
mod loading;
mod mutants;
mod readings;
mod reference;
mod serve;
mod text;
mod watchdog;
