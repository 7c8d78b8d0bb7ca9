package org.plcvec.reference;

import static org.plcvec.spec.Alternatives.Cp1eAllMasked;
import static org.plcvec.spec.Alternatives.Cp1eAndOrWhenOff;
import static org.plcvec.spec.Alternatives.Cp1eCHighBits;
import static org.plcvec.spec.Alternatives.Cp1eErFlag;
import static org.plcvec.spec.Alternatives.Cp1eErrorFlags;
import static org.plcvec.spec.Alternatives.Fx5InvalidS3DeviceRange;
import static org.plcvec.spec.Alternatives.Fx5OrOnError;
import static org.plcvec.spec.Alternatives.HourD1OutOfRange;
import static org.plcvec.spec.Alternatives.HourFirstScan;
import static org.plcvec.spec.Alternatives.HourM8004Off;
import static org.plcvec.spec.Alternatives.HourPresetCheck;
import static org.plcvec.spec.Alternatives.TaddErrorOrder;
import static org.plcvec.spec.Alternatives.Cp1eNonBcd;
import static org.plcvec.spec.Alternatives.Cp1eOutOfRange;
import static org.plcvec.spec.Alternatives.Cp1ePastAreaEnd;
import static org.plcvec.spec.Alternatives.Fx5AndOrWhenOff;
import static org.plcvec.spec.Alternatives.Fx5ClockS2DeviceRange;
import static org.plcvec.spec.Alternatives.Fx5Sm709Scope;
import static org.plcvec.spec.Alternatives.HourInputOff;
import static org.plcvec.spec.Alternatives.HourOutputOff;
import static org.plcvec.spec.Alternatives.HourPresetZero;
import static org.plcvec.spec.Alternatives.HourD2Special;
import static org.plcvec.spec.Alternatives.HourM8004Repeat;
import static org.plcvec.spec.Alternatives.HourS1ConstantRange;
import static org.plcvec.spec.Alternatives.HourWrapReach;
import static org.plcvec.spec.Alternatives.TaddExact24;
import static org.plcvec.spec.Alternatives.TaddFlagsOff;
import static org.plcvec.spec.Alternatives.TaddOnError;
import static org.plcvec.spec.Alternatives.TaddOverlap;

import org.plcvec.verify.Choices;

/**
 * The alternatives the reference follows, read once from the declared {@link Choices} (the
 * generated enums name them; a default is whatever the spec says it is).
 */
public final class Settings {
    // FX5 time/date comparison
    final Fx5Sm709Scope sm709Scope;
    final Fx5AndOrWhenOff fx5Logic;
    final boolean clockS2RangeChecked;
    final boolean fx5OrResultOffOnError;
    final boolean fx5InvalidS3First;
    // FX5 TADD
    final boolean taddFlagsSetOnly;
    final boolean taddCarryAbove24;
    final boolean taddComputedOnError;
    final boolean taddFieldRangeFirst;
    final TaddOverlap taddOverlap;
    // FC6A HOUR
    final boolean hourRecompared;
    final HourInputOff hourInputOff;
    final boolean hourZeroPresetNever;
    final HourFirstScan hourFirstScan;
    final boolean hourPresetEveryExecution;
    final boolean hourM8004OffWhenValid;
    final boolean hourM8004Once;
    final HourD1OutOfRange hourD1OutOfRange;
    final boolean hourWrapBeforeWrap;
    final HourD2Special hourD2Special;
    final HourS1ConstantRange hourS1ConstantRange;
    // CP1E
    final boolean cp1eNonBcdError;
    final boolean cp1eOutOfRangeError;
    final Cp1eAllMasked cp1eAllMasked;
    final boolean cp1eHighBitsError;
    final Cp1eAndOrWhenOff cp1eLogic;
    final boolean cp1eErHeld;
    final boolean cp1eErrorFlagsOff;
    final boolean cp1ePastAreaProgramError;

    /**
     * The alternatives of {@code c}, each resolved once.
     *
     * @param c the alternatives declared; undeclared ones take the default
     */
    public Settings(Choices c) {
        sm709Scope = follows(c, Fx5Sm709Scope.values());
        fx5Logic = follows(c, Fx5AndOrWhenOff.values());
        clockS2RangeChecked = c.follows(Fx5ClockS2DeviceRange.CHECKED);
        taddFlagsSetOnly = c.follows(TaddFlagsOff.SET_ONLY);
        taddCarryAbove24 = c.follows(TaddExact24.CARRY_ABOVE_24);
        taddComputedOnError = c.follows(TaddOnError.COMPUTED);
        hourRecompared = c.follows(HourOutputOff.RECOMPARED);
        hourInputOff = follows(c, HourInputOff.values());
        hourZeroPresetNever = c.follows(HourPresetZero.NEVER);
        cp1eNonBcdError = c.follows(Cp1eNonBcd.ERROR);
        cp1eOutOfRangeError = c.follows(Cp1eOutOfRange.ERROR);
        cp1eAllMasked = follows(c, Cp1eAllMasked.values());
        cp1eHighBitsError = c.follows(Cp1eCHighBits.ERROR);
        cp1eLogic = follows(c, Cp1eAndOrWhenOff.values());
        cp1eErHeld = c.follows(Cp1eErFlag.HELD);
        cp1eErrorFlagsOff = c.follows(Cp1eErrorFlags.OFF);
        fx5OrResultOffOnError = c.follows(Fx5OrOnError.RESULT_OFF);
        fx5InvalidS3First = c.follows(Fx5InvalidS3DeviceRange.S3_FIRST);
        cp1ePastAreaProgramError = c.follows(Cp1ePastAreaEnd.PROGRAM_ERROR);
        taddFieldRangeFirst = c.follows(TaddErrorOrder.FIELD_RANGE_FIRST);
        taddOverlap = follows(c, TaddOverlap.values());
        hourFirstScan = follows(c, HourFirstScan.values());
        hourPresetEveryExecution = c.follows(HourPresetCheck.EVERY_EXECUTION);
        hourM8004OffWhenValid = c.follows(HourM8004Off.VALID_PRESET);
        hourM8004Once = c.follows(HourM8004Repeat.ONCE);
        hourD1OutOfRange = follows(c, HourD1OutOfRange.values());
        hourWrapBeforeWrap = c.follows(HourWrapReach.BEFORE_WRAP);
        hourD2Special = follows(c, HourD2Special.values());
        hourS1ConstantRange = follows(c, HourS1ConstantRange.values());
    }

    private static <A extends org.plcvec.spec.Alternative> A follows(Choices c, A[] alternatives) {
        for (A a : alternatives) {
            if (c.follows(a)) {
                return a;
            }
        }
        throw new IllegalStateException("no alternative followed");
    }
}
