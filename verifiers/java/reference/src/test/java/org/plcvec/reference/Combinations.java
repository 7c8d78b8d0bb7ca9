package org.plcvec.reference;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

import org.plcvec.spec.Alternative;
import org.plcvec.spec.Family;
import org.plcvec.spec.Interpretation;
import org.plcvec.verify.Choices;
import org.plcvec.verify.OfferedChoices;
import org.plcvec.verify.Suite;
import org.plcvec.verify.Vector;

/**
 * The combinations of a family's alternatives the reference is run under, taken from the generated
 * names and the loaded suite (never a list typed here: an alternative the spec gains is run too).
 * Every one up to {@link #PRODUCT_BOUND} of them; past that (HOUR's eleven interpretations have
 * 34,560) a pairwise covering set and each combination some vector states an expectation under,
 * as the Python tests do. What the full product adds over that is an interaction of three or more
 * readings at once; each vector is still checked under each of its own.
 */
final class Combinations {
    /** The number of a family's combinations past which a pairwise covering set is run instead. */
    static final int PRODUCT_BOUND = 1024;

    private Combinations() {
    }

    /**
     * The combinations to run the reference under for {@code family}.
     *
     * @param suite the loaded vectors
     * @param family the family
     * @return each combination once, every interpretation of the family declared
     */
    static List<Choices> toRun(Suite suite, Family family) {
        List<Interpretation> interps = family.interpretations();
        long product = 1;
        for (Interpretation i : interps) {
            product *= i.alternatives().size();
        }
        if (product <= PRODUCT_BOUND) {
            return every(interps);
        }
        Set<Map<String, String>> seen = new LinkedHashSet<>();
        for (Choices c : pairwise(interps)) {
            seen.add(c.asMap());
        }
        for (Vector v : suite.vectors()) {
            if (v.familyName() == family) {
                for (Map<String, String> offered : OfferedChoices.of(v)) {
                    seen.add(complete(interps, offered));    // the others at their defaults
                }
            }
        }
        List<Choices> out = new ArrayList<>();
        for (Map<String, String> m : seen) {
            out.add(Choices.of(m));
        }
        return out;
    }

    /** {@code chosen} with every other interpretation of {@code interps} at its default. */
    private static Map<String, String> complete(List<Interpretation> interps, Map<String, String> chosen) {
        Map<String, String> m = new TreeMap<>();
        for (Interpretation i : interps) {
            m.put(i.id(), chosen.getOrDefault(i.id(), i.defaultAlternative().id()));
        }
        return m;
    }

    /**
     * Every choice of one alternative per interpretation (the product of their alternatives).
     *
     * @param interps the interpretations
     * @return the product, in the interpretations' and alternatives' order
     */
    static List<Choices> every(List<Interpretation> interps) {
        List<Choices> out = new ArrayList<>();
        out.add(Choices.defaults());
        for (Interpretation i : interps) {
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

    /** Two alternatives of two interpretations, by index ({@code a < b}). */
    private record Pair(int a, int altA, int b, int altB) {
        static Pair of(int i, int x, int j, int y) {
            return i < j ? new Pair(i, x, j, y) : new Pair(j, y, i, x);
        }
    }

    /**
     * A covering set of the interpretations' combinations: every alternative of each
     * interpretation beside every alternative of each other in some combination. Greedy and
     * deterministic: take the first pair not yet covered, then give every other interpretation, in
     * order, the alternative that covers the most pairs not yet covered with those already given
     * (the first on a tie).
     *
     * @param interps the interpretations
     * @return the combinations, every interpretation declared
     */
    static List<Choices> pairwise(List<Interpretation> interps) {
        Set<Pair> uncovered = new LinkedHashSet<>();
        for (int a = 0; a < interps.size(); a++) {
            for (int b = a + 1; b < interps.size(); b++) {
                for (int x = 0; x < interps.get(a).alternatives().size(); x++) {
                    for (int y = 0; y < interps.get(b).alternatives().size(); y++) {
                        uncovered.add(new Pair(a, x, b, y));
                    }
                }
            }
        }
        List<Choices> out = new ArrayList<>();
        for (Pair seed : List.copyOf(uncovered)) {
            if (!uncovered.contains(seed)) {
                continue;
            }
            int[] row = new int[interps.size()];
            Arrays.fill(row, -1);
            row[seed.a()] = seed.altA();
            row[seed.b()] = seed.altB();
            for (int i = 0; i < row.length; i++) {
                if (row[i] < 0) {
                    row[i] = bestAlternative(interps, row, i, uncovered);
                }
            }
            Map<String, String> combo = new LinkedHashMap<>();
            for (int i = 0; i < row.length; i++) {
                combo.put(interps.get(i).id(), interps.get(i).alternatives().get(row[i]).id());
                for (int j = i + 1; j < row.length; j++) {
                    uncovered.remove(new Pair(i, row[i], j, row[j]));
                }
            }
            out.add(Choices.of(combo));
        }
        return out;
    }

    /** The alternative of interpretation {@code i} covering the most uncovered pairs with {@code row}'s (-1: none yet). */
    private static int bestAlternative(List<Interpretation> interps, int[] row, int i, Set<Pair> uncovered) {
        int best = 0;
        int bestCount = -1;
        for (int x = 0; x < interps.get(i).alternatives().size(); x++) {
            int n = 0;
            for (int j = 0; j < row.length; j++) {
                if (j != i && row[j] >= 0 && uncovered.contains(Pair.of(i, x, j, row[j]))) {
                    n++;
                }
            }
            if (n > bestCount) {
                best = x;
                bestCount = n;
            }
        }
        return best;
    }
}
