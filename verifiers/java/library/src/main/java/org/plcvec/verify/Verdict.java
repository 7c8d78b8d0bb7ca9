package org.plcvec.verify;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/** The verdict on one vector, with everything a person needs to read it. */
public final class Verdict {
    /** Field lines shown per failing vector in a report. */
    static final int SHOW_PROBLEMS = 12;

    private final String id;
    private final Vector vector;          // null for an expectations entry the suite does not have
    private Status status;
    private final List<Problem> problems;
    private String message;
    private final Map<String, String> judgedBy;
    private Throwable cause;              // what the implementation threw (ERROR), or null
    private Map<Integer, String[]> steps = Map.of();   // step -> its inputs and operands lines, for a FAIL
    // For the roll-up by reading (Inference): what a PASS or FAIL was judged against, and a FAIL's
    // answer (the state after each step as reported, or as the emulator's memory held it).
    private Expected expected;
    private List<StepState> answer;

    Verdict(String id, Vector vector, Status status, List<Problem> problems, String message, Map<String, String> judgedBy) {
        this.id = id;
        this.vector = vector;
        this.status = status;
        this.problems = List.copyOf(problems);
        this.message = message == null ? "" : message;
        this.judgedBy = judgedBy == null ? Map.of() : judgedBy;
    }

    /**
     * The vector's id (or the id an expectations file names).
     *
     * @return the id
     */
    public String id() {
        return id;
    }

    /**
     * The vector judged.
     *
     * @return the vector, or null for an expectations-file entry the suite does not have
     */
    public Vector vector() {
        return vector;
    }

    /**
     * The verdict.
     *
     * @return the status
     */
    public Status status() {
        return status;
    }

    /**
     * Whether this verdict fails the run.
     *
     * @return true for fail, error, stale and not-run
     */
    public boolean failing() {
        return status.failing();
    }

    /**
     * The fields that differ (for a failure).
     *
     * @return the problems, in the order of TEXT.md
     */
    public List<Problem> problems() {
        return problems;
    }

    /**
     * Why it errored, was skipped, is a known failure or is stale.
     *
     * @return the message, "" for none
     */
    public String message() {
        return message;
    }

    /**
     * The alternatives the vector was judged by (only those of the interpretations it depends on).
     *
     * @return interpretation to alternative
     */
    public Map<String, String> judgedBy() {
        return judgedBy;
    }

    /**
     * What the implementation threw.
     *
     * @return the exception of an {@link Status#ERROR} it caused, else null
     */
    public Throwable cause() {
        return cause;
    }

    /** The inputs and operands lines of each step with a problem (TEXT.md's failure block). */
    Verdict steps(Map<Integer, String[]> lines) {
        this.steps = lines;
        return this;
    }

    /** What the vector was judged against and, for a failure, the answer judged. */
    Verdict judged(Expected e, List<StepState> answer) {
        this.expected = e;
        this.answer = answer;
        return this;
    }

    Expected expected() {
        return expected;
    }

    /** The answer of a vector that failed (also once a known failure marked it XFAIL), else null. */
    List<StepState> answer() {
        return answer;
    }

    Verdict causedBy(Throwable t) {
        this.cause = t;
        return this;
    }

    void mark(Status status, String message) {
        this.status = status;
        this.message = message;
    }

    /**
     * The report block of this vector, as {@code plcvec verify} prints it:
     * <pre>
     * FAIL fx5-time-add/TADD/carry/exact-wrap/flags-off-before
     *     TADD: 23:59:59 + 00:00:01 ...
     *     judged by: TADD-EXACT-24=carry-at-24
     *     step 0 D300: expected 0, got 24 (before the step: 65535)
     *     spec clauses: fx5-time-add#sm700, ...
     * </pre>
     *
     * @return the block, without a final newline
     */
    public String report() {
        List<String> lines = new ArrayList<>();
        lines.add(status.label().toUpperCase(java.util.Locale.ROOT) + " " + id);
        if (vector != null && !vector.description().isEmpty()) {
            lines.add("    " + vector.instruction() + ": " + vector.description());
        }
        if (!judgedBy.isEmpty()) {
            StringBuilder sb = new StringBuilder();
            judgedBy.forEach((k, v) -> sb.append(sb.length() == 0 ? "" : ", ").append(k).append('=').append(v));
            lines.add("    judged by: " + sb);
        }
        if (expected != null) {
            expected.notJudgedLines().forEach(line -> lines.add("    " + line));
        }
        int shownStep = Integer.MIN_VALUE;
        for (Problem p : problems.subList(0, Math.min(problems.size(), SHOW_PROBLEMS))) {
            String[] context = steps.get(p.step());
            if (p.step() != shownStep && context != null) {
                lines.add("    step " + p.step() + " inputs: " + context[0]);
                lines.add("    step " + p.step() + " operands: " + context[1]);
            }
            shownStep = p.step();
            lines.add("    " + p.line());
        }
        if (problems.size() > SHOW_PROBLEMS) {
            lines.add("    ... and " + (problems.size() - SHOW_PROBLEMS) + " more differences");
        }
        if (!message.isEmpty()) {
            lines.add("    " + message);
        }
        if (vector != null && !vector.clauses().isEmpty()) {
            lines.add("    spec clauses: " + String.join(", ", vector.clauses()));
        }
        return String.join("\n", lines);
    }

    @Override
    public String toString() {
        return status.label() + " " + id;
    }
}
