package org.plcvec.verify;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.UnaryOperator;

/**
 * The {@code PLCVEC_*} environment variables every plcvec runner reads, with the same meaning and
 * the same errors as {@code plcvec verify} (CONTRACT.md): a CI matrix keyed on them works in every
 * language. A system property of the same name in lower case with dots
 * ({@code -Dplcvec.shard=2/4} for {@code PLCVEC_SHARD}, {@code -Dplcvec.known-failures=} for
 * {@code PLCVEC_KNOWN_FAILURES}) overrides the variable, for a build tool that passes properties
 * more easily than environment.
 *
 * <p>The selection variables narrow what the code selects, never widen it. A name the suite does
 * not have, an empty item ({@code PLCVEC_FAMILY=,}), an id glob that matches no id, a malformed
 * shard or timeout is a {@link VerifyException} that names the variable and its value.
 */
public final class Environment {
    public static final String VECTORS = "PLCVEC_VECTORS";
    public static final String ID = "PLCVEC_ID";
    public static final String FAMILY = "PLCVEC_FAMILY";
    public static final String INSTRUCTION = "PLCVEC_INSTRUCTION";
    public static final String TAG = "PLCVEC_TAG";
    public static final String INTERPRETATION = "PLCVEC_INTERPRETATION";
    public static final String SHARD = "PLCVEC_SHARD";
    public static final String KNOWN_FAILURES = "PLCVEC_KNOWN_FAILURES";
    public static final String WRITE_EXPECTATIONS = "PLCVEC_WRITE_EXPECTATIONS";
    public static final String TIMEOUT = "PLCVEC_TIMEOUT";

    /** The bound on one vector when {@code PLCVEC_TIMEOUT} is not set. */
    public static final Duration DEFAULT_TIMEOUT = Duration.ofSeconds(10);

    private final UnaryOperator<String> lookup;

    private Environment(UnaryOperator<String> lookup) {
        this.lookup = lookup;
    }

    /** This process's variables, each overridden by its system property. */
    public static Environment current() {
        return new Environment(name -> {
            String v = System.getProperty(property(name));
            return v != null ? v : System.getenv(name);
        });
    }

    /** Fixed values (for tests, or a runner that reads its settings elsewhere). */
    public static Environment of(Map<String, String> values) {
        Map<String, String> copy = Map.copyOf(values);
        return new Environment(copy::get);
    }

    /** The system property that overrides {@code variable}: {@code PLCVEC_KNOWN_FAILURES} → {@code plcvec.known-failures}. */
    public static String property(String variable) {
        return "plcvec." + variable.substring("PLCVEC_".length()).toLowerCase(Locale.ROOT).replace('_', '-');
    }

    /** The value, or null when unset or empty. */
    public String get(String variable) {
        String v = lookup.apply(variable);
        return v == null || v.isEmpty() ? null : v;
    }

    /** {@code selection} narrowed by the selection variables, each checked against {@code suite}. */
    public Selection narrow(Selection selection, Suite suite) {
        Selection p = Selection.all();
        String v;
        if ((v = get(FAMILY)) != null) {
            p = checked(FAMILY, v, Selection.all().families(items(FAMILY, v)), suite, p);
        }
        if ((v = get(INSTRUCTION)) != null) {
            p = checked(INSTRUCTION, v, Selection.all().instructions(items(INSTRUCTION, v)), suite, p);
        }
        if ((v = get(TAG)) != null) {
            p = checked(TAG, v, Selection.all().tags(items(TAG, v)), suite, p);
        }
        if ((v = get(ID)) != null) {
            p = checked(ID, v, Selection.all().ids(items(ID, v)), suite, p);
        }
        if ((v = get(INTERPRETATION)) != null) {
            p = checked(INTERPRETATION, v, Selection.all().interpretations(items(INTERPRETATION, v)), suite, p);
        }
        if ((v = get(SHARD)) != null) {
            try {
                p = p.and(Selection.all().shard(v));
            } catch (VerifyException e) {
                throw new VerifyException(SHARD + "=" + v + ": " + e.getMessage());
            }
        }
        return p == Selection.all() ? selection : selection.and(p);
    }

    private static Selection checked(String variable, String value, Selection one, Suite suite, Selection so) {
        try {
            one.check(suite);
        } catch (VerifyException e) {
            throw new VerifyException(variable + "=" + value + ": " + e.getMessage());
        }
        return so.and(one);
    }

    /** Comma-separated names; an empty one is a mistake (a stray comma), not "no filter". */
    private static String[] items(String variable, String value) {
        String[] parts = value.split(",", -1);
        List<String> out = new ArrayList<>();
        for (String part : parts) {
            String name = part.trim();
            if (name.isEmpty()) {
                throw new VerifyException(variable + "=" + value + ": an empty name in the comma-separated list");
            }
            out.add(name);
        }
        return out.toArray(String[]::new);
    }

    /** {@code PLCVEC_TIMEOUT}: seconds per vector, a positive number; 10 s when unset. */
    public Duration timeout() {
        String v = get(TIMEOUT);
        if (v == null) {
            return DEFAULT_TIMEOUT;
        }
        double seconds;
        try {
            seconds = Double.parseDouble(v.trim());
        } catch (NumberFormatException e) {
            seconds = Double.NaN;
        }
        if (!(seconds > 0) || Double.isInfinite(seconds)) {
            throw new VerifyException(TIMEOUT + "=" + v + ": takes the seconds one vector may take, a number above 0");
        }
        return Duration.ofNanos((long) Math.min(seconds * 1e9, Long.MAX_VALUE));
    }

    /** {@code PLCVEC_KNOWN_FAILURES}: the known-failures file, or null. */
    public Path knownFailures() {
        String v = get(KNOWN_FAILURES);
        return v == null ? null : Path.of(v);
    }

    /** {@code PLCVEC_WRITE_EXPECTATIONS}: where to write the run's failures, or null. */
    public Path writeExpectations() {
        String v = get(WRITE_EXPECTATIONS);
        return v == null ? null : Path.of(v);
    }

    /** {@code PLCVEC_VECTORS}: another copy of the vectors, or null for the one inside this jar. */
    public Path vectors() {
        String v = get(VECTORS);
        return v == null ? null : Path.of(v);
    }

    @Override
    public String toString() {
        List<String> set = new ArrayList<>();
        for (String name : Arrays.asList(VECTORS, ID, FAMILY, INSTRUCTION, TAG, INTERPRETATION, SHARD, KNOWN_FAILURES,
                WRITE_EXPECTATIONS, TIMEOUT)) {
            String v = get(name);
            if (v != null) {
                set.add(name + "=" + v);
            }
        }
        return String.join(" ", set);
    }
}
