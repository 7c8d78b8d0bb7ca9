package org.plcvec.reference;

import static org.plcvec.spec.Alternatives.Cp1eAllMasked;
import static org.plcvec.spec.Alternatives.Cp1eAndOrWhenOff;
import static org.plcvec.spec.Alternatives.Cp1eCHighBits;
import static org.plcvec.spec.Alternatives.Cp1eErFlag;
import static org.plcvec.spec.Alternatives.Cp1eNonBcd;
import static org.plcvec.spec.Alternatives.Cp1eOutOfRange;
import static org.plcvec.spec.Alternatives.Fx5AndOrWhenOff;
import static org.plcvec.spec.Alternatives.Fx5ClockS2DeviceRange;
import static org.plcvec.spec.Alternatives.Fx5Sm709Scope;
import static org.plcvec.spec.Alternatives.HourInputOff;
import static org.plcvec.spec.Alternatives.HourOutputOff;
import static org.plcvec.spec.Alternatives.HourPresetZero;
import static org.plcvec.spec.Alternatives.TaddExact24;
import static org.plcvec.spec.Alternatives.TaddFlagsOff;
import static org.plcvec.spec.Alternatives.TaddOnError;

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
    // FX5 TADD
    final boolean taddFlagsSetOnly;
    final boolean taddCarryAbove24;
    final boolean taddComputedOnError;
    // FC6A HOUR
    final boolean hourRecompared;
    final HourInputOff hourInputOff;
    final boolean hourZeroPresetNever;
    // CP1E
    final boolean cp1eNonBcdError;
    final boolean cp1eOutOfRangeError;
    final Cp1eAllMasked cp1eAllMasked;
    final boolean cp1eHighBitsError;
    final Cp1eAndOrWhenOff cp1eLogic;
    final boolean cp1eErHeld;

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
