//! Every mutant of the reference is rejected by the suite, by name: each named vector fails on
//! the named field, the failures stay within the mutant's families, and the same vectors pass
//! with the reference. The vectors and fields are the ones each bug must break (from the manual
//! clause the bug contradicts, as recorded in verifiers/python/plcvec_reference/MUTANTS.md for
//! the mutants the Python reference shares), not read back from this run.

use std::sync::OnceLock;

use plcvec::{Choices, OnMemory, Selection, Status, Suite};
use plcvec_reference::{Mutant, Reference};

fn suite() -> &'static Suite {
    static SUITE: OnceLock<Suite> = OnceLock::new();
    SUITE.get_or_init(|| Suite::embedded().expect("the embedded vectors load"))
}

fn check(mutant: Mutant, caught_by: &[(&str, &str)]) {
    let suite = suite();
    let mut implementation = OnMemory(Reference::mutant(mutant, Choices::new()));
    let report = plcvec::run(suite, &mut implementation, &Selection::all(), None).unwrap();
    assert!(!report.passed(), "{} passes the suite", mutant.name());
    let families: Vec<&str> = mutant.families().iter().map(|f| f.as_str()).collect();
    for (v, verdict) in report.failures() {
        assert!(families.contains(&v.family()), "{} fails {} outside its families", mutant.name(), v.id());
        assert_eq!(verdict.status, Status::Fail, "{}: {}: {}", mutant.name(), v.id(), verdict.message);
    }
    for family in &families {
        assert!(report.failures().any(|(v, _)| v.family() == *family), "no {family} vector catches {}", mutant.name());
    }
    // A bug is never explained away: every reading the roll-up proposes for a mutant's failures is
    // marked partial (failures it leaves unexplained, or passes it would break, are of the same
    // families).
    let text = report.summary();
    if let Some(readings) = text.split("\nREADINGS: ").nth(1) {
        let groups = readings.lines().skip(1).take_while(|l| !l.trim_start().starts_with("declare:"));
        for line in groups {
            assert!(
                line.contains(" (partial: "),
                "{}: a reading explains the bug without the partial mark: {line}",
                mutant.name()
            );
        }
    }
    let mut reference = OnMemory(Reference::new());
    let clean = plcvec::run(suite, &mut reference, &Selection::all(), None).unwrap();
    for (id, field) in caught_by {
        let verdict = report.verdict(id).unwrap_or_else(|| panic!("the suite has no vector {id}"));
        assert_eq!(verdict.status, Status::Fail, "{} is not caught by {id}", mutant.name());
        assert!(
            verdict.problems.iter().any(|p| p.field == *field),
            "{}: {id} fails, but not on {field}: {:?}",
            mutant.name(),
            verdict.problems
        );
        assert_eq!(clean.verdict(id).map(|v| v.status), Some(Status::Pass), "the reference fails {id}");
    }
}

macro_rules! mutants {
    ($($test:ident: $mutant:ident => [$(($id:literal, $field:literal)),+ $(,)?];)+) => {
        $(
            #[test]
            fn $test() {
                check(Mutant::$mutant, &[$(($id, $field)),+]);
            }
        )+

        /// Every mutant has its test above.
        #[test]
        fn every_mutant_is_tested() {
            let tested = [$(Mutant::$mutant),+];
            for m in Mutant::ALL {
                assert!(tested.contains(m), "no test for mutant {}", m.name());
            }
            assert!(Mutant::ALL.len() >= 10);
        }
    };
}

mutants! {
    // The contact result: hour decides before minute.
    fx5_low_field_first: Fx5LowFieldFirst => [
        ("fx5-time-compare/ANDTM</logic/rlo-on/gt", "result"),
        ("fx5-date-compare/ANDDT</logic/rlo-on/gt", "result"),
    ];
    // The contact result: '(4) Set 0. If a value other than 0 is set, the operation result will be non-continuity.'
    fx5_reserved_bits_ignored: Fx5ReservedBitsIgnored => [
        ("fx5-time-compare/LDTM=/selector/000FH/equal-data/constant", "result"),
        ("fx5-date-compare/LDDT=/selector/000FH/equal-data/constant", "result"),
    ];
    // A device that must stay unchanged: 'Once SM709 turns on, the on state is held'.
    fx5_sm709_not_latched: Fx5Sm709NotLatched => [
        ("fx5-time-compare/LDTM=/latch/already-on-valid-data", "SM709"),
        ("fx5-date-compare/LDDT=/latch/already-on-valid-data", "SM709"),
    ];
    // A flag: the device areas exceed the range, so SM709 turns on.
    fx5_device_range_unchecked: Fx5DeviceRangeUnchecked => [
        ("fx5-time-compare/LDTM=/device-range/s1=D7998/0006H", "SM709"),
        ("fx5-date-compare/LDDT=/device-range/s1=D7998/0006H", "SM709"),
    ];
    // The contact result: an AND form with the preceding logic off passes on off, executed or not
    // (under every alternative of FX5-AND-OR-WHEN-OFF).
    fx5_and_as_ld_when_off: Fx5AndAsLdWhenOff => [
        ("fx5-time-compare/ANDTM</logic/rlo-off/lt", "result"),
        ("fx5-date-compare/ANDDT</logic/rlo-off/lt", "result"),
    ];
    // A changed word and the flags: 23:00:00 + 01:00:00 is 0:00:00 with carry and zero.
    tadd_no_wrap_at_24: TaddNoWrapAt24 => [
        ("fx5-time-add/TADD/carry/carry-out-of-hour/flags-off-before", "D300"),
        ("fx5-time-add/TADD/carry/carry-out-of-hour/flags-off-before", "SM700"),
        ("fx5-time-add/TADD/carry/carry-out-of-hour/flags-off-before", "SM8020"),
    ];
    // A flag: SM8022 is the table's second carry relay.
    tadd_sm8022_not_written: TaddSm8022NotWritten => [
        ("fx5-time-add/TADD/carry/below-wrap/flags-on-before", "SM8022"),
    ];
    // A changed word on a later scan: TADDP adds on the rising edge only.
    taddp_every_scan: TaddpEveryScan => [
        ("fx5-time-add/TADDP/pulse/off-on-on-off-on-on", "D302"),
    ];
    // A write outside the vector: (d) at D7998 runs past D7999, so 2820H and nothing written.
    tadd_device_range_unchecked: TaddDeviceRangeUnchecked => [
        ("fx5-time-add/TADD/device-range/d=D7998", "D8000"),
        ("fx5-time-add/TADD/device-range/d=D7998", "SD0"),
    ];
    // A changed word: 11:30:30 + 15:39:39 is 3:10:09, whatever the order (s1), (s2) and (d) are read
    // and written in (TADD-OVERLAP); the copy makes (d) = (s1)+1 11:11:11 first, and the sum 2:50:50.
    tadd_s1_copied_into_d_first: TaddS1CopiedIntoDFirst => [
        ("fx5-time-add/TADD/overlap/d=s1+1", "D101"),
    ];
    // The output bit: D2 turns on when D1 reaches S1.
    hour_output_above_preset: HourOutputAbovePreset => [
        ("fc6a-hour-meter/HOUR/constant/one", "M10"),
    ];
    // A changed word: five 0.4 s scans make 2 s.
    hour_drops_fraction: HourDropsFraction => [
        ("fc6a-hour-meter/HOUR/subsecond/remainder-kept", "D202"),
    ];
    // A device that must stay unchanged: 'with the comparison output remaining on'.
    hour_wrap_clears_d2: HourWrapClearsD2 => [
        ("fc6a-hour-meter/HOUR/wrap/output-stays-on", "M10"),
    ];
    // A flag: a byte of S2 that is not BCD turns P_ER on, as one of S1 does.
    cp1e_s2_bcd_unchecked: Cp1eS2BcdUnchecked => [
        ("cp1e-time-compare/LD =DT/model/mask=all-but-day/ordering=lt/data=S2.hour.non-bcd/error-before=off", "P_ER"),
    ];
    // The contact result: AND with the preceding logic off is off.
    cp1e_and_as_or: Cp1eAndAsOr => [
        ("cp1e-time-compare/AND <=DT/logic/rlo-off/eq", "result"),
    ];
    // The flags: 'the result of a time comparison instruction is reflected in the arithmetic flags'.
    cp1e_flags_not_reflected: Cp1eFlagsNotReflected => [
        ("cp1e-time-compare/AND <=DT/logic/rlo-off/eq", "P_EQ"),
    ];
    // The error flag: 'Error Flag: ON if ... is not BCD' (no reading leaves it off on an error).
    cp1e_er_flag_not_set: Cp1eErFlagNotSet => [
        ("cp1e-time-compare/AND <=DT/logic/rlo-on/invalid-data", "P_ER"),
    ];
    // The error flag and the contact result: S1 at D8190 runs past D8191, an error (P_ER on, an OFF
    // execution condition); compared with D8192 read as 0, year 00 < 49 makes <>DT conduct.
    cp1e_past_area_compared: Cp1ePastAreaCompared => [
        ("cp1e-time-compare/AND <>DT/device-range/S1=D8190", "P_ER"),
        ("cp1e-time-compare/AND <>DT/device-range/S1=D8190", "result"),
    ];
}
