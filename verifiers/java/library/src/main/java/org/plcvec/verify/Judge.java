package org.plcvec.verify;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * One vector run through an implementation and judged (VOCABULARY.md's {@code judge}): the
 * emulator's memory path, compared in place after each step and replayed only when it differs, or
 * the contract path, the reported states compared; then the verdict, with what a failure block
 * shows (the step lines, the interpretations that decide a differing field). An exception of the
 * implementation is an error of the vector, located at the implementation's own frame.
 */
final class Judge {
    private static final List<Problem> NONE = List.of();

    private final Implementation implementation;
    /** interpretation -> the alternative followed, for every interpretation of the suite. */
    private final Map<String, String> followed;
    private final Map<String, String> defaults;

    Judge(Implementation implementation, Map<String, String> followed, Map<String, String> defaults) {
        this.implementation = implementation;
        this.followed = followed;
        this.defaults = defaults;
    }

    /**
     * What an implementation gave on one vector: the problems found and, when there are some, its
     * answer (the state after each step), which the roll-up by reading judges under other
     * alternatives.
     */
    private record Answer(List<Problem> problems, List<StepState> steps) {
    }

    private static final Answer PASSED = new Answer(NONE, null);

    /** The verdict on {@code v} judged by {@code e}; {@code reuse}: a memory to run an emulator in, or null. */
    Verdict judge(Vector v, Expected e, Memory reuse) {
        if (!implementation.supports(v.instruction())) {
            return verdict(v, e, Status.SKIP, implementation.name() + " does not support " + v.instruction());
        }
        try {
            Answer answer = implementation instanceof Emulator
                    ? runEmulator((Emulator) implementation, v, e, reuse)
                    : runContract(v, e);
            List<Problem> problems = answer.problems();
            if (problems.isEmpty()) {
                return verdict(v, e, Status.PASS, null);
            }
            Map<Integer, String[]> steps = new HashMap<>();
            for (Problem p : problems) {
                if (p.step() != Problem.WHOLE) {
                    steps.computeIfAbsent(p.step(), s -> new String[] {e.inputs(s), e.operands(s)});
                }
            }
            return new Verdict(v.id(), v, Status.FAIL, problems, null, deciding(v, e, problems)).steps(steps)
                    .judged(e, answer.steps());
        } catch (SkipVector s) {
            return verdict(v, e, Status.SKIP, s.getMessage());
        } catch (VectorError r) {   // the implementation's own report, in its own words
            return verdict(v, e, Status.ERROR, "the implementation reported an error: " + r.getMessage()).causedBy(r);
        } catch (VirtualMachineError fatal) {
            throw fatal;
        } catch (Throwable t) {   // the implementation's failure on this vector, not the run's
            return verdict(v, e, Status.ERROR, describe(t)).causedBy(t);
        }
    }

    /** A verdict without field lines: judged by the alternatives followed, with what {@code e} leaves unjudged. */
    static Verdict verdict(Vector v, Expected e, Status status, String message) {
        return new Verdict(v.id(), v, status, NONE, message, e.judgedBy).judged(e, null);
    }

    /** The memory path: compare in place after each step; build problems only on a mismatch. */
    private static Answer runEmulator(Emulator emulator, Vector v, Expected e, Memory reuse) throws Exception {
        Memory m = reuse;
        if (m == null) {
            m = v.newMemory();
        } else {
            m.reset(v.slots.length, v.initial);
        }
        return passes(emulator, v, e, m) ? PASSED : replay(emulator, v, e);
    }

    /**
     * Whether the emulator passes {@code v} in {@code m}, which holds the vector's initial devices:
     * compared in place after each step, stopping at the first difference.
     */
    static boolean passes(Emulator emulator, Vector v, Expected e, Memory m) throws Exception {
        Emulator.Scan scan = emulator.load(v, m);
        List<Step> steps = v.steps();
        for (int s = 0, n = steps.size(); s < n; s++) {
            Step step = steps.get(s);
            step.applySet(m);
            if (!Compare.matches(e, s, m, scan.execute(step))) {
                return false;
            }
        }
        return true;
    }

    /**
     * The problems of a vector the emulator failed, found by running it again from the start on a
     * fresh CPU and memory, keeping what it held before each step (the fast path keeps nothing).
     */
    private static Answer replay(Emulator emulator, Vector v, Expected e) throws Exception {
        Memory m = v.newMemory();
        Emulator.Scan scan = emulator.load(v, m);
        List<Problem> problems = new ArrayList<>();
        List<StepState> answer = new ArrayList<>();
        List<Step> steps = v.steps();
        int listed = v.slots.length;
        for (int s = 0, n = steps.size(); s < n; s++) {
            Step step = steps.get(s);
            step.applySet(m);
            int[] held = new int[listed];
            for (int j = 0; j < listed; j++) {
                held[j] = m.valueAt(j);
            }
            Boolean result = scan.execute(step);
            if (!Compare.matches(e, s, m, result)) {
                problems.addAll(Compare.problems(e, s, m, result, held));
            }
            answer.add(new StepState(result, m.snapshot()));
        }
        return new Answer(problems, answer);
    }

    private Answer runContract(Vector v, Expected e) throws Exception {
        List<StepState> states = implementation.run(v);
        if (states == null || states.size() != v.steps().size()) {
            return new Answer(List.of(new Problem(Problem.WHOLE, "steps", v.steps().size() + " steps",
                    (states == null ? 0 : states.size()) + " steps", null)), states);
        }
        List<Problem> problems = NONE;
        for (int s = 0; s < states.size(); s++) {
            StepState st = states.get(s);
            if (st == null || st.devices() == null) {
                throw new IllegalStateException("step " + s + ": the implementation reported no devices");
            }
            List<Problem> p = Compare.problems(e, s, st.devices(), st.result(), s == 0 ? null : states.get(s - 1).devices());
            if (!p.isEmpty()) {
                if (problems == NONE) {
                    problems = new ArrayList<>();
                }
                problems.addAll(p);
            }
        }
        return problems == NONE ? PASSED : new Answer(problems, states);
    }

    /**
     * The interpretations that decide a differing field (TEXT.md, "judged by"): I decides when the
     * vector offers an expectation that differs from the followed one in I only and differs at a
     * problem's field (another value, or the field left unjudged); each with the alternative followed.
     */
    private Map<String, String> deciding(Vector v, Expected e, List<Problem> problems) {
        List<String> touched = v.interpretations();
        if (touched.isEmpty()) {
            return Map.of();
        }
        List<Map<String, String>> offered = Expected.offered(v, defaults);
        Map<String, String> out = new TreeMap<>();
        for (String i : touched) {
            for (Map<String, String> c : offered) {
                boolean onlyI = !c.get(i).equals(e.judgedBy.get(i)) && touched.stream()
                        .allMatch(x -> x.equals(i) || c.get(x).equals(e.judgedBy.get(x)));
                if (!onlyI) {
                    continue;
                }
                Map<String, String> all = new TreeMap<>(followed);
                all.putAll(c);
                Expected other = Expected.of(v, all, defaults);
                if (problems.stream().anyMatch(problem -> e.differs(other, problem))) {
                    out.put(i, e.judgedBy.get(i));
                    break;
                }
            }
        }
        return out;
    }

    /**
     * {@code IllegalStateException: step 0 has no en (MyCpu.java:42)}: located at the
     * implementation's own frame, the first one outside the JDK and this library (a
     * {@code DateTimeException} thrown by {@code LocalDate.of} is the caller's line, not
     * {@code LocalDate.java}).
     */
    static String describe(Throwable t) {
        StackTraceElement frame = ownFrame(t);
        String where = frame != null && frame.getFileName() != null
                ? " (" + frame.getFileName() + ":" + frame.getLineNumber() + ")" : "";
        return t.getClass().getSimpleName() + ": " + t.getMessage() + where;
    }

    /** Whether {@code cls} is this library's own code (by where it was loaded from, not by its package). */
    private static boolean library(String cls) {
        if (!cls.startsWith("org.plcvec.verify.")) {
            return false;
        }
        try {
            Class<?> c = Class.forName(cls, false, Judge.class.getClassLoader());
            java.security.CodeSource mine = Judge.class.getProtectionDomain().getCodeSource();
            java.security.CodeSource its = c.getProtectionDomain().getCodeSource();
            return mine != null && its != null && mine.getLocation().equals(its.getLocation());
        } catch (ClassNotFoundException | SecurityException e) {
            return false;
        }
    }

    /** The first frame of the implementation's own code (else the top frame, else null). */
    static StackTraceElement ownFrame(Throwable t) {
        StackTraceElement[] trace = t.getStackTrace();
        for (StackTraceElement e : trace) {
            String cls = e.getClassName();
            if (!(cls.startsWith("java.") || cls.startsWith("javax.") || cls.startsWith("jdk.")
                    || cls.startsWith("sun.") || cls.startsWith("com.sun.") || library(cls))) {
                return e;
            }
        }
        return trace.length > 0 ? trace[0] : null;
    }
}
