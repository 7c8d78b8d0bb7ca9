package org.plcvec.verify;

import java.util.ArrayList;
import java.util.List;

/**
 * The thin helper: an emulator that executes one instruction on its memory. The verifier sets up a
 * {@link Memory} holding the vector's initial devices, applies each step's {@code set}, calls
 * {@link Scan#execute(Step)} once per step and compares the memory after it.
 *
 * <pre>{@code
 * Emulator mine = (vector, memory) -> {
 *     MyCpu cpu = new MyCpu(memory);                   // fresh per vector: TADDP's edge, HOUR's work area
 *     return step -> cpu.execute(vector.instruction(), vector.operands(), step);
 * };
 * }</pre>
 */
@FunctionalInterface
public interface Emulator extends Implementation {
    /** One execution (scan) of the vector's instruction; returns the contact result, or null for non-contacts. */
    @FunctionalInterface
    interface Scan {
        /**
         * One execution (scan) of the vector's instruction.
         *
         * @param step the step's inputs; its {@code set} is already applied to the memory
         * @return the contact result, or null for an instruction that is not a contact
         * @throws Exception anything the emulator throws: an error of that vector
         */
        Boolean execute(Step step) throws Exception;
    }

    /**
     * Ready a CPU for {@code vector} over {@code memory}, which holds the vector's initial devices.
     *
     * @param vector the vector, without its expectations
     * @param memory the device image the emulator reads and writes
     * @return what executes each step
     * @throws Exception anything the emulator throws: an error of that vector
     */
    Scan load(VectorRequest vector, Memory memory) throws Exception;

    @Override
    default List<StepState> run(VectorRequest vector) throws Exception {
        Memory memory = vector.newMemory();
        Scan scan = load(vector, memory);
        List<StepState> out = new ArrayList<>(vector.steps().size());
        for (Step step : vector.steps()) {
            step.applySet(memory);
            Boolean result = scan.execute(step);
            out.add(new StepState(result, memory.snapshot()));
        }
        return out;
    }
}
