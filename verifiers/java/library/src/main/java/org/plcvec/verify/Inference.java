package org.plcvec.verify;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;

/**
 * Which interpretation alternatives an implementation's answers follow, from the vectors and the
 * answers of one run alone (verifiers/parity/TEXT.md, "The inference"; the same procedure as
 * {@code plcvec verify --infer}, so every runner finds the same choice): the offered combinations
 * of each vector, the judged vectors and where each passes, the greedy choice, what it explains
 * and breaks, and each explained failure's smallest change.
 */
final class Inference {
    /**
     * One judged vector: the interpretations it touches (sorted by id) and the combinations of
     * their alternatives (in that order) under which its answer passes.
     */
    record Judged(Verdict verdict, List<String> touched, Set<List<String>> passing) {
        boolean passesUnder(Map<String, String> choice) {
            List<String> key = new ArrayList<>(touched.size());
            touched.forEach(i -> key.add(choice.get(i)));
            return passing.contains(key);
        }
    }

    /** interpretation -> the alternative the run followed (declared, else default), for every one. */
    final Map<String, String> followed;
    /** interpretation -> the alternative that explains the most judged vectors. */
    final Map<String, String> choice;
    /** failing vector id -> its smallest change (interpretation -> alternative, by id), in run order. */
    final Map<String, Map<String, String>> explained = new LinkedHashMap<>();
    /** The failing vectors no offered reading explains, in run order. */
    final List<Verdict> unexplained = new ArrayList<>();
    /** known failure (XFAIL) id -> its smallest change, for those the choice explains, in run order. */
    final Map<String, Map<String, String>> explainedKnown = new LinkedHashMap<>();
    /** The known failures the choice does not explain (their vector errored, or no reading passes it). */
    final List<Verdict> unexplainedKnown = new ArrayList<>();
    /** The ids of vectors that pass now and would fail under {@link #choice}. */
    final List<String> broken = new ArrayList<>();
    /** The number of judged vectors. */
    final int judged;

    private Inference(Map<String, String> followed, Map<String, String> choice, int judged) {
        this.followed = followed;
        this.choice = choice;
        this.judged = judged;
    }

    /** A failing vector of the roll-up: a failure, an error, or a vector not run. */
    static boolean failing(Verdict v) {
        return v.status() == Status.FAIL || v.status() == Status.ERROR || v.status() == Status.NOT_RUN;
    }

    /**
     * The inference over one run's verdicts: {@code known} every interpretation of the suite,
     * {@code run} the alternative followed for those of the families run (the only ones that move),
     * {@code cpuWrites} the devices the implementation declared.
     */
    static Inference of(Map<String, Suite.InterpretationInfo> known, Map<String, Followed> run, Set<String> cpuWrites,
                        List<Verdict> verdicts) {
        Map<String, String> defaults = new TreeMap<>();
        known.forEach((i, info) -> defaults.put(i, info.defaultAlternative()));
        Map<String, String> followed = new TreeMap<>(defaults);
        run.forEach((i, f) -> followed.put(i, f.alternative()));
        long[] keys = cpuWrites.stream().mapToLong(d -> Address.of(d).key()).toArray();

        List<Judged> judged = judgeAll(verdicts, followed, defaults, keys);
        // Twice: first without the readings that leave devices unjudged, which explain any answer
        // there, so that they take only what no reading that judges explains (TEXT.md, step 4).
        Set<String> leaving = leavingUnjudged(verdicts);
        Map<String, String> choice = choose(judged, followed, run.keySet(), known, leaving);
        choice = choose(judged, choice, run.keySet(), known, Set.of());
        Inference out = new Inference(followed, choice, judged.size());
        out.explain(verdicts, judged);
        return out;
    }

    /**
     * Step 4, the choice: from the followed alternatives, each interpretation of the families run
     * in id order moved to the first of its alternatives that passes strictly more of the judged
     * vectors that touch it, in rounds until a round changes nothing.
     */
    private static Map<String, String> choose(List<Judged> judged, Map<String, String> followed, Set<String> run,
                                              Map<String, Suite.InterpretationInfo> known, Set<String> barred) {
        Map<String, List<Judged>> byInterpretation = new TreeMap<>();
        for (Judged j : judged) {
            j.touched().forEach(i -> byInterpretation.computeIfAbsent(i, k -> new ArrayList<>()).add(j));
        }
        Map<String, String> choice = new TreeMap<>(followed);
        boolean changed = true;
        while (changed) {
            changed = false;
            for (String interpretation : new TreeSet<>(run)) {
                List<Judged> touching = byInterpretation.get(interpretation);
                if (touching == null) {
                    continue;
                }
                String best = choice.get(interpretation);
                int bestScore = score(touching, choice);
                for (String alternative : known.get(interpretation).alternatives()) {
                    if (alternative.equals(choice.get(interpretation)) || barred.contains(interpretation + "=" + alternative)) {
                        continue;
                    }
                    Map<String, String> trial = new TreeMap<>(choice);
                    trial.put(interpretation, alternative);
                    int s = score(touching, trial);
                    if (s > bestScore) {     // strictly more: the first of the best, a tie keeps the current
                        best = alternative;
                        bestScore = s;
                    }
                }
                if (!best.equals(choice.get(interpretation))) {
                    choice.put(interpretation, best);
                    changed = true;
                }
            }
        }
        return choice;
    }

    /** {@code ID=alternative} of every alternative some vector's entry names in its {@code unjudged} map. */
    private static Set<String> leavingUnjudged(List<Verdict> verdicts) {
        Set<String> out = new HashSet<>();
        for (Verdict v : verdicts) {
            if (v.vector() != null) {
                for (Vector.Variant variant : v.vector().variants()) {
                    variant.unjudged().keySet().forEach(i -> out.add(i + "=" + variant.choices().get(i)));
                }
            }
        }
        return out;
    }

    /**
     * Steps 5 and 6: which failing vectors and known failures the choice explains (each with its
     * smallest change), which it does not, and which passing vectors it would break.
     */
    private void explain(List<Verdict> verdicts, List<Judged> judged) {
        Map<String, Judged> byId = new java.util.HashMap<>();
        judged.forEach(j -> byId.put(j.verdict().id(), j));
        for (Verdict v : verdicts) {
            boolean known = v.status() == Status.XFAIL;
            if (!failing(v) && !known) {
                continue;
            }
            Judged j = byId.get(v.id());
            if (j == null || !j.passesUnder(choice)) {
                (known ? unexplainedKnown : unexplained).add(v);
            } else {
                (known ? explainedKnown : explained).put(v.id(), smallestChange(j, followed, choice));
            }
        }
        for (Judged j : judged) {
            if (j.verdict().status() == Status.PASS && !j.passesUnder(choice)) {
                broken.add(j.verdict().id());
            }
        }
    }

    private static int score(List<Judged> vectors, Map<String, String> choice) {
        int n = 0;
        for (Judged j : vectors) {
            n += j.passesUnder(choice) ? 1 : 0;
        }
        return n;
    }

    /**
     * Every vector with an answer (passed, failed, or a failure the expectations file lists), with
     * the offered combinations under which that answer passes.
     */
    private static List<Judged> judgeAll(List<Verdict> verdicts, Map<String, String> followed,
                                         Map<String, String> defaults, long[] cpuWrites) {
        // An interpretation no failing vector touches can gain nothing, so the choice never moves it:
        // a passing vector that touches only such ones needs no expectation under other alternatives.
        Set<String> movable = new HashSet<>();
        for (Verdict v : verdicts) {
            if (answered(v) && v.status() != Status.PASS) {
                movable.addAll(v.vector().interpretations());
            }
        }
        List<Judged> out = new ArrayList<>();
        for (Verdict v : verdicts) {
            if (!answered(v)) {
                continue;
            }
            boolean passed = v.status() == Status.PASS;
            List<String> touched = v.vector().interpretations().stream().sorted().toList();
            Set<List<String>> passing = new HashSet<>();
            if (touched.isEmpty()) {
                if (passed) {
                    passing.add(List.of());
                }
            } else if (passed && touched.stream().noneMatch(movable::contains)) {
                passing.add(touched.stream().map(followed::get).toList());
            } else {
                for (Map<String, String> combination : Expected.offered(v.vector(), defaults)) {
                    Expected under;
                    try {
                        under = Expected.of(v.vector(), combination, defaults).cpuWrites(cpuWrites);
                    } catch (VerifyException inconsistent) {   // an entry whose steps do not add up passes nothing
                        continue;
                    }
                    if (passed ? under.passesWherePasses(v.expected()) : Compare.accepts(under, v.answer())) {
                        passing.add(touched.stream().map(combination::get).toList());
                    }
                }
            }
            out.add(new Judged(v, touched, passing));
        }
        return out;
    }

    /** A pass, or a failure (XFAIL too: a known failure that failed) whose answer was kept. */
    private static boolean answered(Verdict v) {
        if (v.vector() == null || v.expected() == null) {
            return false;
        }
        return v.status() == Status.PASS
                || ((v.status() == Status.FAIL || v.status() == Status.XFAIL) && v.answer() != null);
    }

    /**
     * The fewest interpretations (the first in id order among as few, as itertools.combinations
     * gives the subsets) whose change from the followed alternative to the chosen one makes the
     * failing vector pass: what explains it.
     */
    static Map<String, String> smallestChange(Judged j, Map<String, String> followed, Map<String, String> choice) {
        List<String> flipped = j.touched().stream().filter(i -> !choice.get(i).equals(followed.get(i))).toList();
        for (int size = 1; size <= flipped.size(); size++) {
            for (List<String> subset : combinations(flipped, size)) {
                Map<String, String> trial = new TreeMap<>(followed);
                subset.forEach(i -> trial.put(i, choice.get(i)));
                if (j.passesUnder(trial)) {
                    return change(subset, choice);
                }
            }
        }
        return change(flipped, choice);
    }

    private static Map<String, String> change(List<String> interpretations, Map<String, String> choice) {
        Map<String, String> out = new TreeMap<>();
        interpretations.forEach(i -> out.put(i, choice.get(i)));
        return out;
    }

    /** The subsets of {@code items} of {@code size}, in lexicographic order of positions. */
    static List<List<String>> combinations(List<String> items, int size) {
        List<List<String>> out = new ArrayList<>();
        if (size == 0) {
            out.add(List.of());
            return out;
        }
        for (int first = 0; first <= items.size() - size; first++) {
            for (List<String> rest : combinations(items.subList(first + 1, items.size()), size - 1)) {
                List<String> subset = new ArrayList<>(size);
                subset.add(items.get(first));
                subset.addAll(rest);
                out.add(subset);
            }
        }
        return out;
    }
}
