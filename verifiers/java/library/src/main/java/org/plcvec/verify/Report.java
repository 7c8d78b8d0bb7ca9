package org.plcvec.verify;

import java.nio.file.Path;
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
    /**
     * What a run was: the suite, the implementation, the alternatives it followed.
     *
     * @param suite the vectors the run judged by
     * @param implementation the implementation's name
     * @param version its version ("" when it gives none)
     * @param followed interpretation to the alternative followed, for the families run
     * @param cpuWrites the devices the implementation declares its CPU writes on its own account
     * @param knownFailures the known-failures file as the user gave it ("" for none)
     */
    public record Header(Suite suite, String implementation, String version, Map<String, Followed> followed,
                         java.util.Set<String> cpuWrites, String knownFailures) {
        /**
         * The same, copied: a header does not change with the maps it was made from.
         *
         * @param suite the vectors the run judged by
         * @param implementation the implementation's name
         * @param version its version ("" when it gives none)
         * @param followed interpretation to the alternative followed, for the families run
         * @param cpuWrites the devices the implementation declares its CPU writes on its own account
         * @param knownFailures the known-failures file as the user gave it ("" for none)
         */
        public Header {
            followed = Map.copyOf(new java.util.TreeMap<>(followed));
            cpuWrites = java.util.Set.copyOf(cpuWrites);
            knownFailures = knownFailures == null ? "" : knownFailures;
        }
    }

    private final Header header;
    private final List<Verdict> results;
    private final double seconds;
    private Inference inference;
    private final String aborted;
    /** How the roll-up's {@code declare:} lines are written: as this runner's implementer declares a choice. */
    private java.util.function.Function<Map<String, String>, String> declaration = Rollup::javaDeclaration;

    /**
     * A report of values: what a run was and its verdicts.
     *
     * @param header what the run was
     * @param verdicts every vector's verdict, in run order, then the stale known-failure ids
     * @param seconds how long the run took
     */
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

    /**
     * What the run was.
     *
     * @return the suite, the implementation and what it followed
     */
    public Header header() {
        return header;
    }

    /**
     * Every verdict of the run.
     *
     * @return the vectors' verdicts in run order, then the stale known-failure ids
     */
    public List<Verdict> verdicts() {
        return results;
    }

    /**
     * Every verdict of the run, under its name of 0.1.0.
     *
     * @return {@link #verdicts()}
     * @deprecated renamed {@link #verdicts()} (a verdict is a {@link Verdict}); removed in 0.3.0
     */
    @Deprecated(since = "0.2.0", forRemoval = true)
    public List<Verdict> results() {
        return verdicts();
    }

    /**
     * The verdicts that fail the run: failed, errored, not run, or a stale known failure.
     *
     * @return those verdicts, in run order
     */
    public List<Verdict> failing() {
        return results.stream().filter(Verdict::failing).toList();
    }

    /**
     * How many vectors got each status.
     *
     * @return every status, with 0 for those no vector got
     */
    public Map<Status, Integer> counts() {
        Map<Status, Integer> counts = new EnumMap<>(Status.class);
        for (Status s : Status.values()) {
            counts.put(s, 0);
        }
        results.forEach(r -> counts.merge(r.status(), 1, Integer::sum));
        return counts;
    }

    /**
     * Whether the run passed: nothing failed, errored, was not run or is stale, and at least one
     * vector passed. A run of skips and known failures alone proves nothing (CONTRACT.md: a list of
     * known failures on an implementation that fails them all is never green).
     *
     * @return true for a green run
     */
    public boolean passed() {
        return failing().isEmpty() && counts().get(Status.PASS) > 0;
    }

    /**
     * Why a run without failures still does not pass, as {@code plcvec verify}'s gate says it.
     *
     * @return {@code nothing passed (293 skipped): the run proves nothing}, or "" when the run
     *         failed or passed
     */
    public String shortfall() {
        if (!failing().isEmpty() || counts().get(Status.PASS) > 0) {
            return "";
        }
        List<String> others = new ArrayList<>();
        counts().forEach((status, n) -> {
            if (n > 0) {
                others.add(n + " " + (status == Status.SKIP ? "skipped" : status == Status.XFAIL ? "known failures"
                        : status.label()));
            }
        });
        return "nothing passed (" + String.join(", ", others) + "): the run proves nothing";
    }

    /**
     * How long the run took.
     *
     * @return seconds of wall-clock time
     */
    public double seconds() {
        return seconds;
    }

    /**
     * Write the failing vectors of this run as a new expectations file, each with {@code reason}
     * (a starting list for adopting the suite, as {@code plcvec verify --write-expectations}
     * writes it). Written atomically: the file is whole or untouched.
     *
     * @param file where to write it
     * @param reason the reason every entry gets
     * @return the number of entries written
     * @throws VerifyException when the file cannot be written, naming it
     */
    public int writeExpectations(Path file, String reason) {
        return KnownFailures.write(file, results, reason);
    }

    /**
     * What {@code plcvec verify} prints at the end of a run (verifiers/parity/TEXT.md, "The run's
     * text"): each failure's block, then {@link #totals()}.
     *
     * @return the text
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
     * clauses they cite; the known failures another reading explains), the skips by reason,
     * {@code ABORTED: <why>} when the run was stopped or {@code NOT PASSED: <why>} when nothing
     * passed, an empty line, then the summary lines (the suite and the implementation, every
     * alternative followed, the declared CPU writes, the totals).
     *
     * @return the text
     */
    public String totals() {
        StringBuilder out = new StringBuilder(rollup()).append(skipsByReason());
        if (aborted != null) {
            out.append("ABORTED: ").append(aborted).append('\n');
        } else if (!shortfall().isEmpty()) {
            out.append("NOT PASSED: ").append(shortfall()).append('\n');
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
            i = inference = Inference.of(header.suite().interpretations(), header.followed(), header.cpuWrites(), results);
        }
        return i;
    }

    /** The roll-up by reading (TEXT.md); "" when no vector failed, errored, was not run or is a known failure. */
    String rollup() {
        return results.stream().anyMatch(v -> Inference.failing(v) || v.status() == Status.XFAIL)
                ? Rollup.text(results, inference(), declaration, header.knownFailures()) : "";
    }

    /** This report with the roll-up's declarations written another way (the shared cases' {@code --choose}). */
    Report declaring(java.util.function.Function<Map<String, String>, String> declaration) {
        this.declaration = declaration;
        return this;
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
