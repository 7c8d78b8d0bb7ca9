//! The crate's integration tests, one module per concern, in one test binary: each binary cargo
//! builds is linked on its own, and a binary per file made most of `cargo test`'s build time.

mod failures;
mod modules;
mod unjudged;
