//! Every plcvec vector of TADD/TADDP run against the emulator, one test each: `cargo test`.
use plcvec::{Execute, Memory, Refusal, Step, Vector};

fn main() -> std::process::ExitCode {
    plcvec::harness::run(|| plcvec::OnMemory(Glue::default()))
}

/// The emulator on plcvec's memory: operands, device ranges, flags, and TADDP's edge.
#[derive(Default)]
struct Glue {
    previous_en: bool,
}

impl Execute for Glue {
    fn supports(&self, instruction: &str) -> bool {
        matches!(instruction, "TADD" | "TADDP") // the other vectors are reported as ignored
    }

    fn begin(&mut self, _vector: &Vector) -> Result<(), Refusal> {
        self.previous_en = false; // nothing carries over between vectors
        Ok(())
    }

    fn execute(&mut self, vector: &Vector, step: &Step, mem: &mut Memory<'_>) -> Result<Option<bool>, Refusal> {
        let en = step.en.unwrap_or(false);
        let rising = en && !self.previous_en;
        self.previous_en = en;
        if !en || (vector.instruction() == "TADDP" && !rising) {
            return Ok(None);
        }
        let device = |name| vector.operand(name).and_then(|o| o.device()).ok_or(Refusal::Error(format!("{name}?")));
        let (s1, s2, d) = (device("s1")?, device("s2")?, device("d")?);
        let code = if [s1, s2, d].iter().any(|a| !mem.in_range(a, 3)) {
            Some(0x2820) // the device range is exceeded: nothing is read or written
        } else {
            // (s1), (s1)+1, (s1)+2: the operand's words, found once when the vector was loaded
            let read = |name| mem.operand_words::<3>(name).ok_or(Refusal::Error(format!("{name}?")));
            match minimal_emulator::tadd(read("s1")?, read("s2")?) {
                Ok(sum) => {
                    for (i, w) in sum.time.into_iter().enumerate() {
                        mem.set_word(d, i as u32, w);
                    }
                    mem.set_bit("SM700", sum.carry);
                    mem.set_bit("SM8022", sum.carry);
                    mem.set_bit("SM8020", sum.zero);
                    None
                }
                Err(code) => Some(code),
            }
        };
        if let Some(code) = code {
            mem.set("SD0", code.into());
            mem.set("SD8067", code.into());
        }
        Ok(None) // TADD is not a contact: no result
    }
}
