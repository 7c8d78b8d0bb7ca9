package org.plcvec.verify;

import java.util.List;
import java.util.Set;

/**
 * An implementation under test, at the level of the contract (CONTRACT.md): one vector's initial
 * state and its steps' inputs in, and after each step the device image and, for contacts, the
 * result. Each call starts from the vector's own initial state: nothing carries over between
 * vectors.
 *
 * <p>An emulator that only wants to "execute this instruction on my memory" implements
 * {@link Emulator} instead, which does the bookkeeping.
 */
public interface Implementation {
    /**
     * The name reports show: by default the class's simple name; for a lambda (an {@link Emulator}
     * written as one), the class it is written in, since the lambda's own class name is made up
     * by the JVM anew in each run ({@code ClockTest$$Lambda$500/0x00007f45a00d8c88}).
     *
     * @return the name
     */
    default String name() {
        Class<?> c = getClass();
        if (c.isHidden() || c.isSynthetic()) {
            String name = c.getName();
            int lambda = name.indexOf("$$Lambda");
            String outer = lambda > 0 ? name.substring(0, lambda) : name;
            return outer.substring(outer.lastIndexOf('.') + 1);
        }
        String simple = c.getSimpleName();
        return simple.isEmpty() ? c.getName() : simple;   // an anonymous class has no simple name
    }

    /**
     * The implementation's version, for reports.
     *
     * @return the version, or "" for none
     */
    default String version() {
        return "";
    }

    /**
     * The interpretation alternatives this implementation follows; undeclared ones take the default.
     *
     * @return the declaration
     */
    default Choices choices() {
        return Choices.defaults();
    }

    /**
     * Whether it runs this instruction at all. Vectors of other instructions are skipped; a selection
     * in which nothing is supported fails.
     *
     * @param instruction as the vectors spell it ({@code LDTM<=}, {@code TADDP}, {@code LD <=DT})
     * @return true when supported
     */
    default boolean supports(String instruction) {
        return true;
    }

    /**
     * Devices the CPU writes on its own account (diagnostic relays and registers such as
     * {@code SM0}, {@code SM56}, {@code SD0}), by exact name. A write to one of them that the vector
     * does not list is not a write outside the vector; one the vector lists is compared as usual.
     *
     * @return the device names
     */
    default Set<String> cpuWrites() {
        return Set.of();
    }

    /**
     * Run every step of {@code vector} from its initial state and report the state after each.
     *
     * @param vector the vector, without its expectations
     * @return the state after each step, one per step
     * @throws Exception {@link SkipVector} to skip this vector, {@link VectorError} to report an error
     *         in the implementation's words; anything else is an error of this vector
     */
    List<StepState> run(VectorRequest vector) throws Exception;
}
