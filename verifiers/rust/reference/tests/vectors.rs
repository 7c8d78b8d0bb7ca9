//! Every vector as its own test, judged with the reference implementation: `cargo test --test
//! vectors -- fx5-time-add` runs one family. `PLCVEC_CHOOSE=ID=ALT,...` declares alternatives.
fn main() -> std::process::ExitCode {
    let choices: plcvec::Choices =
        std::env::var("PLCVEC_CHOOSE").unwrap_or_default().split(',').filter_map(|c| c.split_once('=')).collect();
    plcvec::harness::run(move || plcvec::OnMemory(plcvec_reference::Reference::with_choices(choices.clone())))
}
