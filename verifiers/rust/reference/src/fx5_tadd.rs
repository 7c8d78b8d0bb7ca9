//! Mitsubishi MELSEC iQ-F FX5: TADD / TADDP (adding clock data).
//!
//! Written from the manual page fx5-time-add-TADD.txt.

use plcvec::names::{Execution, Instruction, TaddErrorOrder, TaddExact24, TaddFlagsOff, TaddOnError, TaddOverlap};
use plcvec::{Address, Choices, Memory, Refusal, Step, Value, Vector};

use super::{device, read3, signed, Mutant};

const DAY: i64 = 24 * 3600;
// "SM700 Carry ... SM8020 Zero ... SM8022 Carry"
const CARRY_FLAGS: [&str; 2] = ["SM700", "SM8022"];
const ZERO_FLAG: &str = "SM8020";
// "Error code (SD0/SD8067)"
const ERROR_REGISTERS: [&str; 2] = ["SD0", "SD8067"];
// "2820H The device range specified by (s1), (s2), and (d) exceeds the corresponding device range."
const ERR_DEVICE_RANGE: u16 = 0x2820;
// "3405H Any of values specified by (s1) and (s2) is outside the following range."
const ERR_VALUE_RANGE: u16 = 0x3405;
// "(s1) hour ... (s1)+1 minute ... (s1)+2 second": the seconds one unit of each word is worth,
// and what each word counts up to before it carries (24 hours, 60 minutes, 60 seconds).
const WEIGHTS: [i64; 3] = [3600, 60, 1];
const RADIX: [i64; 3] = [24, 60, 60];

#[derive(Clone, Debug)]
pub(super) struct Fx5TimeAdd {
    flags_off: TaddFlagsOff,
    exact_24: TaddExact24,
    on_error: TaddOnError,
    error_order: TaddErrorOrder,
    overlap: TaddOverlap,
    mutant: Option<Mutant>,
    /// TADDP: the state of EN before this scan ("off" before the first).
    previous_en: bool,
}

impl Fx5TimeAdd {
    pub(super) fn new(choices: &Choices, mutant: Option<Mutant>) -> Fx5TimeAdd {
        Fx5TimeAdd {
            flags_off: choices.get(),
            exact_24: choices.get(),
            on_error: choices.get(),
            error_order: choices.get(),
            overlap: choices.get(),
            mutant,
            previous_en: false,
        }
    }

    pub(super) fn reset(&mut self) {
        self.previous_en = false;
    }

    fn bug(&self, m: Mutant) -> bool {
        self.mutant == Some(m)
    }

    pub(super) fn execute(
        &mut self,
        instruction: Instruction,
        vector: &Vector,
        step: &Step,
        mem: &mut Memory<'_>,
    ) -> Result<(), Refusal> {
        let en = step.en.ok_or_else(|| Refusal::Error(format!("{instruction} needs the step's en")))?;
        let run = match instruction.execution() {
            Execution::EveryScan => en, // TADD: every scan while EN is on
            Execution::RisingEdge if self.bug(Mutant::TaddpEveryScan) => en,
            Execution::RisingEdge => en && !self.previous_en, // TADDP: the rising edge of EN only
        };
        self.previous_en = en;
        if run {
            self.add(vector, mem)?;
        }
        Ok(())
    }

    fn add(&self, vector: &Vector, mem: &mut Memory<'_>) -> Result<(), Refusal> {
        let (s1_dev, s2_dev, d_dev) = (device(vector, "s1")?, device(vector, "s2")?, device(vector, "d")?);
        // "(s1) hour (0 to 23) ... minute (0 to 59) ... second (0 to 59)", the same for (s2):
        // 3405H. Only an operand whose three words exist can be read and checked.
        let ranges = [(0, 23), (0, 59), (0, 59)];
        let out_of_range = |name: &str, dev| -> Result<bool, Refusal> {
            if !mem.in_range(dev, 3) {
                return Ok(false);
            }
            let data = read3(vector, mem, name)?.map(signed);
            Ok(data.iter().zip(ranges).any(|(v, (lo, hi))| !(lo..=hi).contains(v)))
        };
        let bad = out_of_range("s1", s1_dev)? || out_of_range("s2", s2_dev)?;
        // "These instructions occupy three points for each of three devices"; out of range:
        // 2820H, and nothing is read or written. With a field out of range as well,
        // TADD-ERROR-ORDER says which code is stored.
        if !self.bug(Mutant::TaddDeviceRangeUnchecked) && [s1_dev, s2_dev, d_dev].iter().any(|d| !mem.in_range(d, 3)) {
            let first = if bad && self.error_order == TaddErrorOrder::FieldRangeFirst {
                ERR_VALUE_RANGE
            } else {
                ERR_DEVICE_RANGE
            };
            error(mem, first);
            return Ok(());
        }
        if bad {
            error(mem, ERR_VALUE_RANGE);
            if self.on_error == TaddOnError::NotExecuted {
                return Ok(());
            }
        }
        let total = self.sum_seconds(mem, [s1_dev, s2_dev, d_dev]);
        let (result, carry) = self.wrap(total);
        let (h, m, s) = (result / 3600, result % 3600 / 60, result % 60);
        for (offset, v) in [h, m, s].into_iter().enumerate() {
            mem.set_word(d_dev, offset as u32, v as u16);
        }
        // "If the result is 0 (0:00:00), the zero flag turns on."
        self.set_flags(mem, carry, result == 0);
        Ok(())
    }

    /// (s1) + (s2) in seconds, the words read in the order TADD-OVERLAP says. The order shows only
    /// when (d) shares words with (s1) or (s2) at another offset ((d) = (s1)+1, ...): then a source
    /// word read after that word of (d) was written holds what was written.
    fn sum_seconds(&self, mem: &mut Memory<'_>, [s1, s2, d]: [&Address; 3]) -> i64 {
        let word = |mem: &Memory<'_>, dev: &Address, k: usize| signed(mem.word(dev, k as u32));
        let s1 = if self.bug(Mutant::TaddS1CopiedIntoDFirst) {
            // (s1) copied into (d) from the hour down, then (s2) added to (d) in place.
            for k in 0..3 {
                let w = mem.word(s1, k);
                mem.set_word(d, k, w);
            }
            d
        } else {
            s1
        };
        let mut total = 0;
        match self.overlap {
            // Every word of (s1) and (s2) is read before (d) is written.
            TaddOverlap::SourcesFirst => {
                let (a, b) = ([0, 1, 2].map(|k| word(mem, s1, k)), [0, 1, 2].map(|k| word(mem, s2, k)));
                total = a.iter().zip(b).zip(WEIGHTS).map(|((a, b), weight)| (a + b) * weight).sum();
            }
            // Second, minute, hour, the carry's way: each word of (d) gets its digit as soon as it
            // is known, and the next pair of words is read after that.
            TaddOverlap::SecondFirst => {
                let mut carry = 0;
                for k in (0..3).rev() {
                    let sum = word(mem, s1, k) + word(mem, s2, k);
                    total += sum * WEIGHTS[k];
                    let digit = (sum + carry).rem_euclid(RADIX[k]);
                    carry = (sum + carry).div_euclid(RADIX[k]);
                    mem.set_word(d, k as u32, digit as u16);
                }
            }
            // Hour, minute, second, in the words' order: the plain sum of each pair into (d); the
            // carries are settled afterwards, when the caller writes the time of day of the total.
            TaddOverlap::HourFirst => {
                for (k, weight) in WEIGHTS.into_iter().enumerate() {
                    let sum = word(mem, s1, k) + word(mem, s2, k);
                    total += sum * weight;
                    mem.set_word(d, k as u32, sum as u16);
                }
            }
        }
        total
    }

    /// The sum in seconds -> (the result in seconds, the carry).
    fn wrap(&self, total: i64) -> (i64, bool) {
        // "If the sum of two values exceeds 24:00:00, the carry flag turns on, and the result
        // will be the sum minus 24:00:00." But: "If 1 second is added to 23:59:59, the result will
        // be 0:00:00. This turns on both the carry flag and the zero flag." -> TADD-EXACT-24.
        if self.bug(Mutant::TaddNoWrapAt24) && total == DAY {
            return (total, false);
        }
        let carry = match self.exact_24 {
            TaddExact24::CarryAt24 => total >= DAY,
            TaddExact24::CarryAbove24 => total > DAY,
        };
        (total.rem_euclid(DAY), carry)
    }

    fn set_flags(&self, mem: &mut Memory<'_>, carry: bool, zero: bool) {
        let carry_flags: &[&str] =
            if self.bug(Mutant::TaddSm8022NotWritten) { &CARRY_FLAGS[..1] } else { &CARRY_FLAGS };
        match self.flags_off {
            TaddFlagsOff::WrittenEachExecution => {
                for f in carry_flags {
                    mem.set_bit(f, carry);
                }
                mem.set_bit(ZERO_FLAG, zero);
            }
            // An execution only ever turns a flag on.
            TaddFlagsOff::SetOnly => {
                if carry {
                    for f in carry_flags {
                        mem.set_bit(f, true);
                    }
                }
                if zero {
                    mem.set_bit(ZERO_FLAG, true);
                }
            }
        }
    }
}

fn error(mem: &mut Memory<'_>, code: u16) {
    for register in ERROR_REGISTERS {
        mem.set(register, Value::Word(code));
    }
}
