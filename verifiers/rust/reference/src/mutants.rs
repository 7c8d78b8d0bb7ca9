//! Single-bug variants of the reference: each is the reference with one plausible bug an
//! emulator could have. The suite must reject every one of them, by name (tests/mutants.rs);
//! a mutant no vector catches means the vectors miss a case.

use plcvec::names::Family;

/// A mutant of the reference implementation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Mutant {
    /// The selected fields are compared from (s1)+2 up, so a later field decides first.
    Fx5LowFieldFirst,
    /// Bits 3 to 14 of (s3) are masked off instead of making the result non-continuity.
    Fx5ReservedBitsIgnored,
    /// SM709 is written off whenever the data are good, although it is held once on.
    Fx5Sm709NotLatched,
    /// (s1)..(s1)+2 and (s2)..(s2)+2 are not checked against the device range.
    Fx5DeviceRangeUnchecked,
    /// An AND form while the preceding logic is off passes on its own comparison, as LD would.
    Fx5AndAsLdWhenOff,
    /// A sum of exactly 24:00:00 is stored as 24:00:00 with neither flag.
    TaddNoWrapAt24,
    /// Only SM700 is written as the carry flag; SM8022 is left alone.
    TaddSm8022NotWritten,
    /// TADDP adds on every scan while EN is on, not once on the rising edge.
    TaddpEveryScan,
    /// (s1), (s2) and (d) are not checked against the device range: D beyond D7999 is written.
    TaddDeviceRangeUnchecked,
    /// (s1) is copied into (d) from the hour down, then (s2) is added to (d) in place, so a word of
    /// (s2), or a later word of (s1), that is also a word of (d) is overwritten before it is read.
    TaddS1CopiedIntoDFirst,
    /// D2 turns on only once D1 is past S1, not when it reaches it.
    HourOutputAbovePreset,
    /// Each scan's ON time is cut to whole seconds and the remainder thrown away.
    HourDropsFraction,
    /// D2 is turned off when D1 wraps to 0:00:00, instead of remaining on.
    HourWrapClearsD2,
    /// Only S1 is checked for BCD: a non-BCD byte of S2 is compared as binary.
    Cp1eS2BcdUnchecked,
    /// AND =DT ... AND >=DT combine with the preceding logic as OR does.
    Cp1eAndAsOr,
    /// The arithmetic flags (=, <>, <, <=, >, >=) are left alone.
    Cp1eFlagsNotReflected,
    /// An execution that ends in error does not turn P_ER on (the rest of the error is handled).
    Cp1eErFlagNotSet,
    /// S1 or S2 at the last one or two words of the data area is compared all the same, the words
    /// past the end read as 0, instead of the error or program error CP1E-PAST-AREA-END names.
    Cp1ePastAreaCompared,
}

impl Mutant {
    /// Every mutant.
    pub const ALL: &'static [Mutant] = &[
        Mutant::Fx5LowFieldFirst,
        Mutant::Fx5ReservedBitsIgnored,
        Mutant::Fx5Sm709NotLatched,
        Mutant::Fx5DeviceRangeUnchecked,
        Mutant::Fx5AndAsLdWhenOff,
        Mutant::TaddNoWrapAt24,
        Mutant::TaddSm8022NotWritten,
        Mutant::TaddpEveryScan,
        Mutant::TaddDeviceRangeUnchecked,
        Mutant::TaddS1CopiedIntoDFirst,
        Mutant::HourOutputAbovePreset,
        Mutant::HourDropsFraction,
        Mutant::HourWrapClearsD2,
        Mutant::Cp1eS2BcdUnchecked,
        Mutant::Cp1eAndAsOr,
        Mutant::Cp1eFlagsNotReflected,
        Mutant::Cp1eErFlagNotSet,
        Mutant::Cp1ePastAreaCompared,
    ];

    /// The mutant's name (`tadd-no-wrap-at-24`), as the adapter's `--mutant` takes it.
    pub fn name(self) -> &'static str {
        match self {
            Mutant::Fx5LowFieldFirst => "fx5-low-field-first",
            Mutant::Fx5ReservedBitsIgnored => "fx5-reserved-bits-ignored",
            Mutant::Fx5Sm709NotLatched => "fx5-sm709-not-latched",
            Mutant::Fx5DeviceRangeUnchecked => "fx5-device-range-unchecked",
            Mutant::Fx5AndAsLdWhenOff => "fx5-and-as-ld-when-off",
            Mutant::TaddNoWrapAt24 => "tadd-no-wrap-at-24",
            Mutant::TaddSm8022NotWritten => "tadd-sm8022-not-written",
            Mutant::TaddpEveryScan => "taddp-every-scan",
            Mutant::TaddDeviceRangeUnchecked => "tadd-device-range-unchecked",
            Mutant::TaddS1CopiedIntoDFirst => "tadd-s1-copied-into-d-first",
            Mutant::HourOutputAbovePreset => "hour-output-above-preset",
            Mutant::HourDropsFraction => "hour-drops-fraction",
            Mutant::HourWrapClearsD2 => "hour-wrap-clears-d2",
            Mutant::Cp1eS2BcdUnchecked => "cp1e-s2-bcd-unchecked",
            Mutant::Cp1eAndAsOr => "cp1e-and-as-or",
            Mutant::Cp1eFlagsNotReflected => "cp1e-flags-not-reflected",
            Mutant::Cp1eErFlagNotSet => "cp1e-er-flag-not-set",
            Mutant::Cp1ePastAreaCompared => "cp1e-past-area-compared",
        }
    }

    /// The families whose vectors must catch it.
    pub fn families(self) -> &'static [Family] {
        match self {
            Mutant::Fx5LowFieldFirst
            | Mutant::Fx5ReservedBitsIgnored
            | Mutant::Fx5Sm709NotLatched
            | Mutant::Fx5DeviceRangeUnchecked
            | Mutant::Fx5AndAsLdWhenOff => &[Family::Fx5TimeCompare, Family::Fx5DateCompare],
            Mutant::TaddNoWrapAt24
            | Mutant::TaddSm8022NotWritten
            | Mutant::TaddpEveryScan
            | Mutant::TaddDeviceRangeUnchecked
            | Mutant::TaddS1CopiedIntoDFirst => &[Family::Fx5TimeAdd],
            Mutant::HourOutputAbovePreset | Mutant::HourDropsFraction | Mutant::HourWrapClearsD2 => {
                &[Family::Fc6aHourMeter]
            }
            Mutant::Cp1eS2BcdUnchecked
            | Mutant::Cp1eAndAsOr
            | Mutant::Cp1eFlagsNotReflected
            | Mutant::Cp1eErFlagNotSet
            | Mutant::Cp1ePastAreaCompared => &[Family::Cp1eTimeCompare],
        }
    }

    /// The mutant of a name.
    pub fn from_name(name: &str) -> Option<Mutant> {
        Mutant::ALL.iter().copied().find(|m| m.name() == name)
    }
}
