package org.plcvec.verify;

import java.math.BigDecimal;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.UnaryOperator;
import java.util.regex.Pattern;

/**
 * The {@code PLCVEC_*} environment variables every plcvec runner reads, with the same meaning and
 * the same errors as {@code plcvec verify} (CONTRACT.md, "The environment"): a CI matrix keyed on
 * them works in every language. A system property of the same name in lower case with dots
 * ({@code -Dplcvec.shard=2/4} for {@code PLCVEC_SHARD}, {@code -Dplcvec.known-failures=} for
 * {@code PLCVEC_KNOWN_FAILURES}) overrides the variable, for a build tool that passes properties
 * more easily than environment; a property set to nothing ({@code -Dplcvec.id=}) unsets its variable.
 *
 * <p>The selection variables narrow what the code selects, never widen it. A name the suite does
 * not have, an empty item ({@code PLCVEC_FAMILY=,}), an id glob that matches no id, a malformed
 * shard or timeout is a {@link VerifyException} that names the variable and its value.
 *
 * <p>A renamed setting is still read under its old name ({@code PLCVEC_EXPECTATIONS} as
 * {@code PLCVEC_KNOWN_FAILURES}, until plcvec 0.3.0), and a {@code PLCVEC_*} variable that is no
 * setting is taken for a misspelling: {@link #warnings()} says so in the words of every runner, and
 * each run prints them once on standard error.
 */
public final class Environment {
    /** Another copy of the vectors (a folder or one family file). */
    public static final String VECTORS = "PLCVEC_VECTORS";
    /** Exact ids or globs on the whole id, comma-separated. */
    public static final String ID = "PLCVEC_ID";
    /** Family names, comma-separated. */
    public static final String FAMILY = "PLCVEC_FAMILY";
    /** Instruction names, comma-separated. */
    public static final String INSTRUCTION = "PLCVEC_INSTRUCTION";
    /** Tag names, comma-separated. */
    public static final String TAG = "PLCVEC_TAG";
    /** Interpretation ids, comma-separated. */
    public static final String INTERPRETATION = "PLCVEC_INTERPRETATION";
    /** {@code K/N}: one of N shards. */
    public static final String SHARD = "PLCVEC_SHARD";
    /** The known-failures TOML file. */
    public static final String KNOWN_FAILURES = "PLCVEC_KNOWN_FAILURES";
    /** Write the run's failures to this TOML file. */
    public static final String WRITE_EXPECTATIONS = "PLCVEC_WRITE_EXPECTATIONS";
    /** The bound on one vector's answer, in seconds. */
    public static final String TIMEOUT = "PLCVEC_TIMEOUT";

    /** The bound on one vector when {@code PLCVEC_TIMEOUT} is not set. */
    public static final Duration DEFAULT_TIMEOUT = Duration.ofSeconds(SettingNames.TIMEOUT_DEFAULT_SECONDS);
    /** The largest {@code PLCVEC_TIMEOUT} every runner takes: a day (CONTRACT.md), so no clock overflows. */
    public static final int TIMEOUT_MAX_SECONDS = SettingNames.TIMEOUT_MAX_SECONDS;
    /** Digits with an optional fraction: no sign, no exponent, no spaces (CONTRACT.md's one rule). */
    private static final Pattern SECONDS = Pattern.compile("[0-9]+(\\.[0-9]+)?");
    /** The process's {@code PLCVEC_*} variables (or the fixed ones), by name. */
    private final Map<String, String> variables;
    /** The system property that overrides a setting, or nothing. */
    private final UnaryOperator<String> override;

    private Environment(Map<String, String> variables, UnaryOperator<String> override) {
        this.variables = variables;
        this.override = override;
    }

    /**
     * This process's variables, each overridden by its system property.
     *
     * @return the settings of this process
     */
    public static Environment current() {
        Map<String, String> plcvec = new TreeMap<>();
        System.getenv().forEach((name, value) -> {
            if (name.startsWith(SettingNames.PREFIX)) {
                plcvec.put(name, value);
            }
        });
        return new Environment(plcvec, name -> System.getProperty(property(name)));
    }

    /**
     * Fixed values instead of the process's (a test, a runner that reads its settings elsewhere,
     * or one process running several configurations): no system property overrides them.
     *
     * @param values variable name to value, as an environment holds them
     * @return the settings those values give
     */
    public static Environment of(Map<String, String> values) {
        return new Environment(new TreeMap<>(values), name -> null);
    }

    /**
     * The system property that overrides {@code variable}.
     *
     * @param variable a {@code PLCVEC_*} name: {@code PLCVEC_KNOWN_FAILURES}
     * @return its property: {@code plcvec.known-failures}
     */
    public static String property(String variable) {
        return "plcvec." + variable.substring(SettingNames.PREFIX.length()).toLowerCase(Locale.ROOT).replace('_', '-');
    }

    /**
     * A setting's value: its system property, else the variable, else the variable's old name when
     * the new one is not set at all.
     *
     * @param variable the setting ({@link #KNOWN_FAILURES}, ...)
     * @return the value, or null when unset or empty
     */
    public String get(String variable) {
        String v = override.apply(variable);
        if (v != null) {     // set, even to nothing: -Dplcvec.id= unsets PLCVEC_ID
            return v.isEmpty() ? null : v;
        }
        v = variables.get(variable);
        if (v == null && !variables.containsKey(variable)) {
            for (SettingNames.OldName old : SettingNames.OLD_NAMES) {
                if (old.replacement().equals(variable) && variables.containsKey(old.name())) {
                    v = variables.get(old.name());
                }
            }
        }
        return v == null || v.isEmpty() ? null : v;
    }

    /**
     * What the variables give cause to warn of, one line each in variable order, in the words of
     * every runner (CONTRACT.md, "Old names and misspellings"): an old name read as its new one (or
     * ignored, when the new one is set too), and a {@code PLCVEC_*} variable that is no setting,
     * with the nearest setting. Neither stops a run.
     *
     * @return the lines, each {@code plcvec: warning: ...}; empty when there is nothing to say
     */
    public List<String> warnings() {
        List<String> out = new ArrayList<>();
        for (String name : variables.keySet()) {
            if (SettingNames.SETTINGS.contains(name) || SettingNames.RESERVED.contains(name)
                    || SettingNames.RESERVED_PREFIXES.stream().anyMatch(name::startsWith)) {
                continue;
            }
            SettingNames.OldName old = oldName(name);
            if (old != null) {
                out.add("plcvec: warning: " + name + (variables.containsKey(old.replacement())
                        ? " is ignored: it is the old name of " + old.replacement() + ", which is set too"
                        : " is the old name of " + old.replacement() + ", read as it until plcvec " + old.until()
                        + "; set " + old.replacement() + " instead"));
                continue;
            }
            String guess = nearest(name);
            out.add("plcvec: warning: " + name + " is not a plcvec setting" + (guess != null ? "; did you mean " + guess + "?"
                    : "; the settings are " + String.join(", ", SettingNames.SETTINGS)));
        }
        return out;
    }

    /** Print {@link #warnings()} on standard error: what each run does once, before anything else. */
    void warn() {
        for (String line : warnings()) {
            System.err.println(line);
        }
    }

    private static SettingNames.OldName oldName(String name) {
        for (SettingNames.OldName old : SettingNames.OLD_NAMES) {
            if (old.name().equals(name)) {
                return old;
            }
        }
        return null;
    }

    /**
     * The setting {@code name} is most likely a misspelling of: the first by name among those at
     * the smallest edit distance, an old name counting as its new one; null when none is within 3.
     */
    static String nearest(String name) {
        List<String> candidates = new ArrayList<>(SettingNames.SETTINGS);
        SettingNames.OLD_NAMES.forEach(o -> candidates.add(o.name()));
        candidates.sort(null);
        String upper = name.toUpperCase(Locale.ROOT);
        String best = null;
        int distance = Integer.MAX_VALUE;
        for (String c : candidates) {
            int d = editDistance(upper, c);
            if (d < distance) {
                best = c;
                distance = d;
            }
        }
        if (best == null || distance > SettingNames.NEAREST_DISTANCE) {
            return null;
        }
        SettingNames.OldName old = oldName(best);
        return old != null ? old.replacement() : best;
    }

    /** Levenshtein distance: insert, delete or replace one character, each 1. */
    static int editDistance(String a, String b) {
        int[] previous = new int[b.length() + 1];
        for (int j = 0; j <= b.length(); j++) {
            previous[j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            int[] current = new int[b.length() + 1];
            current[0] = i;
            for (int j = 1; j <= b.length(); j++) {
                int replace = previous[j - 1] + (a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1);
                current[j] = Math.min(Math.min(previous[j] + 1, current[j - 1] + 1), replace);
            }
            previous = current;
        }
        return previous[b.length()];
    }

    /**
     * {@code selection} narrowed by the selection variables, each checked against {@code suite}.
     *
     * @param selection what the code selects
     * @param suite the vectors the names are checked against
     * @return the selection narrowed; {@code selection} itself when no variable narrows it
     */
    public Selection narrow(Selection selection, Suite suite) {
        Selection p = Selection.all();
        p = narrowed(p, FAMILY, suite, Selection.all()::families);
        p = narrowed(p, INSTRUCTION, suite, Selection.all()::instructions);
        p = narrowed(p, TAG, suite, Selection.all()::tags);
        p = narrowed(p, ID, suite, Selection.all()::ids);
        p = narrowed(p, INTERPRETATION, suite, Selection.all()::interpretations);
        String v = get(SHARD);
        if (v != null) {
            try {
                p = p.and(Selection.all().shard(v));
            } catch (VerifyException e) {
                throw new VerifyException(SHARD + "=" + v + ": " + e.getMessage());
            }
        }
        return p == Selection.all() ? selection : selection.and(p);
    }

    private Selection narrowed(Selection so, String variable, Suite suite,
                               java.util.function.Function<String[], Selection> filter) {
        String value = get(variable);
        if (value == null) {
            return so;
        }
        Selection one = filter.apply(items(variable, value));
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

    /**
     * {@code PLCVEC_TIMEOUT}: the seconds one vector may take, written as digits with an optional
     * fraction ({@code 10}, {@code 2.5}), above 0 and at most a day; the one rule of every runner.
     *
     * @return the bound; {@link #DEFAULT_TIMEOUT} when unset
     * @throws VerifyException for anything else, naming the variable and its value
     */
    public Duration timeout() {
        String v = get(TIMEOUT);
        if (v == null) {
            return DEFAULT_TIMEOUT;
        }
        // Compared as a decimal, never as a double or a long: no value overflows or rounds into range.
        BigDecimal seconds = SECONDS.matcher(v).matches() ? new BigDecimal(v) : null;
        if (seconds == null || seconds.signum() <= 0 || seconds.compareTo(BigDecimal.valueOf(TIMEOUT_MAX_SECONDS)) > 0) {
            throw new VerifyException(TIMEOUT + "=" + v + ": the bound must be a number of seconds above 0 and at most "
                    + TIMEOUT_MAX_SECONDS + ", written as digits with an optional fraction (2, 0.5)");
        }
        return Duration.ofNanos(Math.max(1, seconds.movePointRight(9).longValue()));
    }

    /**
     * {@code PLCVEC_KNOWN_FAILURES} (or its old name, {@code PLCVEC_EXPECTATIONS}).
     *
     * @return the known-failures file, or null
     */
    public Path knownFailures() {
        String v = get(KNOWN_FAILURES);
        return v == null ? null : Path.of(v);
    }

    /**
     * {@code PLCVEC_WRITE_EXPECTATIONS}.
     *
     * @return where to write the run's failures, or null
     */
    public Path writeExpectations() {
        String v = get(WRITE_EXPECTATIONS);
        return v == null ? null : Path.of(v);
    }

    /**
     * {@code PLCVEC_VECTORS}.
     *
     * @return another copy of the vectors, or null for the one inside this jar
     */
    public Path vectors() {
        String v = get(VECTORS);
        return v == null ? null : Path.of(v);
    }

    /**
     * The vectors these settings name: {@code PLCVEC_VECTORS} loaded, or the copy inside this jar.
     *
     * @return the loaded vectors
     * @throws VerifyException when they cannot be loaded, naming the file
     */
    public Suite suite() {
        Path path = vectors();
        return path == null ? Suite.bundled() : Suite.load(path);
    }

    @Override
    public String toString() {
        List<String> set = new ArrayList<>();
        for (String name : SettingNames.SETTINGS) {
            String v = get(name);
            if (v != null) {
                set.add(name + "=" + v);
            }
        }
        return String.join(" ", set);
    }
}
