package org.plcvec.verify;

import java.util.ArrayList;
import java.util.List;

/**
 * An answer held to an {@link Expected}, exactly as CONTRACT.md's "Comparing" says: after every
 * step the contact result and every listed device that is judged (scratch words and the devices
 * the followed alternative leaves unjudged are not), value and JSON type together, and no write
 * outside the vector but the CPU's own declared devices. Two forms of the answer: an emulator's
 * {@link Memory}, checked in place, and a contract-level implementation's {@link DeviceImage}.
 */
final class Compare {
    private Compare() {
    }

    /** Fast check of the memory after step {@code s}: true when every judged device and the result match. */
    static boolean matches(Expected e, int s, Memory m, Boolean result) {
        Boolean want = e.results[s];
        if (want != null && !want.equals(result)) {
            return false;
        }
        int[] expect = e.states[s];
        boolean[] judged = e.judged;
        for (int j = 0; j < expect.length; j++) {
            if (m.valueAt(j) != expect[j] && judged[j]) {
                return false;
            }
        }
        for (int j = expect.length, n = m.size(); j < n; j++) {
            if (m.valueAt(j) != Values.ABSENT && !e.cpuWrite(m.address(j))) {
                return false;      // a write outside the vector
            }
        }
        return true;
    }

    /** The field-level differences after step {@code s}, memory form. */
    static List<Problem> problems(Expected e, int s, Memory m, Boolean result, int[] held) {
        int n = m.size();
        Address[] a = new Address[n];
        String[] shown = new String[n];
        int[] values = new int[n];
        for (int j = 0; j < n; j++) {
            a[j] = m.address(j);
            values[j] = m.valueAt(j);
            shown[j] = Values.show(values[j]);
        }
        return problems(e, s, new Reported(a, values, shown), result, held);
    }

    /** The field-level differences after step {@code s}, as a contract-level implementation reported it. */
    static List<Problem> problems(Expected e, int s, DeviceImage image, Boolean result, DeviceImage previous) {
        int n = image.size();
        Address[] a = new Address[n];
        String[] shown = new String[n];
        int[] values = new int[n];
        for (int j = 0; j < n; j++) {
            a[j] = image.address(j);
            values[j] = image.value(j);
            shown[j] = image.show(j);
        }
        return problems(e, s, new Reported(a, values, shown), result, held(e, s, previous));
    }

    /**
     * Whether {@code answer} (the state after each step) has no problem against {@code e}: the
     * comparison of a run, with the same declared CPU writes.
     */
    static boolean accepts(Expected e, List<StepState> answer) {
        if (answer.size() != e.results.length) {
            return false;
        }
        for (int s = 0; s < answer.size(); s++) {
            StepState st = answer.get(s);
            if (st == null || st.devices() == null
                    || !problems(e, s, st.devices(), st.result(), s == 0 ? null : answer.get(s - 1).devices()).isEmpty()) {
                return false;
            }
        }
        return true;
    }

    /**
     * What a contract-level implementation held before step {@code s}, per slot: the vector's own
     * state for step 0, else its report of the step before with step {@code s}'s {@code set} over it.
     */
    private static int[] held(Expected e, int s, DeviceImage previous) {
        if (s == 0 || previous == null) {
            return e.befores[s];
        }
        Address[] slots = e.vector.slots;
        int[] held = new int[slots.length];
        java.util.Arrays.fill(held, Values.ABSENT);
        for (int r = 0; r < previous.size(); r++) {
            int j = Expected.find(slots, previous.address(r));
            if (j >= 0) {
                held[j] = previous.value(r);
            }
        }
        e.vector.steps().get(s).set().forEach((name, value) -> {
            int j = Expected.find(slots, Address.of(name));
            if (j >= 0) {
                held[j] = Values.encode(value);
            }
        });
        return held;
    }

    /** What was reported after one step: each device, its encoded value and how a report shows it. */
    private record Reported(Address[] devices, int[] values, String[] shown) {
    }

    private static List<Problem> problems(Expected e, int s, Reported reported, Boolean result, int[] held) {
        List<Problem> out = new ArrayList<>();
        Boolean want = e.results[s];
        if (want != null && !want.equals(result)) {
            out.add(new Problem(s, "result", want.toString(), result == null ? Problem.NOT_REPORTED : result.toString(),
                    null));
        }
        Address[] slots = e.vector.slots;
        int[] actual = new int[slots.length];
        String[] actualShown = new String[slots.length];
        java.util.Arrays.fill(actual, Values.ABSENT);
        List<Problem> fields = new ArrayList<>();
        List<Problem> outside = new ArrayList<>();
        String[] reportedAs = new String[slots.length];
        for (int r = 0; r < reported.devices().length; r++) {
            Address device = reported.devices()[r];
            int value = reported.values()[r];
            int j = Expected.find(slots, device);
            if (j >= 0) {
                if (reportedAs[j] != null && actual[j] != value) {
                    // One device under two spellings (D100, D0100) with two values: which one the
                    // implementation means is unknowable, so neither is taken.
                    outside.add(new Problem(s, slots[j].name(), "one value", actualShown[j] + " as " + reportedAs[j]
                            + " and " + reported.shown()[r] + " as " + device.name() + " (reported twice)", null));
                }
                reportedAs[j] = device.name();
                actual[j] = value;
                actualShown[j] = reported.shown()[r];
            } else if (value != Values.ABSENT && !e.cpuWrite(device)) {
                outside.add(new Problem(s, device.name(), Problem.NOT_IN_VECTOR, reported.shown()[r], null));
            }
        }
        for (int j = 0; j < slots.length; j++) {
            if (e.judged[j] && actual[j] != e.states[s][j]) {
                fields.add(field(e, s, j, actual[j], actualShown[j], held));
            }
        }
        fields.addAll(outside);
        fields.sort((x, y) -> x.field().compareTo(y.field()));
        out.addAll(fields);
        return out;
    }

    /**
     * One differing device, with TEXT.md's suffix: the value the implementation held before the
     * step, and "must leave it unchanged" only where the vector keeps the device and the
     * implementation wrote it.
     */
    private static Problem field(Expected e, int s, int j, int actual, String shown, int[] held) {
        int expect = e.states[s][j];
        int before = e.befores[s][j];
        String want = expect == Values.ABSENT ? Problem.NOT_IN_VECTOR : Values.show(expect);
        String got = actual == Values.ABSENT ? Problem.NOT_REPORTED : shown;
        int had = held == null ? before : held[j];
        String was = had == Values.ABSENT ? Problem.NOT_REPORTED : Values.show(had);
        boolean keep = expect == before;
        boolean wrote = actual != Values.ABSENT && actual != had;
        return new Problem(s, e.vector.slots[j].name(), want, got, was, keep && wrote);
    }
}
