package org.plcvec.reference;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicNode;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;
import org.plcvec.spec.Alternative;
import org.plcvec.spec.Family;
import org.plcvec.spec.Interpretation;
import org.plcvec.verify.Choices;
import org.plcvec.verify.PlcvecTests;
import org.plcvec.verify.Report;
import org.plcvec.verify.Selection;
import org.plcvec.verify.Verifier;

/** The reference passes every vector, under the defaults one test per vector, and under every combination of alternatives. */
class ReferenceTest {
    @TestFactory
    Stream<DynamicNode> everyVectorUnderTheDefaults() {
        return PlcvecTests.of(new Reference()).stream();
    }

    @TestFactory
    Stream<DynamicTest> everyCombinationOfAlternatives() {
        List<DynamicTest> tests = new ArrayList<>();
        for (Family family : Family.values()) {
            for (Choices choices : combinations(family.interpretations())) {
                tests.add(DynamicTest.dynamicTest(family.id() + " " + choices, () -> {
                    Report report = Verifier.of(new Reference(choices)).selection(Selection.all().families(family)).run();
                    assertTrue(report.passed(), report::summary);
                }));
            }
        }
        return tests.stream();
    }

    /** Every choice of one alternative per interpretation (the product of their alternatives). */
    static List<Choices> combinations(List<Interpretation> interpretations) {
        List<Choices> out = new ArrayList<>();
        out.add(Choices.defaults());
        for (Interpretation i : interpretations) {
            List<Choices> next = new ArrayList<>();
            for (Choices c : out) {
                for (Alternative a : i.alternatives()) {
                    next.add(c.with(a));
                }
            }
            out = next;
        }
        return out;
    }
}
