package org.plcvec.reference;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicNode;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.plcvec.spec.Alternative;
import org.plcvec.spec.Family;
import org.plcvec.spec.Interpretation;
import org.plcvec.verify.Choices;
import org.plcvec.verify.PlcvecTests;
import org.plcvec.verify.Report;
import org.plcvec.verify.Selection;
import org.plcvec.verify.Suite;
import org.plcvec.verify.Verifier;

/** The reference passes every vector, under the defaults one test per vector, and under every combination of alternatives (or a covering set of them, {@link Combinations}). */
class ReferenceTest {
    @TestFactory
    Stream<DynamicNode> everyVectorUnderTheDefaults() {
        return PlcvecTests.of(new Reference()).stream();
    }

    /**
     * Every vector of every family under every combination of that family's alternatives up to
     * {@link Combinations#PRODUCT_BOUND} of them, past that a pairwise covering set and each
     * combination a vector states an expectation under.
     */
    @TestFactory
    Stream<DynamicTest> everyCombinationOfAlternatives() {
        Suite suite = Suite.golden();
        List<DynamicTest> tests = new ArrayList<>();
        for (Family family : Family.values()) {
            List<Choices> combinations = Combinations.toRun(suite, family);
            assertTrue(combinations.size() >= 2, family + ": expected the family to have interpretations");
            for (Choices choices : combinations) {
                tests.add(DynamicTest.dynamicTest(family.id() + " " + choices, () -> {
                    Report report = Verifier.of(new Reference(choices)).suite(suite)
                            .selection(Selection.all().families(family)).run();
                    assertTrue(report.passed(), report::summary);
                }));
            }
        }
        return tests.stream();
    }

    /** The set past the bound holds every pair of alternatives of two interpretations, and is far smaller than the product. */
    @Test
    void pairwiseCoversEveryPair() {
        List<Interpretation> interps = Family.FC6A_HOUR_METER.interpretations();
        List<Choices> rows = Combinations.pairwise(interps);
        for (Interpretation a : interps) {
            for (Interpretation b : interps) {
                for (Alternative x : a.alternatives()) {
                    for (Alternative y : b.alternatives()) {
                        assertTrue(a == b || rows.stream().anyMatch(r -> r.follows(x) && r.follows(y)),
                                "no combination has " + x + " with " + y);
                    }
                }
            }
        }
        assertTrue(rows.size() < 100, rows.size() + " rows");
        assertTrue(Combinations.every(interps).size() > Combinations.PRODUCT_BOUND, "HOUR no longer past the bound");
    }
}
