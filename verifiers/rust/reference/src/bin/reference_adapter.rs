//! The reference implementation served over the plcvec stdio protocol (PROTOCOL.md):
//!
//! ```sh
//! plcvec verify --adapter "verifiers/rust/reference-adapter [--mutant NAME] [--choose ID=ALT]"
//! ```
#![forbid(unsafe_code)]

use std::io::{stdin, stdout, BufWriter};
use std::process::ExitCode;

use plcvec::serve::{serve, AdapterInfo};
use plcvec::{Choices, OnMemory};
use plcvec_reference::{Mutant, Reference};

const USAGE: &str = "usage: plcvec-reference-adapter [--mutant NAME] [--choose INTERPRETATION=ALTERNATIVE]...";

fn main() -> ExitCode {
    let mut mutant = None;
    let mut choices = Choices::new();
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--mutant" => {
                let Some(name) = args.next() else { return usage("--mutant needs a NAME") };
                let Some(m) = Mutant::from_name(&name) else {
                    let names: Vec<&str> = Mutant::ALL.iter().map(|m| m.name()).collect();
                    return usage(&format!("no mutant {name:?}; known: {}", names.join(", ")));
                };
                mutant = Some(m);
            }
            "--choose" => {
                let Some((i, a)) =
                    args.next().and_then(|c| c.split_once('=').map(|(i, a)| (i.to_owned(), a.to_owned())))
                else {
                    return usage("--choose takes INTERPRETATION=ALTERNATIVE");
                };
                let known = plcvec::names::INTERPRETATIONS.iter().find(|x| x.id == i);
                match known {
                    Some(x) if x.alternatives.contains(&a.as_str()) => choices.declare(&i, &a),
                    Some(x) => return usage(&format!("{i} has the alternatives {}", x.alternatives.join(", "))),
                    None => return usage(&format!("no interpretation {i:?}")),
                }
            }
            "-h" | "--help" => {
                println!("{USAGE}");
                return ExitCode::SUCCESS;
            }
            other => return usage(&format!("unknown argument {other:?}")),
        }
    }
    let reference = match mutant {
        Some(m) => Reference::mutant(m, choices),
        None => Reference::with_choices(choices),
    };
    let name = plcvec::Execute::name(&reference);
    let mut implementation = OnMemory(reference);
    let info = AdapterInfo { name, version: env!("CARGO_PKG_VERSION").to_owned() };
    match serve(&mut implementation, &info, stdin().lock(), BufWriter::new(stdout().lock())) {
        Ok(0) => ExitCode::SUCCESS,
        Ok(_) => ExitCode::from(1),
        Err(e) => {
            eprintln!("plcvec-reference-adapter: {e}");
            ExitCode::from(1)
        }
    }
}

fn usage(message: &str) -> ExitCode {
    eprintln!("plcvec-reference-adapter: {message}\n{USAGE}");
    ExitCode::from(2)
}
