package org.plcvec.verify;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

/**
 * What one vector expects of an implementation that follows given alternatives, worked out once:
 * the full device state after every step (a vector stores only the changes), over the vector's
 * device table, which devices are judged, and the lines a failure block shows of each step; checked
 * against the vector's own {@code final} so that an inconsistent file is caught, not trusted.
 * {@link Compare} holds an answer to it.
 */
final class Expected {
    final Vector vector;
    final Boolean[] results;
    final int[][] states;       // after each step, per slot (Values encoding; ABSENT: not in the image)
    final int[][] befores;      // before each step (after `set`), for messages
    final Map<String, String> judgedBy;   // interpretation -> alternative, for those the vector depends on
    final String category;
    /** interpretation -> the devices the followed entry leaves unjudged (sorted; empty for most). */
    final Map<String, List<String>> unjudged;
    /** Per slot: compared after every step (not scratch, not unjudged under these alternatives). */
    final boolean[] judged;
    // Address keys of the devices the implementation declares its CPU writes on its own account.
    long[] cpuWrites = NO_CPU_WRITES;
    private static final long[] NO_CPU_WRITES = new long[0];

    private Expected(Vector vector, Boolean[] results, int[][] states, int[][] befores, Map<String, String> judgedBy,
                     String category, Map<String, List<String>> unjudged, boolean[] judged) {
        this.vector = vector;
        this.results = results;
        this.states = states;
        this.befores = befores;
        this.judgedBy = judgedBy;
        this.category = category;
        this.unjudged = unjudged;
        this.judged = judged;
    }

    /**
     * {@code choices}: interpretation to alternative for every interpretation (declared or default).
     *
     * @throws VerifyException when the vector offers no expectation for them, or its steps do not
     *         add up to its {@code final}
     */
    static Expected of(Vector v, Map<String, String> choices, Map<String, String> defaults) {
        Map<String, String> applied = new TreeMap<>();
        boolean other = false;
        for (String i : v.interpretations()) {
            String alt = choices.getOrDefault(i, defaults.get(i));
            applied.put(i, alt);
            other |= alt != null && !alt.equals(defaults.get(i));
        }
        Vector.Variant variant = other ? variant(v, applied) : null;
        Vector.Expectation e = variant != null ? variant.expectation() : v.expectation();
        Map<String, List<String>> unjudged = variant != null ? variant.unjudged() : Map.of();
        boolean[] judged = v.compared;
        if (!unjudged.isEmpty()) {
            judged = v.compared.clone();
            for (String device : Validate.union(unjudged)) {
                judged[slot(v, Address.of(device))] = false;
            }
        }
        int n = v.steps().size();
        int[] state = v.initial.clone();
        Boolean[] results = new Boolean[n];
        int[][] states = new int[n][];
        int[][] befores = new int[n][];
        for (int s = 0; s < n; s++) {
            Step step = v.steps().get(s);
            for (Map.Entry<String, Object> kv : step.set().entrySet()) {
                state[slot(v, Address.of(kv.getKey()))] = Values.encode(kv.getValue());
            }
            befores[s] = state.clone();
            // A device left unjudged is in no step's changes: it keeps the value it had before.
            Vector.StepExpect se = e.steps().get(s);
            for (int d = 0; d < se.devices().length; d++) {
                state[slot(v, se.devices()[d])] = se.values()[d];
            }
            states[s] = state.clone();
            results[s] = se.result();
        }
        addsUp(v, e, states[n - 1], judged);
        return new Expected(v, results, states, befores, Collections.unmodifiableMap(applied), e.category(),
                unjudged, judged);
    }

    /** The entry of {@code alternatives} whose choices are {@code applied}. */
    private static Vector.Variant variant(Vector v, Map<String, String> applied) {
        for (Vector.Variant variant : v.variants()) {
            boolean all = true;
            for (Map.Entry<String, String> a : applied.entrySet()) {
                all &= a.getValue().equals(variant.choices().get(a.getKey()));
            }
            if (all) {
                return variant;
            }
        }
        StringBuilder sb = new StringBuilder();
        applied.forEach((k, a) -> sb.append(sb.length() == 0 ? "" : ", ").append(k).append('=').append(a));
        throw new VerifyException("vector " + v.id() + ": no expectation for " + sb
                + " (the vector file lists no such alternative)");
    }

    /** The changes of every step add up to {@code final}, over the devices judged. */
    private static void addsUp(Vector v, Vector.Expectation e, int[] last, boolean[] judged) {
        int[] fin = new int[v.slots.length];
        java.util.Arrays.fill(fin, Values.ABSENT);
        for (int d = 0; d < e.finalDevices().length; d++) {
            fin[slot(v, e.finalDevices()[d])] = e.finalValues()[d];
        }
        for (int j = 0; j < fin.length; j++) {
            if (judged[j] && fin[j] != last[j]) {
                throw new VerifyException("vector " + v.id() + ": the per-step changes do not add up to `final` at "
                        + v.slots[j] + " (the vector file is inconsistent; regenerate it)");
            }
        }
    }

    /**
     * The combinations of alternatives {@code v} offers an expectation for (TEXT.md, "The
     * inference", 1): the defaults of the interpretations it touches (its own steps), then each
     * {@code alternatives} entry in file order that names all of them, restricted to them.
     */
    static List<Map<String, String>> offered(Vector v, Map<String, String> defaults) {
        List<String> touched = v.interpretations();
        List<Map<String, String>> out = new ArrayList<>();
        Map<String, String> own = new TreeMap<>();
        touched.forEach(i -> own.put(i, defaults.get(i)));
        out.add(own);
        for (Vector.Variant variant : v.variants()) {
            if (variant.choices().keySet().containsAll(touched)) {
                Map<String, String> c = new TreeMap<>();
                touched.forEach(i -> c.put(i, variant.choices().get(i)));
                out.add(c);
            }
        }
        return out;
    }

    /**
     * Whether an answer that passes {@code followed} passes this expectation too, known from the
     * two alone (unjudged.md, "The inference"): every step's result is equal, and every device this
     * one judges is judged by {@code followed} and expected alike by both (value and JSON type). A
     * device this one judges but {@code followed} leaves unjudged makes them differ: what the
     * answer holds there is not known.
     */
    boolean passesWherePasses(Expected followed) {
        if (!java.util.Arrays.equals(results, followed.results)) {
            return false;
        }
        for (int s = 0; s < states.length; s++) {
            for (int j = 0; j < judged.length; j++) {
                if (judged[j] && (!followed.judged[j] || states[s][j] != followed.states[s][j])) {
                    return false;
                }
            }
        }
        return true;
    }

    /**
     * Whether {@code other} expects something else than this at {@code problem}'s step and field:
     * another result, another value or JSON type, or the device left unjudged.
     */
    boolean differs(Expected other, Problem problem) {
        int k = problem.step();
        if (k == Problem.WHOLE) {
            return false;
        }
        if (problem.field().equals("result")) {
            return !java.util.Objects.equals(results[k], other.results[k]);
        }
        int j = find(vector.slots, Address.of(problem.field()));
        return j >= 0 && (!other.judged[j] || states[k][j] != other.states[k][j]);
    }

    /** The devices the implementation's CPU writes on its own: not a write outside the vector. */
    Expected cpuWrites(long[] keys) {
        this.cpuWrites = keys;
        return this;
    }

    boolean cpuWrite(Address a) {
        for (long k : cpuWrites) {
            if (k == a.key()) {
                return true;
            }
        }
        return false;
    }

    /**
     * {@code not judged under <ID>=<alternative>: <device>, ...}, one line per interpretation of the
     * followed entry's {@code unjudged} map (unjudged.md, "The failure block").
     */
    List<String> notJudgedLines() {
        List<String> out = new ArrayList<>();
        unjudged.forEach((i, devices) -> out.add("not judged under " + i + "=" + judgedBy.get(i) + ": "
                + String.join(", ", devices)));
        return out;
    }

    /**
     * {@code step k inputs: ...} of TEXT.md: the clock, rlo_in, en, input, elapsed_ms, then the
     * step's {@code set}, or {@code (none)}.
     */
    String inputs(int s) {
        Step step = vector.steps().get(s);
        List<String> parts = new ArrayList<>();
        Map<String, Integer> clock = step.clock();
        if (clock != null) {
            parts.add("clock=" + clock(clock));
        }
        Map<String, Object> inputs = step.toMap();
        for (String k : new String[] {"rlo_in", "en", "input", "elapsed_ms"}) {
            if (inputs.containsKey(k)) {
                parts.add(k + "=" + inputs.get(k));
            }
        }
        StringBuilder out = new StringBuilder(String.join(", ", parts));
        Map<String, Object> set = new TreeMap<>(step.set());
        if (!set.isEmpty()) {
            StringBuilder sets = new StringBuilder("set");
            set.forEach((k, v) -> sets.append(' ').append(k).append('=').append(v));
            out.append(out.length() > 0 ? ", " : "").append(sets);
        }
        return out.length() == 0 ? "(none)" : out.toString();
    }

    /** The clock as TEXT.md shows it: {@code 2029/6/17 4:02:41}, other fields after it. */
    private static String clock(Map<String, Integer> clock) {
        List<String> date = new ArrayList<>();
        for (String f : new String[] {"year", "month", "day"}) {
            if (clock.containsKey(f)) {
                date.add(String.valueOf(clock.get(f)));
            }
        }
        StringBuilder time = new StringBuilder();
        for (String f : new String[] {"hour", "minute", "second"}) {
            if (clock.containsKey(f)) {
                int v = clock.get(f);
                time.append(time.length() == 0 ? String.valueOf(v) : String.format(java.util.Locale.ROOT, ":%02d", v));
            }
        }
        StringBuilder shown = new StringBuilder(String.join("/", date));
        if (time.length() > 0) {
            shown.append(shown.length() > 0 ? " " : "").append(time);
        }
        new TreeMap<>(clock).forEach((k, v) -> {
            if (!List.of("year", "month", "day", "hour", "minute", "second").contains(k)) {
                shown.append(' ').append(k).append('=').append(v);
            }
        });
        return shown.toString();
    }

    /**
     * {@code step k operands: ...} of TEXT.md: each operand, sorted by name, with the words its
     * device and the next listed addresses hold in the vector's state before the step.
     */
    String operands(int s) {
        int[] before = befores[s];
        Set<Long> operandKeys = new java.util.HashSet<>();
        for (Operand o : vector.operands().values()) {
            if (!o.isConstant()) {
                operandKeys.add(o.device().key());
            }
        }
        List<String> parts = new ArrayList<>();
        for (Map.Entry<String, Operand> e : new TreeMap<>(vector.operands()).entrySet()) {
            parts.add(e.getKey() + operand(e.getValue(), before, operandKeys));
        }
        return String.join(", ", parts);
    }

    /** One operand after its name: {@code  constant 2}, {@code  D100=23 0 0}, ... */
    private String operand(Operand o, int[] before, Set<Long> operandKeys) {
        if (o.isConstant()) {
            return " constant " + o.constant();
        }
        Address a = o.device();
        Set<String> scratch = vector.scratch();
        if (scratch.contains(a.name())) {
            return " " + a.name() + " (scratch)";
        }
        Address[] slots = vector.slots;
        int j = find(slots, a);
        if (j < 0 || before[j] == Values.ABSENT) {
            return " " + a.name() + " (not in the vector)";
        }
        StringBuilder words = new StringBuilder(Values.show(before[j]));
        if (Values.isWord(before[j]) && a.number() >= 0) {
            for (Address next = a.plus(1);; next = next.plus(1)) {
                int k = find(slots, next);
                if (k < 0 || before[k] == Values.ABSENT || !Values.isWord(before[k])
                        || operandKeys.contains(next.key()) || scratch.contains(next.name())) {
                    break;
                }
                words.append(' ').append(Values.show(before[k]));
            }
        }
        return " " + a.name() + "=" + words;
    }

    static int slot(VectorRequest v, Address a) {
        long key = a.key();
        Address[] slots = v.slots;
        for (int j = 0; j < slots.length; j++) {
            if (slots[j].key() == key) {
                return j;
            }
        }
        throw new IllegalStateException("vector " + v.id() + ": " + a + " is not in its device table");
    }

    static int find(Address[] slots, Address a) {
        for (int j = 0; j < slots.length; j++) {
            if (slots[j].key() == a.key()) {
                return j;
            }
        }
        return -1;
    }
}
