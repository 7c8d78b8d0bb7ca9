package org.plcvec.verify;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
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

    /**
     * Write the failing vectors of this run as a new expectations file, each with {@code reason}
     * (a starting list for adopting the suite, as {@code plcvec verify --write-expectations}
     * writes it). Written atomically: the file is whole or untouched. Returns the number of entries.
     */
    public int writeExpectations(Path file, String reason) {
        StringBuilder sb = new StringBuilder("# Known failures: each passing entry fails the run as stale, so fix and delete.\n\n");
        int n = 0;
        for (Result r : results.stream().sorted(java.util.Comparator.comparing(Result::id)).toList()) {
            if (r.vector() != null && (r.status() == Status.FAIL || r.status() == Status.ERROR || r.status() == Status.XFAIL)) {
                sb.append("[[").append(KnownFailures.SECTION).append("]]\nid = ").append(toml(r.id())).append("\nreason = ")
                        .append(toml(reason)).append("\n\n");
                n++;
            }
        }
        Path dir = file.toAbsolutePath().getParent();
        try {
            Path tmp = Files.createTempFile(dir, "." + file.getFileName(), ".tmp");
            try {
                Files.writeString(tmp, sb, StandardCharsets.UTF_8);
                Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            } finally {
                Files.deleteIfExists(tmp);
            }
        } catch (IOException e) {
            throw new VerifyException(file + ": cannot write the expectations file: " + e.getMessage(), e);
        }
        return n;
    }

    private static String toml(String s) {
        StringBuilder sb = new StringBuilder("\"");
        for (char c : s.toCharArray()) {
            if (c == '"' || c == '\\') {
                sb.append('\\').append(c);
            } else if (c < 0x20 || c == 0x7f) {
                sb.append(String.format("\\u%04X", (int) c));
            } else {
                sb.append(c);
            }
        }
        return sb.append('"').toString();
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
