package org.plcvec.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Map;
import java.util.function.BiPredicate;

import org.junit.jupiter.api.Test;
import org.plcvec.spec.Instruction.Condition;

class ContactTest {
    /** Each condition against Java's own comparison of two numbers below, equal to and above each other. */
    @Test
    void eachConditionHoldsForTheComparisonItNames() {
        Map<Condition, BiPredicate<Integer, Integer>> compare = Map.of(
                Condition.EQ, (a, b) -> a.intValue() == b.intValue(),
                Condition.NE, (a, b) -> a.intValue() != b.intValue(),
                Condition.LT, (a, b) -> a < b,
                Condition.LE, (a, b) -> a <= b,
                Condition.GT, (a, b) -> a > b,
                Condition.GE, (a, b) -> a >= b);
        assertEquals(Condition.values().length, compare.size());
        int[][] pairs = {{3, 7}, {7, 7}, {7, 3}, {0, 65535}, {65535, 0}};
        for (Map.Entry<Condition, BiPredicate<Integer, Integer>> e : compare.entrySet()) {
            for (int[] p : pairs) {
                assertEquals(e.getValue().test(p[0], p[1]), Contact.holds(e.getKey(), p[0] - p[1]),
                        e.getKey() + " for s1=" + p[0] + " s2=" + p[1]);
            }
        }
    }
}
