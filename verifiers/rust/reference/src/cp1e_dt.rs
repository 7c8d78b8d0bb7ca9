//! Omron SYSMAC CP1E: LD/AND/OR =DT, <>DT, <DT, <=DT, >DT, >=DT (time comparison).
//!
//! Written from the manual page cp1e-time-compare-DT.txt (W483 p. 2-93).
//!
//! P_ER is an Omron condition flag: it reflects the result of the instruction just executed, so
//! an execution that ends without error turns it off (spec: validity.error.latch false). The
//! other reading, that only an error ever writes P_ER, is the alternative `held` of CP1E-ER-FLAG.

use std::cmp::Ordering;

use plcvec::names::{
    Condition, Cp1eAllMasked, Cp1eAndOrWhenOff, Cp1eCHighBits, Cp1eErFlag, Cp1eErrorFlags, Cp1eNonBcd, Cp1eOutOfRange,
    Cp1ePastAreaEnd, Form,
};
use plcvec::{Choices, Memory, Refusal, Vector};

use super::{device, holds, read3, rlo_in, word_operand, Mutant};

const ERROR_FLAG: &str = "P_ER";
// "the result of a time comparison instruction is reflected in the arithmetic flags (=, <>, <,
// <=, >, >=)."
const FLAGS: [&str; 6] = ["P_EQ", "P_NE", "P_LT", "P_LE", "P_GT", "P_GE"]; // in Condition::ALL's order

/// One field of the Calendar/Clock layout, most significant first.
struct Field {
    word: usize,
    /// 0: bits 00-07, 1: bits 08-15.
    byte: u32,
    min: u8,
    max: u8,
    /// The bit of C that masks it.
    mask_bit: u16,
}

// "A351.00 to A351.07 Second (00 to 59, BCD) A351.08 to A351.15 Minute (00 to 59, BCD)
//  A352.00 to A352.07 Hour (00 to 23, BCD)   A352.08 to A352.15 Day of month (01 to 31, BCD)
//  A353.00 to A353.07 Month (01 to 12, BCD)  A353.08 to A353.15 Year (00 to 99, BCD)"
// "Bits 00 to 05 of C mask the seconds, minutes, hours, day, month, and year, respectively."
const FIELDS: [Field; 6] = [
    Field { word: 2, byte: 1, min: 0, max: 99, mask_bit: 5 }, // year
    Field { word: 2, byte: 0, min: 1, max: 12, mask_bit: 4 }, // month
    Field { word: 1, byte: 1, min: 1, max: 31, mask_bit: 3 }, // day
    Field { word: 1, byte: 0, min: 0, max: 23, mask_bit: 2 }, // hour
    Field { word: 0, byte: 1, min: 0, max: 59, mask_bit: 1 }, // minute
    Field { word: 0, byte: 0, min: 0, max: 59, mask_bit: 0 }, // second
];

#[derive(Clone, Debug)]
pub(super) struct Cp1eTimeCompare {
    non_bcd: Cp1eNonBcd,
    out_of_range: Cp1eOutOfRange,
    all_masked: Cp1eAllMasked,
    c_high_bits: Cp1eCHighBits,
    and_or: Cp1eAndOrWhenOff,
    er_flag: Cp1eErFlag,
    error_flags: Cp1eErrorFlags,
    past_area_end: Cp1ePastAreaEnd,
    mutant: Option<Mutant>,
}

fn is_bcd(b: u8) -> bool {
    b >> 4 <= 9 && b & 0xF <= 9
}

fn bcd_value(b: u8) -> u8 {
    (b >> 4) * 10 + (b & 0xF)
}

/// The six arithmetic flags after a comparison that found `order`. Written out flag by flag, not
/// as a loop over FLAGS: each name is then a constant, whose slot `Memory::set_bit` finds by a
/// key worked out at compile time (the loop packed the six names at every execution: a sixth of
/// the time a vector of this family took to judge).
fn reflect(mem: &mut Memory<'_>, order: Ordering) {
    mem.set_bit(FLAGS[0], holds(Condition::ALL[0], order));
    mem.set_bit(FLAGS[1], holds(Condition::ALL[1], order));
    mem.set_bit(FLAGS[2], holds(Condition::ALL[2], order));
    mem.set_bit(FLAGS[3], holds(Condition::ALL[3], order));
    mem.set_bit(FLAGS[4], holds(Condition::ALL[4], order));
    mem.set_bit(FLAGS[5], holds(Condition::ALL[5], order));
}

impl Cp1eTimeCompare {
    pub(super) fn new(choices: &Choices, mutant: Option<Mutant>) -> Cp1eTimeCompare {
        let er_flag = choices.get::<Cp1eErFlag>();
        Cp1eTimeCompare {
            non_bcd: choices.get(),
            out_of_range: choices.get(),
            all_masked: choices.get(),
            c_high_bits: choices.get(),
            and_or: choices.get(),
            er_flag,
            error_flags: choices.get(),
            past_area_end: choices.get(),
            mutant,
        }
    }

    fn bug(&self, m: Mutant) -> bool {
        self.mutant == Some(m)
    }

    pub(super) fn execute(
        &self,
        form: Form,
        symbol: Condition,
        step: &plcvec::Step,
        vector: &Vector,
        mem: &mut Memory<'_>,
    ) -> Result<bool, Refusal> {
        // "The time comparison instructions are treated just like the LD, AND, and OR
        // instructions to control the execution of subsequent instructions."
        match form {
            Form::Ld => self.evaluate(symbol, vector, mem),
            Form::And => {
                let rlo = rlo_in(step)?;
                if !rlo && matches!(self.and_or, Cp1eAndOrWhenOff::AndSkipped | Cp1eAndOrWhenOff::ShortCircuit) {
                    return Ok(false);
                }
                let contact = self.evaluate(symbol, vector, mem)?;
                Ok(if self.bug(Mutant::Cp1eAndAsOr) { rlo || contact } else { rlo && contact })
            }
            Form::Or => {
                let rlo = rlo_in(step)?;
                if rlo && self.and_or == Cp1eAndOrWhenOff::ShortCircuit {
                    return Ok(true); // decided already: not executed, the flags left as they were
                }
                let contact = self.evaluate(symbol, vector, mem)?;
                Ok(rlo || contact)
            }
        }
    }

    fn evaluate(&self, condition: Condition, vector: &Vector, mem: &mut Memory<'_>) -> Result<bool, Refusal> {
        // Error: P_ER on, the execution condition off. The flag table has no row for an
        // execution without a comparison result: the six flags keep their values, or
        // (CP1E-ERROR-FLAGS=off) are all written off.
        let error_flags = self.error_flags;
        let sets_error_flag = !self.bug(Mutant::Cp1eErFlagNotSet);
        let error = |mem: &mut Memory<'_>| {
            if sets_error_flag {
                mem.set_bit(ERROR_FLAG, true);
            }
            if error_flags == Cp1eErrorFlags::Off {
                for flag in FLAGS {
                    mem.set_bit(flag, false);
                }
            }
            Ok(false)
        };

        // "S 1 to S 1 +2", "S 2 to S 2 +2": three words each. One past the end of the data area
        // (S1 or S2 at one of the last two words of D) is CP1E-PAST-AREA-END, found before C or
        // the data are read.
        let within = |operand| device(vector, operand).map(|dev| mem.in_range(dev, 3));
        let checked = !self.bug(Mutant::Cp1ePastAreaCompared);
        if checked && !(within("S1")? && within("S2")?) {
            return match self.past_area_end {
                Cp1ePastAreaEnd::Error => error(mem),
                // Not executed: nothing written, an OFF execution condition.
                Cp1ePastAreaEnd::ProgramError => Ok(false),
            };
        }
        let s1 = read3(vector, mem, "S1")?;
        let s2 = read3(vector, mem, "S2")?;
        let c = word_operand(vector, mem, "C")?;
        // Bits 06 to 15 of C: not described by the manual (CP1E-C-HIGH-BITS).
        if c & 0xFFC0 != 0 && self.c_high_bits == Cp1eCHighBits::Error {
            return error(mem);
        }
        // "To mask a time value, set the corresponding bit in the control word (C) to 1."
        // "compares the unmasked values (corresponding bit of C set to 0)"
        let unmasked = FIELDS.iter().filter(|f| c >> f.mask_bit & 1 == 0);
        if unmasked.clone().next().is_none() {
            match self.all_masked {
                Cp1eAllMasked::Error => return error(mem),
                // Nothing compared, no result: OFF, the flags untouched, no error.
                Cp1eAllMasked::NotCompared => {
                    if self.er_flag == Cp1eErFlag::ReflectsEachExecution {
                        mem.set_bit(ERROR_FLAG, false);
                    }
                    return Ok(false);
                }
                Cp1eAllMasked::Equal => {}
            }
        }
        let byte = |words: &[u16; 3], f: &Field| (words[f.word] >> (8 * f.byte)) as u8;
        let mut order = Ordering::Equal;
        for f in unmasked {
            let (a, b) = (byte(&s1, f), byte(&s2, f));
            for (k, raw) in [a, b].into_iter().enumerate() {
                let unchecked = k == 1 && self.bug(Mutant::Cp1eS2BcdUnchecked);
                if !is_bcd(raw) && !unchecked {
                    // "Second (00 to 59, BCD)" ... (CP1E-NON-BCD)
                    if self.non_bcd == Cp1eNonBcd::Error {
                        return error(mem);
                    }
                } else if !(f.min..=f.max).contains(&bcd_value(raw)) && self.out_of_range == Cp1eOutOfRange::Error {
                    return error(mem);
                }
            }
            // "The time comparison instructions are limited to comparing 8-bit time values."
            // For valid BCD the byte order is the numeric order; with "raw-bytes" the bytes are
            // compared as unsigned 8-bit values.
            if order == Ordering::Equal {
                order = a.cmp(&b);
            }
        }
        if !self.bug(Mutant::Cp1eFlagsNotReflected) {
            reflect(mem, order);
        }
        if self.er_flag == Cp1eErFlag::ReflectsEachExecution {
            mem.set_bit(ERROR_FLAG, false); // executed without error
        }
        Ok(holds(condition, order))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The flags `reflect` leaves on for each order, by the manual's names of the six arithmetic
    /// flags (=, <>, <, <=, >, >=), from an image with every flag off and one with every flag on:
    /// each flag is written, whatever it held.
    #[test]
    fn reflect_writes_each_flag_by_the_order_found() {
        let on_for = [
            (Ordering::Less, ["P_NE", "P_LT", "P_LE"]),
            (Ordering::Equal, ["P_EQ", "P_LE", "P_GE"]),
            (Ordering::Greater, ["P_NE", "P_GT", "P_GE"]),
        ];
        for before in [false, true] {
            let devices: serde_json::Map<String, serde_json::Value> =
                FLAGS.iter().map(|f| ((*f).to_owned(), before.into())).collect();
            let vector = Vector::from_request(&serde_json::json!({
                "id": "t", "family": "cp1e-time-compare", "instruction": "LD =DT",
                "initial": {"devices": devices, "operands": {}}, "steps": [{}],
            }))
            .unwrap();
            for (order, on) in on_for {
                let mut mem = Memory::new(&vector);
                reflect(&mut mem, order);
                for flag in FLAGS {
                    assert_eq!(mem.bit(flag), on.contains(&flag), "{flag} after {order:?}, {before} before");
                }
                assert!(mem.outside().is_empty());
            }
        }
    }
}
