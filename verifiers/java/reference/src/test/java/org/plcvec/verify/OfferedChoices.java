package org.plcvec.verify;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * For the reference's every-combination test ({@code org.plcvec.reference.Combinations}): the
 * combinations of alternatives a vector states an expectation under (its {@code alternatives}
 * entries), each naming only the interpretations it holds for. Kept with the tests, in the
 * library's package, because a vector's expectations are not public API.
 */
public final class OfferedChoices {
    private OfferedChoices() {
    }

    /**
     * The choices of each of {@code v}'s alternatives entries, in the vector's order.
     *
     * @param v a vector
     * @return interpretation id to alternative id, one map per entry (empty for most vectors)
     */
    public static List<Map<String, String>> of(Vector v) {
        List<Map<String, String>> out = new ArrayList<>();
        for (Vector.Variant variant : v.variants()) {
            out.add(variant.choices());
        }
        return out;
    }
}
