package org.plcvec.verify;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * What one vector expects of an implementation that follows given alternatives, worked out once:
 * the full device state after every step (a vector stores only the changes), over the vector's
 * device table, and checked against the vector's own {@code final} so that an inconsistent file
 * is caught, not trusted.
 */
final class Expected {
    final Vector vector;
    final Boolean[] results;
    final int[][] states;       // after each step, per slot (Values encoding; ABSENT: not in the image)
    final int[][] befores;      // before each step (after `set`), for messages
    final Map<String, String> judgedBy;   // interpretation -> alternative, for those the vector depends on
    final String category;
    // Address keys of the devices the implementation declares its CPU writes on its own account.
    private long[] cpuWrites = NO_CPU_WRITES;
    private static final long[] NO_CPU_WRITES = new long[0];

    private Expected(Vector vector, Boolean[] results, int[][] states, int[][] befores, Map<String, String> judgedBy,
                     String category) {
        this.vector = vector;
        this.results = results;
        this.states = states;
        this.befores = befores;
        this.judgedBy = judgedBy;
        this.category = category;
    }

    /** {@code choices}: interpretation → alternative for every interpretation (declared or default). */
    static Expected of(Vector v, Map<String, String> choices, Map<String, String> defaults) {
        Vector.Expectation e = v.expectation();
        Map<String, String> applied = new TreeMap<>();
        boolean other = false;
        for (String i : v.interpretations()) {
            String alt = choices.getOrDefault(i, defaults.get(i));
            applied.put(i, alt);
            other |= alt != null && !alt.equals(defaults.get(i));
        }
        if (other) {
            e = null;
            for (Vector.Variant variant : v.variants()) {
                boolean all = true;
                for (Map.Entry<String, String> a : applied.entrySet()) {
                    all &= a.getValue().equals(variant.choices().get(a.getKey()));
                }
                if (all) {
                    e = variant.expectation();
                    break;
                }
            }
            if (e == null) {
                StringBuilder sb = new StringBuilder();
                applied.forEach((k, a) -> sb.append(sb.length() == 0 ? "" : ", ").append(k).append('=').append(a));
                throw new VerifyException("vector " + v.id() + ": no expectation for " + sb
                        + " (the vector file lists no such alternative)");
            }
        }
        int n = v.steps().size();
        int[] state = v.initial.clone();
        Boolean[] results = new Boolean[n];
        int[][] states = new int[n][];
        int[][] befores = new int[n][];
        for (int s = 0; s < n; s++) {
            Step step = v.steps().get(s);
            Map<String, Object> set = step.set();
            for (Map.Entry<String, Object> kv : set.entrySet()) {
                state[slot(v, Address.of(kv.getKey()))] = Values.encode(kv.getValue());
            }
            befores[s] = state.clone();
            Vector.StepExpect se = e.steps().get(s);
            for (int d = 0; d < se.devices().length; d++) {
                state[slot(v, se.devices()[d])] = se.values()[d];
            }
            states[s] = state.clone();
            results[s] = se.result();
        }
        int[] fin = new int[v.slots.length];
        java.util.Arrays.fill(fin, Values.ABSENT);
        for (int d = 0; d < e.finalDevices().length; d++) {
            fin[slot(v, e.finalDevices()[d])] = e.finalValues()[d];
        }
        int[] last = states[n - 1];
        for (int j = 0; j < fin.length; j++) {
            if (v.compared[j] && fin[j] != last[j]) {
                throw new VerifyException("vector " + v.id() + ": the per-step changes do not add up to `final` at "
                        + v.slots[j] + " (the vector file is inconsistent; regenerate it)");
            }
        }
        return new Expected(v, results, states, befores, Collections.unmodifiableMap(applied), e.category());
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
     * Whether {@code answer} (the state after each step) has no problem against this expectation:
     * the comparison of a run, with the same declared CPU writes.
     */
    boolean accepts(List<StepState> answer) {
        if (answer.size() != results.length) {
            return false;
        }
        for (int s = 0; s < answer.size(); s++) {
            StepState st = answer.get(s);
            if (st == null || st.devices() == null
                    || !problems(s, st.devices(), st.result(), s == 0 ? null : answer.get(s - 1).devices()).isEmpty()) {
                return false;
            }
        }
        return true;
    }

    /** Whether {@code other} expects the same as this: every step's result and full state, value and type. */
    boolean sameOutcome(Expected other) {
        return java.util.Arrays.equals(results, other.results) && java.util.Arrays.deepEquals(states, other.states);
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
            parts.add("clock=" + shown);
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

    /**
     * {@code step k operands: ...} of TEXT.md: each operand, sorted by name, with the words its
     * device and the next listed addresses hold in the vector's state before the step.
     */
    String operands(int s) {
        int[] before = befores[s].clone();
        Address[] slots = vector.slots;
        java.util.Set<Long> operandKeys = new java.util.HashSet<>();
        for (Operand o : vector.operands().values()) {
            if (!o.isConstant()) {
                operandKeys.add(o.device().key());
            }
        }
        java.util.Set<String> scratch = vector.scratch();
        List<String> parts = new ArrayList<>();
        for (Map.Entry<String, Operand> e : new TreeMap<>(vector.operands()).entrySet()) {
            Operand o = e.getValue();
            if (o.isConstant()) {
                parts.add(e.getKey() + " constant " + o.constant());
                continue;
            }
            Address a = o.device();
            if (scratch.contains(a.name())) {
                parts.add(e.getKey() + " " + a.name() + " (scratch)");
                continue;
            }
            int j = find(slots, a);
            if (j < 0 || before[j] == Values.ABSENT) {
                parts.add(e.getKey() + " " + a.name() + " (not in the vector)");
                continue;
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
            parts.add(e.getKey() + " " + a.name() + "=" + words);
        }
        return String.join(", ", parts);
    }

    /** Whether {@code other} expects something else than this at {@code problem}'s step and field. */
    boolean differs(Expected other, Problem problem) {
        int k = problem.step();
        if (k == Problem.WHOLE) {
            return false;
        }
        if (problem.field().equals("result")) {
            return !java.util.Objects.equals(results[k], other.results[k]);
        }
        int j = find(vector.slots, Address.of(problem.field()));
        return j >= 0 && states[k][j] != other.states[k][j];
    }

    /** The devices the implementation's CPU writes on its own: not a write outside the vector. */
    Expected cpuWrites(long[] keys) {
        this.cpuWrites = keys;
        return this;
    }

    private boolean cpuWrite(Address a) {
        for (long k : cpuWrites) {
            if (k == a.key()) {
                return true;
            }
        }
        return false;
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

    /** Fast check of the memory after step {@code s}: true when every compared device and the result match. */
    boolean matches(int s, Memory m, Boolean result) {
        Boolean want = results[s];
        if (want != null && !want.equals(result)) {
            return false;
        }
        int[] expect = states[s];
        boolean[] compared = vector.compared;
        for (int j = 0; j < expect.length; j++) {
            if (m.valueAt(j) != expect[j] && compared[j]) {
                return false;
            }
        }
        for (int j = expect.length, n = m.size(); j < n; j++) {
            if (m.valueAt(j) != Values.ABSENT && !cpuWrite(m.address(j))) {
                return false;      // a write outside the vector
            }
        }
        return true;
    }

    /** The field-level differences after step {@code s}, memory form. */
    List<Problem> problems(int s, Memory m, Boolean result, int[] held) {
        int n = m.size();
        Address[] a = new Address[n];
        String[] shown = new String[n];
        int[] values = new int[n];
        for (int j = 0; j < n; j++) {
            a[j] = m.address(j);
            values[j] = m.valueAt(j);
            shown[j] = Values.show(values[j]);
        }
        return problems(s, a, values, shown, result, held);
    }

    /** The field-level differences after step {@code s}, as a contract-level implementation reported it. */
    List<Problem> problems(int s, DeviceImage image, Boolean result, DeviceImage previous) {
        int n = image.size();
        Address[] a = new Address[n];
        String[] shown = new String[n];
        int[] values = new int[n];
        for (int j = 0; j < n; j++) {
            a[j] = image.address(j);
            values[j] = image.value(j);
            shown[j] = image.show(j);
        }
        return problems(s, a, values, shown, result, held(s, previous));
    }

    /**
     * What a contract-level implementation held before step {@code s}, per slot: the vector's own
     * state for step 0, else its report of the step before with step {@code s}'s {@code set} over it.
     */
    private int[] held(int s, DeviceImage previous) {
        if (s == 0 || previous == null) {
            return befores[s];
        }
        Address[] slots = vector.slots;
        int[] held = new int[slots.length];
        java.util.Arrays.fill(held, Values.ABSENT);
        for (int r = 0; r < previous.size(); r++) {
            int j = find(slots, previous.address(r));
            if (j >= 0) {
                held[j] = previous.value(r);
            }
        }
        vector.steps().get(s).set().forEach((name, value) -> {
            int j = find(slots, Address.of(name));
            if (j >= 0) {
                held[j] = Values.encode(value);
            }
        });
        return held;
    }

    private List<Problem> problems(int s, Address[] reported, int[] values, String[] shown, Boolean result,
                                   int[] held) {
        List<Problem> out = new ArrayList<>();
        Boolean want = results[s];
        if (want != null && !want.equals(result)) {
            out.add(new Problem(s, "result", want.toString(), result == null ? Problem.NOT_REPORTED : result.toString(),
                    null));
        }
        Address[] slots = vector.slots;
        int[] actual = new int[slots.length];
        String[] actualShown = new String[slots.length];
        java.util.Arrays.fill(actual, Values.ABSENT);
        List<Problem> outside = new ArrayList<>();
        String[] reportedAs = new String[slots.length];
        for (int r = 0; r < reported.length; r++) {
            int j = find(slots, reported[r]);
            if (j >= 0) {
                if (reportedAs[j] != null && actual[j] != values[r]) {
                    // One device under two spellings (D100, D0100) with two values: which one the
                    // implementation means is unknowable, so neither is taken.
                    outside.add(new Problem(s, slots[j].name(), "one value", actualShown[j] + " as " + reportedAs[j]
                            + " and " + shown[r] + " as " + reported[r].name() + " (reported twice)", null));
                }
                reportedAs[j] = reported[r].name();
                actual[j] = values[r];
                actualShown[j] = shown[r];
            } else if (values[r] != Values.ABSENT && !cpuWrite(reported[r])) {
                outside.add(new Problem(s, reported[r].name(), Problem.NOT_IN_VECTOR, shown[r], null));
            }
        }
        int[] expect = states[s];
        int[] before = befores[s];
        List<Problem> fields = new ArrayList<>();
        for (int j = 0; j < slots.length; j++) {
            if (!vector.compared[j] || actual[j] == expect[j]) {
                continue;
            }
            String want2 = expect[j] == Values.ABSENT ? Problem.NOT_IN_VECTOR : Values.show(expect[j]);
            String got = actual[j] == Values.ABSENT ? Problem.NOT_REPORTED : actualShown[j];
            // TEXT.md: the value the implementation held before the step, and "must leave it
            // unchanged" only where the vector keeps the device and the implementation wrote it.
            int had = held == null ? before[j] : held[j];
            String was = had == Values.ABSENT ? Problem.NOT_REPORTED : Values.show(had);
            boolean keep = expect[j] == before[j];
            boolean wrote = actual[j] != Values.ABSENT && actual[j] != had;
            fields.add(new Problem(s, slots[j].name(), want2, got, was, keep && wrote));
        }
        fields.addAll(outside);
        fields.sort((x, y) -> x.field().compareTo(y.field()));
        out.addAll(fields);
        return out;
    }

    private static int find(Address[] slots, Address a) {
        for (int j = 0; j < slots.length; j++) {
            if (slots[j].key() == a.key()) {
                return j;
            }
        }
        return -1;
    }
}
