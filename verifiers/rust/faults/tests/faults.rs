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
    "closes-fds",
    "child-holds-stdout",
    "follows-alternative",
];

/// Named by the table of faults but not built here: a Rust word is a `u16`, so an implementation
/// cannot report 65536 or a NaN (the rows are exempt, README.md "The table of faults").
const CANNOT: &[&str] = &["word-65536", "not-a-number"];

fn main() -> ExitCode {
    let name = std::env::var("PLCVEC_HOSTILE").ok().filter(|n| !n.is_empty()).unwrap_or_else(|| "reference".into());
    let Some(&hostile) = NAMES.iter().find(|&&n| n == name) else {
        let why = if CANNOT.contains(&name.as_str()) {
            "its value does not fit a Rust word (u16)"
        } else {
            "no such hostile implementation"
        };
        eprintln!("faults: PLCVEC_HOSTILE={name}: {why}; known: {}", NAMES.join(", "));
        return ExitCode::from(2);
    };
    let on = std::env::var("PLCVEC_HOSTILE_ON").unwrap_or_default();
    // follows-alternative: the reference following `ID=alternative`, declared nowhere.
    let followed = match std::env::var("PLCVEC_HOSTILE_CHOICE").ok().filter(|_| hostile == "follows-alternative") {
        Some(choice) => match choice.split_once('=') {
            Some((id, alternative)) => [(id, alternative)].into_iter().collect(),
            None => {
                eprintln!("faults: PLCVEC_HOSTILE_CHOICE={choice}: not ID=alternative");
                return ExitCode::from(2);
            }
        },
        None => Choices::new(),
    };
    plcvec::harness::run(move || Hostile {
        hostile,
        on: on.clone(),
        reference: Reference::with_choices(followed.clone()),
    })
}

struct Hostile {
    hostile: &'static str,
    on: String,
    /// The reference (following `PLCVEC_HOSTILE_CHOICE` for follows-alternative).
    reference: Reference,
}

/// Close every descriptor from 3 to 1023, whatever opened it (the harness, the test runner).
fn close_inherited_descriptors() {
    for fd in 3..1024 {
        // SAFETY: the hostile's whole point is to pull descriptors from under the runner; nothing
        // in this process that reads or writes one may rely on it surviving.
        unsafe {
            libc::close(fd);
        }
    }
}

/// Start a process that inherits stdout and stderr and outlives the vector (300 s).
fn start_child_holding_stdout() {
    let child = std::process::Command::new("sleep").arg("300").stdin(std::process::Stdio::null()).spawn();
    if let Err(e) = child {
        eprintln!("faults: cannot start `sleep 300`: {e}");
    }
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
                "closes-fds" => close_inherited_descriptors(),
                "child-holds-stdout" => start_child_holding_stdout(),
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
                "wrong-result" | "closes-fds" => match result {
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
