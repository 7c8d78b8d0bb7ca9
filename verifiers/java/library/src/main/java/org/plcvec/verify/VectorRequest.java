package org.plcvec.verify;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.plcvec.spec.Family;
import org.plcvec.spec.Instruction;

/**
 * What an implementation receives of a vector: everything needed to run it, no expectation
 * (the protocol's run request, CONTRACT.md "Setting up the initial state" and "Executing").
 */
public class VectorRequest {
    private final String id;
    private final String family;
    private final String instruction;
    private final DeviceSizes sizes;
    private final Map<String, Operand> operands;
    private final Set<String> scratch;
    private final List<Step> steps;
    // The device table: initial.devices first (listed), then any other device the vector names.
    final Address[] slots;
    final int[] initial;          // Values encoding; ABSENT where initial.devices has no entry
    final boolean[] compared;     // false for scratch
    final int listed;             // initial.devices.size()
    private final Family familyName;
    private final Instruction instructionName;
    // The operands again as arrays: a lookup by the manual's name is a few reference comparisons
    // (the names are interned here, like the string literals callers pass).
    private final String[] operandNames;
    private final Operand[] operandValues;

    VectorRequest(String id, String family, String instruction, DeviceSizes sizes, Map<String, Operand> operands,
                  Set<String> scratch, List<Step> steps, Address[] slots, int[] initial, boolean[] compared, int listed) {
        this.id = id;
        this.family = family;
        this.instruction = instruction;
        this.sizes = sizes;
        this.operands = Collections.unmodifiableMap(operands);
        this.scratch = Collections.unmodifiableSet(scratch);
        this.steps = List.copyOf(steps);
        this.slots = slots;
        this.initial = initial;
        this.compared = compared;
        this.listed = listed;
        this.familyName = Family.byId(family);
        this.instructionName = Instruction.byMnemonic(instruction);
        this.operandNames = operands.keySet().stream().map(String::intern).toArray(String[]::new);
        this.operandValues = operands.values().toArray(new Operand[0]);
    }

    VectorRequest(VectorRequest r) {
        this(r.id, r.family, r.instruction, r.sizes, r.operands, r.scratch, r.steps, r.slots, r.initial, r.compared,
                r.listed);
    }

    /**
     * The vector's stable id.
     *
     * @return {@code fx5-time-add/TADD/manual-example/program}
     */
    public String id() {
        return id;
    }

    /**
     * The family as the vectors spell it.
     *
     * @return {@code fx5-time-add}
     */
    public String family() {
        return family;
    }

    /**
     * The family by its generated name.
     *
     * @return the family, or null if this verifier's generated names do not know it (a newer suite)
     */
    public Family familyName() {
        return familyName;
    }

    /**
     * The instruction as the manual spells it.
     *
     * @return {@code LDTM<=}, {@code LD <=DT}, {@code TADDP}
     */
    public String instruction() {
        return instruction;
    }

    /**
     * The instruction by its generated name.
     *
     * @return the instruction, or null if this verifier's generated names do not know it
     */
    public Instruction instructionName() {
        return instructionName;
    }

    /**
     * {@code assumes.device_sizes}.
     *
     * @return the device sizes the vector assumes
     */
    public DeviceSizes deviceSizes() {
        return sizes;
    }

    /**
     * The instruction's operands.
     *
     * @return operand name as the manual names it to operand
     */
    public Map<String, Operand> operands() {
        return operands;
    }

    /**
     * The operand named {@code name} as the manual names it ({@code s1}, {@code D1}, {@code C}).
     *
     * @param name the operand's name
     * @return the operand
     * @throws IllegalStateException when the vector has no such operand
     */
    public Operand operand(String name) {
        String[] names = operandNames;
        for (int i = 0; i < names.length; i++) {
            if (names[i] == name) {
                return operandValues[i];
            }
        }
        for (int i = 0; i < names.length; i++) {
            if (names[i].equals(name)) {
                return operandValues[i];
            }
        }
        Operand o = operands.get(name);
        if (o == null) {
            throw new IllegalStateException("vector " + id + " has no operand " + name + " (has " + operands.keySet() + ")");
        }
        return o;
    }

    /**
     * Work-area words: the implementation's own, never compared.
     *
     * @return the device names
     */
    public Set<String> scratch() {
        return scratch;
    }

    /**
     * The executions, in order.
     *
     * @return the steps
     */
    public List<Step> steps() {
        return steps;
    }

    /**
     * {@code initial.devices}, JSON-ready.
     *
     * @return device name to value (words as Integer, bits as Boolean)
     */
    public Map<String, Object> initialDevices() {
        Map<String, Object> out = new LinkedHashMap<>();
        for (int i = 0; i < listed; i++) {
            out.put(slots[i].name(), Values.decode(initial[i]));
        }
        return out;
    }

    /**
     * A fresh device image holding {@code initial.devices}.
     *
     * @return the memory
     */
    public Memory newMemory() {
        return new Memory(sizes, slots, initial);
    }

    @Override
    public String toString() {
        return id;
    }
}
