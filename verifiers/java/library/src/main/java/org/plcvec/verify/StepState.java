package org.plcvec.verify;

import java.util.Map;

/**
 * What a contract-level {@link Implementation} reports after one step: the contact result
 * ({@code null} for TADD/TADDP and HOUR) and the device image.
 */
public record StepState(Boolean result, DeviceImage devices) {
    /**
     * From a map of device name to value (Boolean for a bit, an integer 0..65535 for a word).
     *
     * @param result the contact result, or null for an instruction that is not a contact
     * @param devices the devices after the step
     * @return the state
     */
    public static StepState of(Boolean result, Map<String, ?> devices) {
        return new StepState(result, DeviceImage.of(devices));
    }
}
