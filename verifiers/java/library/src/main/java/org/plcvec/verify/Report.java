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

/**
 * The verdicts of a run, and the summary a person reads: every failing vector's diff, then what
 * the run followed, the skips by reason and the totals. Built from values (the run's header and
 * its verdicts), so it can be made by any runner of the suite, JUnit's included.
 */
public final class Report {
    /** What a run was: the suite, the implementation, the alternatives it followed. */
    public record Header(Suite suite, String implementation, String version, Map<String, Followed> followed,
                         java.util.Set<String> cpuWrites) {
        public Header {
            followed = Map.copyOf(new java.util.TreeMap<>(followed));
            cpuWrites = java.util.Set.copyOf(cpuWrites);
        }
    }

    private final Header header;
    private final List<Verdict> results;
    private final double seconds;
    private Inference inference;
    private final String aborted;

    public Report(Header header, List<Verdict> verdicts, double seconds) {
        this(header, verdicts, seconds, null);
    }

    /** {@code aborted}: why the run was stopped before its end (its text's {@code ABORTED:} line), or null. */
    Report(Header header, List<Verdict> verdicts, double seconds, String aborted) {
        this.header = header;
        this.results = List.copyOf(verdicts);
        this.seconds = seconds;
        this.aborted = aborted;
    }

    public Header header() {
        return header;
    }

    public List<Verdict> verdicts() {
        return results;
    }

    public List<Verdict> failing() {
        return results.stream().filter(Verdict::failing).toList();
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
        for (Verdict r : results.stream().sorted(java.util.Comparator.comparing(Verdict::id)).toList()) {
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

    /**
     * What {@code plcvec verify} prints at the end of a run (verifiers/parity/TEXT.md, "The run's
     * text"): each failure's block, then {@link #totals()}.
     */
    public String summary() {
        StringBuilder sb = new StringBuilder();
        for (Verdict r : results) {
            if (r.failing()) {
                sb.append(r.report()).append('\n');
            }
        }
        return sb.append(totals()).toString();
    }

    /**
     * The end of a run without the failure blocks (a test runner has shown each already), as
     * verifiers/parity/TEXT.md writes it: the roll-up by reading (the failures another
     * alternative explains, and the declaration that gives it; those no reading explains, by the
     * clauses they cite), the skips by reason, {@code ABORTED: <why>} when the run was stopped, an
     * empty line, then the summary lines (the suite
     * and the implementation, every alternative followed, the declared CPU writes, the totals).
     */
    public String totals() {
        StringBuilder out = new StringBuilder(rollup()).append(skipsByReason());
        if (aborted != null) {
            out.append("ABORTED: ").append(aborted).append('\n');
        }
        out.append('\n');
        Suite s = header.suite();
        out.append("plcvec verify: ").append(header.implementation())
                .append(header.version().isEmpty() ? "" : " " + header.version()).append(" against ").append(s.source())
                .append(" (suite ").append(s.suiteVersion().isEmpty() ? "?" : s.suiteVersion()).append(", schema ")
                .append(s.schemaVersion()).append(", spec sha256 ")
                .append(s.specSha256(), 0, Math.min(12, s.specSha256().length())).append(")\n");
        out.append(summaryLines());
        out.append(String.format(java.util.Locale.ROOT, " in %.2f s", seconds)).append('\n');
        return out.toString();
    }

    /** The inference over this run's answers (computed once, and only when something failed). */
    Inference inference() {
        Inference i = inference;
        if (i == null) {
            i = inference = Inference.of(header, results);
        }
        return i;
    }

    /** The roll-up by reading (TEXT.md); "" when no vector failed or errored. */
    String rollup() {
        return results.stream().anyMatch(Inference::failing) ? Rollup.text(results, inference()) : "";
    }

    /** {@code SKIPPED s of n vectors (p%):} and a line per reason, most vectors first (TEXT.md); "" without skips. */
    String skipsByReason() {
        Map<String, Integer> reasons = new java.util.HashMap<>();
        int selected = 0;
        for (Verdict r : results) {
            if (r.vector() != null) {
                selected++;
            }
            if (r.status() == Status.SKIP) {
                reasons.merge(r.message().isEmpty() ? "(no reason given)" : r.message(), 1, Integer::sum);
            }
        }
        if (reasons.isEmpty()) {
            return "";
        }
        int skipped = reasons.values().stream().mapToInt(Integer::intValue).sum();
        long t = (2000L * skipped + selected) / (2L * selected);    // s/n in tenths of a percent, half up
        StringBuilder out = new StringBuilder("SKIPPED " + skipped + " of " + selected + " vectors (" + t / 10 + "." + t % 10
                + "%):\n");
        List<Map.Entry<String, Integer>> sorted = new ArrayList<>(reasons.entrySet());
        sorted.sort(Map.Entry.<String, Integer>comparingByValue().reversed().thenComparing(Map.Entry.comparingByKey()));
        for (Map.Entry<String, Integer> e : sorted.subList(0, Math.min(12, sorted.size()))) {
            out.append(Rollup.countLine(e.getValue(), e.getKey()));
        }
        if (sorted.size() > 12) {
            out.append("    ... and ").append(sorted.size() - 12).append(" more reasons (--jsonl lists each vector)\n");
        }
        return out.toString();
    }

    /** The summary lines after the header line, the totals without their time (TEXT.md). */
    String summaryLines() {
        StringBuilder out = new StringBuilder();
        List<String> followed = new ArrayList<>();
        new java.util.TreeMap<>(header.followed()).forEach((i, f) -> followed.add(i + "=" + f.alternative()
                + (f.declared() ? " (declared)" : " (default)")));
        out.append("interpretations: ").append(followed.isEmpty() ? "(none)" : String.join(", ", followed)).append('\n');
        if (!header.cpuWrites().isEmpty()) {
            out.append("cpu_writes: ").append(String.join(", ", new java.util.TreeSet<>(header.cpuWrites()))).append('\n');
        }
        StringBuilder counts = new StringBuilder();
        counts().forEach((st, n) -> {
            if (n > 0 || st == Status.PASS || st == Status.FAIL || st == Status.SKIP) {
                counts.append(counts.length() == 0 ? "" : ", ").append(n).append(' ').append(st.label());
            }
        });
        return out.append(results.size()).append(" vectors: ").append(counts).toString();
    }
}
