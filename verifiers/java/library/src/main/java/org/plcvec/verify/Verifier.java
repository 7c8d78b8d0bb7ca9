package org.plcvec.verify;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

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

    /**
     * A verifier of {@code implementation} against the golden set, every vector selected.
     *
     * @param implementation the implementation under test
     * @return the verifier
     */
    public static Verifier of(Implementation implementation) {
        return new Verifier(null, implementation, Selection.all(), KnownFailures.none());
    }

    /**
     * The same verifier over other vectors.
     *
     * @param suite the vectors
     * @return the new verifier
     */
    public Verifier suite(Suite suite) {
        return new Verifier(suite, implementation, selection, known);
    }

    /**
     * The same verifier over part of the vectors.
     *
     * @param selection the vectors to run
     * @return the new verifier
     */
    public Verifier selection(Selection selection) {
        return new Verifier(suite, implementation, selection, known);
    }

    /**
     * The same verifier with known failures.
     *
     * @param known the known failures
     * @return the new verifier
     */
    public Verifier expectations(KnownFailures known) {
        return new Verifier(suite, implementation, selection, known);
    }

    /**
     * The same verifier with the known failures of an expectations file.
     *
     * @param file the TOML file
     * @return the new verifier
     * @throws VerifyException when the file cannot be read
     */
    public Verifier expectations(Path file) {
        return expectations(KnownFailures.load(file));
    }

    /**
     * The vectors judged.
     *
     * @return the suite given, else the golden set
     */
    public Suite suite() {
        return suite != null ? suite : Suite.golden();
    }

    /** Whether a suite was given ({@link #suite(Suite)}), rather than the golden set by default. */
    boolean hasSuite() {
        return suite != null;
    }

    /**
     * The implementation under test.
     *
     * @return the implementation
     */
    public Implementation implementation() {
        return implementation;
    }

    /**
     * The vectors to run.
     *
     * @return the selection
     */
    public Selection selection() {
        return selection;
    }

    /**
     * The known failures applied.
     *
     * @return the known failures
     */
    public KnownFailures knownFailures() {
        return known;
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

    /**
     * The selected vectors, in the suite's order.
     *
     * @return the vectors
     * @throws VerifyException when the selection matches nothing or names what the suite lacks
     */
    public List<Vector> vectors() {
        return plan().vectors;
    }

    /**
     * The alternative followed for every interpretation of the selected families.
     *
     * @return interpretation to what is followed
     */
    public Map<String, Followed> followed() {
        return plan().followed;
    }

    /**
     * What a report of this run says it was.
     *
     * @return the header
     */
    public Report.Header header() {
        return new Report.Header(suite(), implementation.name(), implementation.version(), followed(),
                implementation.cpuWrites(), known == KnownFailures.none() ? "" : known.path());
    }

    /**
     * Run one vector and judge it, known failures applied.
     *
     * @param v a selected vector
     * @return its verdict
     * @throws VerifyException when the vector is not selected
     */
    public Verdict check(Vector v) {
        Expected e = plan().expected.get(v.id());
        if (e == null) {
            throw new VerifyException("vector " + v.id() + " is not in the selection (" + selection + ")");
        }
        Verdict r = plan().judge.judge(v, e, null);
        known.apply(r);
        return r;
    }

    /** What {@code v} expects under the alternatives this run follows, or null when it is not selected. */
    Expected expected(Vector v) {
        return plan().expected.get(v.id());
    }

    /**
     * Run every selected vector; the report holds every verdict, known failures applied.
     *
     * @return the report
     */
    public Report run() {
        Environment.current().warn();
        long start = System.nanoTime();
        Plan p = plan();
        List<Verdict> results = new ArrayList<>(p.vectors.size());
        int i = 0;
        for (Vector v : p.vectors) {
            Memory m = p.memories[i];
            if (m == null && implementation instanceof Emulator) {
                m = p.memories[i] = v.newMemory();
            }
            Verdict r = p.judge.judge(v, p.expectedInOrder[i], m);
            known.apply(r);
            results.add(r);
            i++;
        }
        results.addAll(known.unknownIds(suite()));
        return new Report(header(), results, (System.nanoTime() - start) / 1e9);
    }

    /**
     * Run and judge the selected vectors without keeping verdicts, for the benchmark. The same
     * judgement as {@link #run()}, without building a report.
     *
     * @return the number of vectors that did not pass (0 for a conforming implementation)
     */
    public int countFailures() {
        Plan p = plan();
        int failures = 0;
        List<Vector> vectors = p.vectors;
        if (!(implementation instanceof Emulator)) {
            for (int i = 0, n = vectors.size(); i < n; i++) {
                if (p.judge.judge(vectors.get(i), p.expectedInOrder[i], null).status() != Status.PASS) {
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
                m.reset(v.slots.length, v.initial);
                if (!p.supported[i] || !Judge.passes(emulator, v, p.expectedInOrder[i], m)) {
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
}
