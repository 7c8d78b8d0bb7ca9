package org.plcvec.verify;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;

/** The results of a run, and the summary a person reads: every failing vector's diff, then totals. */
public final class Report {
    private final Verifier verifier;
    private final List<Result> results;
    private final double seconds;

    Report(Verifier verifier, List<Result> results, double seconds) {
        this.verifier = verifier;
        this.results = List.copyOf(results);
        this.seconds = seconds;
    }

    public List<Result> results() {
        return results;
    }

    public List<Result> failing() {
        return results.stream().filter(Result::failing).toList();
    }

    public Map<Status, Integer> counts() {
        Map<Status, Integer> counts = new EnumMap<>(Status.class);
        for (Status s : Status.values()) {
            counts.put(s, 0);
        }
        results.forEach(r -> counts.merge(r.status(), 1, Integer::sum));
        return counts;
    }

    /** Nothing failed, errored or is stale, and something was run (an all-skipped run proves nothing). */
    public boolean passed() {
        Map<Status, Integer> c = counts();
        return failing().isEmpty() && c.get(Status.PASS) + c.get(Status.XFAIL) > 0;
    }

    public double seconds() {
        return seconds;
    }

    /** What {@code plcvec verify} prints at the end of a run. */
    public String summary() {
        List<String> lines = new ArrayList<>();
        for (Result r : results) {
            if (r.failing()) {
                lines.add(r.report());
            }
        }
        Suite s = verifier.suite();
        Implementation impl = verifier.implementation();
        lines.add("");
        lines.add("plcvec verify: " + impl.name() + (impl.version().isEmpty() ? "" : " " + impl.version()) + " against "
                + s.source() + " (suite " + (s.suiteVersion().isEmpty() ? "?" : s.suiteVersion()) + ", schema "
                + s.schemaVersion() + ", spec sha256 " + s.specSha256().substring(0, Math.min(12, s.specSha256().length()))
                + ")");
        StringBuilder declared = new StringBuilder();
        verifier.followed().forEach((i, f) -> {
            if (f.declared()) {
                declared.append(i).append('=').append(f.alternative()).append(", ");
            }
        });
        lines.add("interpretations: " + (declared.length() > 0 ? declared.substring(0, declared.length() - 2) + "; " : "")
                + "others default");
        StringBuilder counts = new StringBuilder();
        counts().forEach((st, n) -> {
            if (n > 0 || st == Status.PASS || st == Status.FAIL) {
                counts.append(counts.length() == 0 ? "" : ", ").append(n).append(' ').append(st.label());
            }
        });
        lines.add(results.size() + " vectors: " + counts + String.format(" in %.2f s", seconds));
        if (!passed() && failing().isEmpty()) {
            lines.add("nothing was run: " + impl.name() + " skipped every selected vector");
        }
        return String.join("\n", lines) + "\n";
    }
}
