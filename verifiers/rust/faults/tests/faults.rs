//! The implementation `PLCVEC_HOSTILE` names, run through the harness as a user's crate runs it:
//! the reference, or the reference misbehaving on the vector `PLCVEC_HOSTILE_ON` (or on every
//! vector, for the names that act on all). Only plcvec's public API, as an outside emulator.
use std::process::ExitCode;

use plcvec::{Choices, Execute, Implementation, Memory, Refusal, Steps, Value, Vector};
use plcvec_reference::Reference;

const NAMES: &[&str] = &[
    "reference",
    "wrong-result",
    "panic",
    "loop-forever",
    "empty-answer",
    "stray-write",
    "duplicate-write",
    "wrong-type",
    "out-of-range",
    "exit-zero",
    "exit-nonzero",
    "crash",
    "mutates-request",
    "supports-nothing",
    "skips-everything",
    "bad-choice",
    "cpu-writes",
];

fn main() -> ExitCode {
    let name = std::env::var("PLCVEC_HOSTILE").ok().filter(|n| !n.is_empty()).unwrap_or_else(|| "reference".into());
    let Some(&hostile) = NAMES.iter().find(|&&n| n == name) else {
        eprintln!("faults: PLCVEC_HOSTILE={name}: no such hostile implementation; known: {}", NAMES.join(", "));
        return ExitCode::from(2);
    };
    let on = std::env::var("PLCVEC_HOSTILE_ON").unwrap_or_default();
    plcvec::harness::run(move || Hostile { hostile, on: on.clone(), reference: Reference::new() })
}

struct Hostile {
    hostile: &'static str,
    on: String,
    reference: Reference,
}

impl Implementation for Hostile {
    fn name(&self) -> String {
        format!("hostile {}", self.hostile)
    }

    fn interpretations(&self) -> Choices {
        let mut choices = Choices::new();
        if self.hostile == "bad-choice" {
            choices.declare("NO-SUCH-INTERPRETATION", "x");
        }
        choices
    }

    fn supports(&self, instruction: &str) -> bool {
        self.hostile != "supports-nothing" && self.reference.supports(instruction)
    }

    fn cpu_writes(&self) -> Vec<String> {
        match self.hostile {
            "cpu-writes" => vec!["SM56".into(), "SD1".into(), "SD0".into()],
            _ => Vec::new(),
        }
    }

    fn run(&mut self, vector: &Vector, steps: &mut Steps<'_>) -> Result<(), Refusal> {
        if self.hostile == "skips-everything" {
            return Err(Refusal::Skip("skips every vector".into()));
        }
        let target = vector.id() == self.on;
        if target {
            match self.hostile {
                "panic" => panic!("hostile: a panic on {}", vector.id()),
                "loop-forever" => loop {
                    std::thread::sleep(std::time::Duration::from_millis(50));
                },
                "empty-answer" => return Ok(()),
                "exit-zero" => std::process::exit(0),
                "exit-nonzero" => std::process::exit(3),
                "crash" => std::process::abort(),
                _ => {}
            }
        }
        self.reference.begin(vector)?;
        let mut memory = Memory::new(vector);
        for step in vector.steps() {
            memory.apply_set(step);
            let mut result = self.reference.execute(vector, step, &mut memory)?;
            if self.hostile == "cpu-writes" {
                memory.set("SM56", Value::Bit(true));
                memory.set("SD1", Value::Word(1));
                if target {
                    memory.set("SD0", Value::Word(1));
                }
            }
            if !target {
                steps.memory(result, &memory);
                continue;
            }
            let scratch = vector.scratch();
            let word = (0..vector.devices().len()).find(|&i| !scratch[i] && memory.values()[i].word().is_some());
            let bit = (0..vector.devices().len()).find(|&i| memory.values()[i].bit().is_some());
            let mut image: Vec<(String, Value)> = memory.image().map(|(name, v)| (name.to_owned(), v)).collect();
            match self.hostile {
                "wrong-result" => match result {
                    Some(r) => result = Some(!r),
                    None => {
                        let i = word.expect("a vector with a word device");
                        image[i].1 = Value::Word(image[i].1.word().unwrap_or(0).wrapping_add(1));
                    }
                },
                "stray-write" => image.push(("D7777".into(), Value::Word(1))),
                "duplicate-write" => {
                    let (name, value) = image[0].clone();
                    let other = match value {
                        Value::Bit(b) => Value::Bit(!b),
                        Value::Word(w) => Value::Word(w.wrapping_add(1)),
                    };
                    image.push((name, other));
                }
                // A bit reported as the number 1: the nearest a `Value` can carry.
                "wrong-type" => image[bit.expect("a vector with a bit device")].1 = Value::Word(1),
                // 70000 does not fit a 16-bit word: a `Value` cannot carry it, so the nearest
                // is the 16 bits an emulator's truncation would give (70000 - 65536).
                "out-of-range" => {
                    image[word.expect("a vector with a word device")].1 = Value::Word((70000u32 % 65536) as u16)
                }
                // A `&Vector` cannot be changed by the implementation: the request is safe.
                _ => {}
            }
            steps.devices(result, image.iter().map(|(n, v)| (n.as_str(), *v)));
        }
        Ok(())
    }
}
