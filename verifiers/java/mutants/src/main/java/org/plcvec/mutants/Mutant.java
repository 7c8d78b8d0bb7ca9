package org.plcvec.mutants;

import java.util.List;
import java.util.function.Function;

import org.plcvec.reference.Reference;
import org.plcvec.spec.Family;
import org.plcvec.verify.Choices;

/**
 * The reference with one plausible bug: its name, the families the bug is in, what the bug is
 * (against the manual's words), and how to build it for the declared alternatives.
 */
public record Mutant(String name, List<Family> families, String bug, Function<Choices, Reference> build) {
    /** The mutant following the defaults. */
    public Reference create() {
        return build.apply(Choices.defaults());
    }
}
