package org.plcvec.verify;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * The roll-up by reading (verifiers/parity/TEXT.md): after the failure blocks, the failing vectors
 * another reading explains, grouped by the smallest change that explains each, with the
 * declaration that gives the inferred choice; then the failures no reading explains, grouped by
 * the spec clauses they cite. Empty when no vector failed, errored or was not run.
 */
final class Rollup {
    private static final String INDENT = "    ";
    private static final String ID_INDENT = INDENT + "      " + "  ";   // under the count: 4 + 6 + 2
    private static final int SHOW_IDS = 5;

    private Rollup() {
    }

    static String text(List<Verdict> verdicts, Inference inference) {
        long failing = verdicts.stream().filter(Inference::failing).count();
        if (failing == 0) {
            return "";
        }
        StringBuilder out = new StringBuilder();
        if (!inference.explained.isEmpty()) {
            out.append("READINGS: ").append(inference.explained.size()).append(" of ").append(failing)
                    .append(" failing vectors pass under other alternatives:\n");
            Map<String, Integer> groups = new TreeMap<>();
            for (Map<String, String> change : inference.explained.values()) {
                groups.merge(joined(change), 1, Integer::sum);
            }
            counted(out, groups);
            List<String> declare = new ArrayList<>();
            inference.choice.forEach((i, a) -> {
                if (!a.equals(inference.followed.get(i))) {
                    declare.add("--choose " + i + "=" + a);
                }
            });
            out.append(INDENT).append("declare: ").append(String.join(" ", declare)).append('\n');
            if (!inference.broken.isEmpty()) {
                out.append(INDENT).append("(so declared, ").append(inference.broken.size())
                        .append(" vectors that pass now would fail)\n");
            }
        }
        if (!inference.unexplained.isEmpty()) {
            out.append("NOT EXPLAINED by any reading: ").append(inference.unexplained.size())
                    .append(" failing vectors, by the clauses they cite:\n");
            Map<String, List<String>> groups = new TreeMap<>();
            for (Verdict v : inference.unexplained) {
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
        return out.toString();
    }

    /** {@code ID=alternative, ...} in id order. */
    private static String joined(Map<String, String> change) {
        List<String> parts = new ArrayList<>();
        change.forEach((i, a) -> parts.add(i + "=" + a));
        return String.join(", ", parts);
    }

    /** A line per group, largest first, then by its text (TEXT.md's order, also the skips'). */
    static void counted(StringBuilder out, Map<String, Integer> groups) {
        List<Map.Entry<String, Integer>> sorted = new ArrayList<>(groups.entrySet());
        sorted.sort(Map.Entry.<String, Integer>comparingByValue().reversed().thenComparing(Map.Entry.comparingByKey()));
        sorted.forEach(e -> out.append(countLine(e.getValue(), e.getKey())));
    }

    /** {@code {n:>6}} under the four-space indent, then two spaces and the text. */
    static String countLine(int n, String text) {
        return INDENT + String.format(java.util.Locale.ROOT, "%6d", n) + "  " + text + "\n";
    }
}
