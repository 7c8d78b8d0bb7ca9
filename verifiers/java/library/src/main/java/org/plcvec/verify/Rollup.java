package org.plcvec.verify;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.function.Function;

import org.plcvec.spec.Alternative;
import org.plcvec.spec.Interpretation;

/**
 * The roll-up by reading (verifiers/parity/TEXT.md): after the failure blocks, the failing vectors
 * another reading explains, grouped by the smallest change that explains each, a group marked
 * partial where failures no reading explains share its families, with the declaration that gives
 * the inferred choice; then the failures no reading explains, grouped by the spec clauses they
 * cite; then the known failures another reading explains, and the declaration that replaces them.
 * Empty when no vector failed, errored, was not run or is a known failure.
 */
final class Rollup {
    private static final String INDENT = "    ";
    private static final String ID_INDENT = INDENT + "      " + "  ";   // under the count: 4 + 6 + 2
    private static final int SHOW_IDS = 5;

    private Rollup() {
    }

    /**
     * The roll-up of a run; {@code declaration} writes a choice as the runner's implementer declares
     * it, {@code knownFile} is the known-failures file as given.
     */
    static String text(List<Verdict> verdicts, Inference inference, Function<Map<String, String>, String> declaration,
                       String knownFile) {
        long failing = verdicts.stream().filter(Inference::failing).count();
        StringBuilder out = new StringBuilder();
        Map<String, Verdict> byId = new LinkedHashMap<>();
        verdicts.forEach(v -> byId.putIfAbsent(v.id(), v));
        Map<String, Integer> broken = new TreeMap<>();
        inference.broken.forEach(id -> broken.merge(family(byId.get(id)), 1, Integer::sum));
        if (!inference.explained.isEmpty()) {
            out.append("READINGS: ").append(inference.explained.size()).append(" of ").append(failing)
                    .append(" failing vectors pass under other alternatives:\n");
            boolean partial = groups(out, inference.explained, byId, families(inference.unexplained), broken);
            out.append(INDENT).append("declare: ").append(declaration.apply(changed(inference, inference.choice.keySet())))
                    .append('\n');
            if (!inference.broken.isEmpty()) {
                out.append(INDENT).append("(so declared, ").append(inference.broken.size())
                        .append(" vectors that pass now would fail)\n");
            }
            if (partial) {
                // Of the families of every explained vector, each vector counted once.
                Set<String> explainedFamilies = new TreeSet<>();
                inference.explained.keySet().forEach(id -> explainedFamilies.add(family(byId.get(id))));
                long p = inference.unexplained.stream().filter(v -> explainedFamilies.contains(family(v))).count();
                long q = inference.broken.stream().filter(id -> explainedFamilies.contains(family(byId.get(id)))).count();
                out.append(INDENT).append("partial: ").append(p).append(" vectors no reading explains and ").append(q)
                        .append(" vectors that pass now are of the same families; the declaration may hide part of a bug "
                                + "there\n");
            }
        }
        if (!inference.unexplained.isEmpty()) {
            unexplained(out, inference.unexplained);
        }
        if (!inference.explainedKnown.isEmpty()) {
            long known = verdicts.stream().filter(v -> v.status() == Status.XFAIL).count();
            out.append("KNOWN FAILURES: ").append(inference.explainedKnown.size()).append(" of ").append(known)
                    .append(" known failures pass under other alternatives:\n");
            List<Verdict> notExplained = new ArrayList<>(inference.unexplained);
            notExplained.addAll(inference.unexplainedKnown);
            groups(out, inference.explainedKnown, byId, families(notExplained), broken);
            Set<String> touched = new TreeSet<>();
            inference.explainedKnown.values().forEach(change -> touched.addAll(change.keySet()));
            out.append(INDENT).append("declare: ").append(declaration.apply(changed(inference, touched))).append('\n');
            out.append(INDENT).append("then remove those ").append(inference.explainedKnown.size())
                    .append(" known failures from ").append(knownFile).append('\n');
        }
        return out.toString();
    }

    /**
     * One line per group of explained vectors (their smallest change), largest first, each marked
     * partial when {@code unexplained} or {@code broken} (family to count) holds a family of the
     * group's vectors.
     *
     * @return whether some group is partial
     */
    private static boolean groups(StringBuilder out, Map<String, Map<String, String>> explained,
                                  Map<String, Verdict> byId, Map<String, Integer> unexplained, Map<String, Integer> broken) {
        Map<String, Set<String>> groups = new TreeMap<>();   // the change's text -> the families of its vectors
        Map<String, Integer> sizes = new TreeMap<>();
        explained.forEach((id, change) -> {
            String text = joined(change);
            sizes.merge(text, 1, Integer::sum);
            groups.computeIfAbsent(text, k -> new TreeSet<>()).add(family(byId.get(id)));
        });
        boolean partial = false;
        for (Map.Entry<String, Integer> group : sorted(sizes)) {
            List<String> shared = groups.get(group.getKey()).stream()
                    .filter(f -> unexplained.containsKey(f) || broken.containsKey(f)).toList();
            String line = group.getKey();
            if (!shared.isEmpty()) {
                int u = shared.stream().mapToInt(f -> unexplained.getOrDefault(f, 0)).sum();
                int w = shared.stream().mapToInt(f -> broken.getOrDefault(f, 0)).sum();
                line += " (partial: " + u + " not explained, " + w + " would fail, in " + String.join(", ", shared) + ")";
                partial = true;
            }
            out.append(countLine(group.getValue(), line));
        }
        return partial;
    }

    /** The failing vectors no reading explains, grouped by the clauses they cite. */
    private static void unexplained(StringBuilder out, List<Verdict> unexplained) {
        out.append("NOT EXPLAINED by any reading: ").append(unexplained.size())
                .append(" failing vectors, by the clauses they cite:\n");
        Map<String, List<String>> groups = new TreeMap<>();
        for (Verdict v : unexplained) {
            List<String> clauses = v.vector() == null ? List.of() : v.vector().clauses();
            groups.computeIfAbsent(clauses.isEmpty() ? "(no clauses)" : String.join(", ", clauses),
                    k -> new ArrayList<>()).add(v.id());
        }
        List<Map.Entry<String, List<String>>> sorted = new ArrayList<>(groups.entrySet());
        sorted.sort((a, b) -> a.getValue().size() != b.getValue().size()
                ? Integer.compare(b.getValue().size(), a.getValue().size()) : a.getKey().compareTo(b.getKey()));
        for (Map.Entry<String, List<String>> group : sorted) {
            List<String> ids = group.getValue().stream().sorted().toList();
            out.append(countLine(ids.size(), group.getKey()));
            ids.subList(0, Math.min(SHOW_IDS, ids.size())).forEach(id -> out.append(ID_INDENT).append(id).append('\n'));
            if (ids.size() > SHOW_IDS) {
                out.append(ID_INDENT).append("... and ").append(ids.size() - SHOW_IDS).append(" more\n");
            }
        }
    }

    /** Of {@code interpretations}, those whose inferred alternative differs from the followed one, with it. */
    private static Map<String, String> changed(Inference inference, Set<String> interpretations) {
        Map<String, String> out = new TreeMap<>();
        for (String i : interpretations) {
            String a = inference.choice.get(i);
            if (a != null && !a.equals(inference.followed.get(i))) {
                out.put(i, a);
            }
        }
        return out;
    }

    /** family -> how many of {@code verdicts} are of it. */
    private static Map<String, Integer> families(List<Verdict> verdicts) {
        Map<String, Integer> out = new TreeMap<>();
        verdicts.forEach(v -> out.merge(family(v), 1, Integer::sum));
        return out;
    }

    private static String family(Verdict v) {
        return v.vector() != null ? v.vector().family() : v.id().split("/", 2)[0];
    }

    /** {@code ID=alternative, ...} in id order. */
    private static String joined(Map<String, String> change) {
        List<String> parts = new ArrayList<>();
        change.forEach((i, a) -> parts.add(i + "=" + a));
        return String.join(", ", parts);
    }

    /** Groups largest first, then by their text (TEXT.md's order, also the skips'). */
    static List<Map.Entry<String, Integer>> sorted(Map<String, Integer> groups) {
        List<Map.Entry<String, Integer>> sorted = new ArrayList<>(groups.entrySet());
        sorted.sort(Map.Entry.<String, Integer>comparingByValue().reversed().thenComparing(Map.Entry.comparingByKey()));
        return sorted;
    }

    /** {@code {n:>6}} under the four-space indent, then two spaces and the text. */
    static String countLine(int n, String text) {
        return INDENT + String.format(java.util.Locale.ROOT, "%6d", n) + "  " + text + "\n";
    }

    /**
     * A choice as a Java implementer declares it (TEXT.md, "The declaration in each runner"):
     * {@code Choices.of(Alternatives.Fx5Sm709Scope.ALL_WORDS, ...)}, the generated names of each
     * alternative; an interpretation those names do not know (a newer suite) as the map form.
     */
    static String javaDeclaration(Map<String, String> choice) {
        List<String> names = new ArrayList<>();
        for (Map.Entry<String, String> e : new TreeMap<>(choice).entrySet()) {
            Interpretation i = Interpretation.byId(e.getKey());
            Alternative a = i == null ? null : i.alternative(e.getValue());
            if (!(a instanceof Enum<?>)) {
                List<String> entries = new ArrayList<>();
                new TreeMap<>(choice).forEach((k, v) -> entries.add("java.util.Map.entry(\"" + k + "\", \"" + v + "\")"));
                return "Choices.of(java.util.Map.ofEntries(" + String.join(", ", entries) + "))";
            }
            names.add("Alternatives." + ((Enum<?>) a).getDeclaringClass().getSimpleName() + "." + ((Enum<?>) a).name());
        }
        return "Choices.of(" + String.join(", ", names) + ")";
    }

    /** A choice as {@code plcvec verify} takes it, the form of the shared cases' expected text. */
    static String verifyDeclaration(Map<String, String> choice) {
        List<String> parts = new ArrayList<>();
        new TreeMap<>(choice).forEach((i, a) -> parts.add("--choose " + i + "=" + a));
        return String.join(" ", parts);
    }
}
