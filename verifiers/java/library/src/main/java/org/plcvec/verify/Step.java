package org.plcvec.verify;

import java.util.Collections;
import java.util.Map;

/**
 * The inputs of one execution (scan): the values the outside world writes first ({@code set}),
 * then the instruction's inputs (CONTRACT.md, "Executing").
 */
public final class Step {
    private final int index;
    private final Address[] setDevices;
    private final int[] setValues;
    private final Boolean rloIn;
    private final Map<String, Integer> clock;
    private final Boolean en;
    private final Boolean input;
    private final Long elapsedMs;

    Step(int index, Address[] setDevices, int[] setValues, Boolean rloIn, Map<String, Integer> clock,
         Boolean en, Boolean input, Long elapsedMs) {
        this.index = index;
        this.setDevices = setDevices;
        this.setValues = setValues;
        this.rloIn = rloIn;
        this.clock = clock == null ? null : Collections.unmodifiableMap(clock);
        this.en = en;
        this.input = input;
        this.elapsedMs = elapsedMs;
    }

    /**
     * The step's place in the vector.
     *
     * @return 0 for the first step
     */
    public int index() {
        return index;
    }

    /**
     * Apply {@code set} (values written by the program or an HMI before the execution).
     *
     * @param memory the device image to write them to
     */
    public void applySet(Memory memory) {
        for (int i = 0; i < setDevices.length; i++) {
            memory.setRaw(setDevices[i], setValues[i]);
        }
    }

    /**
     * {@code set} as JSON-ready values.
     *
     * @return device name to value, empty when the step sets nothing
     */
    public Map<String, Object> set() {
        Map<String, Object> out = new java.util.LinkedHashMap<>();
        for (int i = 0; i < setDevices.length; i++) {
            out.put(setDevices[i].name(), Values.decode(setValues[i]));
        }
        return out;
    }

    /**
     * Whether the step gives the logic state before an AND/OR form.
     *
     * @return true for an AND or OR form's step
     */
    public boolean hasRloIn() {
        return rloIn != null;
    }

    /**
     * The logic state before an AND/OR form.
     *
     * @return the preceding logic
     * @throws IllegalStateException when the step has none (an LD form)
     */
    public boolean rloIn() {
        return require(rloIn, "rlo_in");
    }

    /**
     * The injected clock (only the fields the family compares: hour/minute/second or year/month/day).
     *
     * @return field to value, or null
     */
    public Map<String, Integer> clock() {
        return clock;
    }

    /**
     * One field of the injected clock.
     *
     * @param field {@code hour}, {@code day}, ...
     * @return its value
     * @throws IllegalStateException when the step has no such field
     */
    public int clock(String field) {
        Integer v = clock == null ? null : clock.get(field);
        if (v == null) {
            throw new IllegalStateException("step " + index + " has no clock." + field);
        }
        return v;
    }

    /**
     * The execution condition of TADD/TADDP.
     *
     * @return EN
     * @throws IllegalStateException when the step has none
     */
    public boolean en() {
        return require(en, "en");
    }

    /**
     * Whether the step gives an execution condition (TADD/TADDP).
     *
     * @return true when it does
     */
    public boolean hasEn() {
        return en != null;
    }

    /**
     * The HOUR input this scan.
     *
     * @return whether the input is on
     * @throws IllegalStateException when the step has none
     */
    public boolean input() {
        return require(input, "input");
    }

    /**
     * Milliseconds since the previous execution, all ON time when the input is on.
     *
     * @return the milliseconds
     * @throws IllegalStateException when the step has none
     */
    public long elapsedMs() {
        if (elapsedMs == null) {
            throw new IllegalStateException("step " + index + " has no elapsed_ms");
        }
        return elapsedMs;
    }

    private boolean require(Boolean value, String name) {
        if (value == null) {
            throw new IllegalStateException("step " + index + " has no " + name);
        }
        return value;
    }

    /**
     * The inputs as the protocol sends them (for a stdio adapter written on top of this library).
     *
     * @return input name to value
     */
    public Map<String, Object> toMap() {
        Map<String, Object> out = new java.util.LinkedHashMap<>();
        if (setDevices.length > 0) {
            out.put("set", set());
        }
        if (rloIn != null) {
            out.put("rlo_in", rloIn);
        }
        if (clock != null) {
            out.put("clock", clock);
        }
        if (en != null) {
            out.put("en", en);
        }
        if (input != null) {
            out.put("input", input);
        }
        if (elapsedMs != null) {
            out.put("elapsed_ms", elapsedMs);
        }
        return out;
    }
}
