package org.plcvec.verify;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * Runs a selection of vectors through an {@link Implementation} and judges every answer, exactly
 * as CONTRACT.md says: the contact result and every listed device after every step, with its type,
 * listed devices that must stay unchanged, and no write outside the vector.
 *
 * <pre>{@code
 * Report report = Verifier.of(new MyEmulator()).selection(Selection.all().tags(Tag.BOUNDARY)).run();
 * System.out.print(report.summary());
 * }</pre>
 *
 * <p>Immutable; the plan (the selected vectors and what each expects under the implementation's
 * alternatives) is built once, on first use.
 */
public final class Verifier {
    private final Suite suite;
    private final Implementation implementation;
    private final Selection selection;
    private final KnownFailures known;
    private volatile Plan plan;

    private Verifier(Suite suite, Implementation implementation, Selection selection, KnownFailures known) {
        this.suite = suite;
        this.implementation = implementation;
        this.selection = selection;
        this.known = known;
    }

    /** A verifier of {@code implementation} against the golden set, every vector selected. */
    public static Verifier of(Implementation implementation) {
        return new Verifier(null, implementation, Selection.all(), KnownFailures.none());
    }

    public Verifier suite(Suite suite) {
        return new Verifier(suite, implementation, selection, known);
    }

    public Verifier selection(Selection selection) {
        return new Verifier(suite, implementation, selection, known);
    }

    public Verifier expectations(KnownFailures known) {
        return new Verifier(suite, implementation, selection, known);
    }

    /** The expectations file (known failures) to apply. */
    public Verifier expectations(Path file) {
        return expectations(KnownFailures.load(file));
    }

    public Suite suite() {
        return suite != null ? suite : Suite.golden();
    }

    public Implementation implementation() {
        return implementation;
    }

    public Selection selection() {
        return selection;
    }

    public KnownFailures knownFailures() {
        return known;
    }

    /** What the run is: the selected vectors, their expectations, the alternatives followed. */
    static final class Plan {
        final List<Vector> vectors;
        final Map<String, Expected> expected = new LinkedHashMap<>();
        final Map<String, Followed> followed;
        final Expected[] expectedInOrder;   // expected, in the order of `vectors`
        final boolean[] supported;          // implementation.supports(instruction), asked once
        final Memory[] memories;            // one per vector, reused by run()
        final Map<String, String> all;      // interpretation -> the alternative followed (declared or default)
        final Map<String, String> defaults;

        Plan(Suite suite, Implementation impl, Selection selection) {
            this.vectors = selection.apply(suite);
            if (vectors.isEmpty()) {
                throw new VerifyException("the selection (" + selection + ") matches no vector of " + suite.source()
                        + "; a run of nothing proves nothing");
            }
            Choices choices = impl.choices();
            choices.validate(suite, impl.name());
            Map<String, String> defaults = new TreeMap<>();
            Map<String, String> all = new TreeMap<>();
            Map<String, Followed> followed = new TreeMap<>();
            java.util.Set<String> families = new java.util.TreeSet<>();
            vectors.forEach(v -> families.add(v.family()));
            for (Suite.InterpretationInfo i : suite.interpretations().values()) {
                defaults.put(i.id(), i.defaultAlternative());
                String declared = choices.get(i.id());
                all.put(i.id(), declared != null ? declared : i.defaultAlternative());
                if (i.families().stream().anyMatch(families::contains)) {
                    followed.put(i.id(), new Followed(all.get(i.id()), declared != null, i.families()));
                }
            }
            this.followed = Collections.unmodifiableMap(followed);
            this.all = all;
            this.defaults = defaults;
            long[] cpuWrites = impl.cpuWrites().stream().mapToLong(d -> Address.of(d).key()).toArray();
            for (Vector v : vectors) {
                expected.put(v.id(), Expected.of(v, all, defaults).cpuWrites(cpuWrites));
            }
            this.memories = new Memory[vectors.size()];
            this.expectedInOrder = vectors.stream().map(v -> expected.get(v.id())).toArray(Expected[]::new);
            this.supported = new boolean[vectors.size()];
            for (int i = 0; i < supported.length; i++) {
                supported[i] = impl.supports(vectors.get(i).instruction());
            }
        }
    }

    Plan plan() {
        Plan p = plan;
        if (p == null) {
            synchronized (this) {
                p = plan;
                if (p == null) {
                    p = new Plan(suite(), implementation, selection);
                    plan = p;
                }
            }
        }
        return p;
    }

    /** The selected vectors, in the suite's order. */
    public List<Vector> vectors() {
        return plan().vectors;
    }

    /** interpretation → the alternative followed, for every interpretation of the selected families. */
    public Map<String, Followed> followed() {
        return plan().followed;
    }

    /** What a report of this run says it was. */
    public Report.Header header() {
        return new Report.Header(suite(), implementation.name(), implementation.version(), followed(),
                implementation.cpuWrites());
    }

    /** Run one vector and judge it, known failures applied. */
    public Verdict check(Vector v) {
        Expected e = plan().expected.get(v.id());
        if (e == null) {
            throw new VerifyException("vector " + v.id() + " is not in the selection (" + selection + ")");
        }
        Verdict r = judge(v, e, null);
        known.apply(r);
        return r;
    }

    /** Run every selected vector; the report holds every result, known failures applied. */
    public Report run() {
        long start = System.nanoTime();
        Plan p = plan();
        List<Verdict> results = new ArrayList<>(p.vectors.size());
        int i = 0;
        for (Vector v : p.vectors) {
            Memory m = p.memories[i];
            if (m == null && implementation instanceof Emulator) {
                m = p.memories[i] = v.newMemory();
            }
            Verdict r = judge(v, p.expectedInOrder[i], m);
            known.apply(r);
            results.add(r);
            i++;
        }
        results.addAll(known.unknownIds(suite()));
        return new Report(header(), results, (System.nanoTime() - start) / 1e9);
    }

    /**
     * Run and judge the selected vectors without keeping results, for the benchmark: the number
     * of vectors that did not pass (0 for a conforming implementation). The same judgement as
     * {@link #run()}, without building a report.
     */
    public int countFailures() {
        Plan p = plan();
        int failures = 0;
        List<Vector> vectors = p.vectors;
        if (!(implementation instanceof Emulator)) {
            for (int i = 0, n = vectors.size(); i < n; i++) {
                if (judge(vectors.get(i), p.expectedInOrder[i], null).status() != Status.PASS) {
                    failures++;
                }
            }
            return failures;
        }
        Emulator emulator = (Emulator) implementation;
        for (int i = 0, n = vectors.size(); i < n; i++) {
            Vector v = vectors.get(i);
            Memory m = p.memories[i];
            if (m == null) {
                m = p.memories[i] = v.newMemory();
            }
            try {
                if (!p.supported[i] || !passes(emulator, v, p.expectedInOrder[i], m)) {
                    failures++;
                }
            } catch (VirtualMachineError fatal) {
                throw fatal;
            } catch (Throwable t) {
                failures++;
            }
        }
        return failures;
    }

    /** Whether the emulator passes {@code v}: the memory path, stopping at the first difference. */
    private static boolean passes(Emulator emulator, Vector v, Expected e, Memory m) throws Exception {
        m.reset(v.slots.length, v.initial);
        Emulator.Scan scan = emulator.load(v, m);
        List<Step> steps = v.steps();
        for (int s = 0, n = steps.size(); s < n; s++) {
            Step step = steps.get(s);
            step.applySet(m);
            if (!e.matches(s, m, scan.execute(step))) {
                return false;
            }
        }
        return true;
    }

    private static final List<Problem> NONE = List.of();

    private Verdict judge(Vector v, Expected e, Memory reuse) {
        if (!implementation.supports(v.instruction())) {
            return new Verdict(v.id(), v, Status.SKIP, NONE, implementation.name() + " does not support "
                    + v.instruction(), e.judgedBy);
        }
        try {
            Answer answer = implementation instanceof Emulator
                    ? runEmulator((Emulator) implementation, v, e, reuse)
                    : runContract(v, e);
            List<Problem> problems = answer.problems();
            if (problems.isEmpty()) {
                return new Verdict(v.id(), v, Status.PASS, problems, null, e.judgedBy).judged(e, null);
            }
            Map<Integer, String[]> steps = new java.util.HashMap<>();
            for (Problem p : problems) {
                if (p.step() != Problem.WHOLE) {
                    steps.computeIfAbsent(p.step(), s -> new String[] {e.inputs(s), e.operands(s)});
                }
            }
            return new Verdict(v.id(), v, Status.FAIL, problems, null, deciding(v, e, problems)).steps(steps)
                    .judged(e, answer.steps());
        } catch (SkipVector s) {
            return new Verdict(v.id(), v, Status.SKIP, NONE, s.getMessage(), e.judgedBy);
        } catch (VectorError r) {   // the implementation's own report, in its own words
            return new Verdict(v.id(), v, Status.ERROR, NONE, "the implementation reported an error: " + r.getMessage(),
                    e.judgedBy).causedBy(r);
        } catch (VirtualMachineError fatal) {
            throw fatal;
        } catch (Throwable t) {   // the implementation's failure on this vector, not the run's
            return new Verdict(v.id(), v, Status.ERROR, NONE, describe(t), e.judgedBy).causedBy(t);
        }
    }

    /**
     * What an implementation gave on one vector: the problems found and, when there are some, its
     * answer (the state after each step), which the roll-up by reading judges under other
     * alternatives.
     */
    private record Answer(List<Problem> problems, List<StepState> steps) {
    }

    private static final Answer PASSED = new Answer(NONE, null);

    /** The memory path: compare in place after each step; build problems only on a mismatch. */
    private static Answer runEmulator(Emulator emulator, Vector v, Expected e, Memory reuse) throws Exception {
        Memory m = reuse;
        if (m == null) {
            m = v.newMemory();
        } else {
            m.reset(v.slots.length, v.initial);
        }
        Emulator.Scan scan = emulator.load(v, m);
        List<Step> steps = v.steps();
        for (int s = 0, n = steps.size(); s < n; s++) {
            Step step = steps.get(s);
            step.applySet(m);
            if (!e.matches(s, m, scan.execute(step))) {
                return replay(emulator, v, e);
            }
        }
        return PASSED;
    }

    /**
     * The interpretations that decide a differing field (TEXT.md, "judged by"): I decides when the
     * vector offers an expectation that differs from the followed one in I only and differs at a
     * problem's field; each with the alternative followed.
     */
    private Map<String, String> deciding(Vector v, Expected e, List<Problem> problems) {
        List<String> touched = v.interpretations();
        if (touched.isEmpty()) {
            return Map.of();
        }
        Plan p = plan();
        List<Map<String, String>> offered = Expected.offered(v, p.defaults);
        Map<String, String> out = new TreeMap<>();
        for (String i : touched) {
            for (Map<String, String> c : offered) {
                boolean onlyI = !c.get(i).equals(e.judgedBy.get(i)) && touched.stream()
                        .allMatch(x -> x.equals(i) || c.get(x).equals(e.judgedBy.get(x)));
                if (!onlyI) {
                    continue;
                }
                Map<String, String> all = new TreeMap<>(p.all);
                all.putAll(c);
                Expected other = Expected.of(v, all, p.defaults);
                if (problems.stream().anyMatch(problem -> e.differs(other, problem))) {
                    out.put(i, e.judgedBy.get(i));
                    break;
                }
            }
        }
        return out;
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
            if (!e.matches(s, m, result)) {
                problems.addAll(e.problems(s, m, result, held));
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
            List<Problem> p = e.problems(s, st.devices(), st.result(), s == 0 ? null : states.get(s - 1).devices());
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
            Class<?> c = Class.forName(cls, false, Verifier.class.getClassLoader());
            java.security.CodeSource mine = Verifier.class.getProtectionDomain().getCodeSource();
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
