package org.plcvec.reference;

import java.io.OutputStream;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

import org.junit.jupiter.api.DynamicNode;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.function.Executable;
import org.plcvec.verify.GuardedPass;
import org.plcvec.verify.PlcvecTests;
import org.plcvec.verify.Selection;
import org.plcvec.verify.Suite;
import org.plcvec.verify.Verifier;
import org.plcvec.verify.Vector;

/**
 * How fast the Java verifier judges the golden set with the reference, in process: loading and
 * planning timed apart, then a warmed loop (the JIT compiles the hot path during the warm-up
 * passes, which are not counted), then the median of the measured samples (each a run of passes,
 * wall clock, beside the judging thread's CPU time). Every pass must judge every vector a pass,
 * or the figure is refused. The last line is the JSON object {@code plcvec bench-native} reads;
 * {@code seconds} and {@code vectors_per_s} are that figure ({@link Verifier#countFailures}, the
 * verifier's fastest loop).
 *
 * <p>Then what the per-vector bound and the exit guard cost, by passes paired in this JVM (on a
 * shared machine a figure taken a minute apart moves by a third; passes back to back meet the
 * same moment). Each of {@value #PAIRS} iterations makes, each timed on its own, the order
 * reversed every other iteration:
 * <ul>
 * <li>an unguarded pass: {@link Verifier#check} on each vector in turn, the judgement a JUnit run
 * makes, with nothing around it;
 * <li>a guarded pass: the same judging between the entry and exit points of the library's own
 * guard ({@code GuardedPass}: a fresh {@code PlcvecTests} run, the watchdog and exit
 * guard, under {@code PLCVEC_TIMEOUT}), nothing else;
 * <li>a pass of the dynamic tests: a fresh run of {@link PlcvecTests}' tests, the vectors' tests
 * executed in order as the JUnit engine executes them, without the engine: the guard plus what
 * the test adds per vector (keeping the verdict for the end of the run, turning it into the test's
 * outcome). The tests are made before the clock starts and the end-of-run test runs after it
 * stops (once per run, not per vector).
 * </ul>
 * The keys, named as the Go bench names them: {@code guarded_ratio}, the median over iterations
 * of unguarded seconds / guarded seconds (1: the guard costs nothing); {@code
 * guarded_ratio_fastest}, the fastest unguarded pass / the fastest guarded pass; {@code
 * guarded_ratio_per_vector}, the median of unguarded / (guarded - {@code guard_fixed_seconds}),
 * where {@code guard_fixed_seconds} is what a run pays once (handing itself to the watchdog with
 * its first vector; the watchdog's thread is the process's, started once, in the warm-up): the
 * median, over as many paired iterations over ONE vector, of the guarded pass less the unguarded
 * pass. {@code guarded_tests_ratio}, {@code guarded_tests_ratio_fastest}, {@code
 * guarded_tests_ratio_per_vector} and {@code guarded_tests_fixed_seconds}: the same for the
 * dynamic tests. {@code unguarded_loop_vectors_per_s} (also {@code check_vectors_per_s}, its
 * earlier name), {@code guarded_vectors_per_s}, {@code guarded_tests_vectors_per_s}: vectors / the
 * median pass of each.
 */
public final class Bench {
    private static final double WARM_UP_SECONDS = 3.0;
    private static final int MIN_WARM_UP_PASSES = 200;
    /** Measured samples, each {@link #ROUNDS} passes over the golden set. */
    private static final int PASSES = 21;
    /**
     * Passes per sample: about 50 ms of work, so that a sample on a busy machine holds its share
     * of preemption as the Python figure's passes (a few hundred ms each) do: like for like.
     */
    private static final int ROUNDS = 20;
    /** Warm-up iterations of the paired passes, each an unguarded, a guarded and a tests pass. */
    private static final int PAIRED_WARM_UP = MIN_WARM_UP_PASSES / 2;
    /** Paired iterations (an unguarded, a guarded and a tests pass each): a few seconds. */
    private static final int PAIRS = 200;

    private Bench() {
    }

    public static void main(String[] args) {
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        boolean cpuTime = threads.isCurrentThreadCpuTimeSupported();
        long c0 = cpuTime ? threads.getCurrentThreadCpuTime() : 0;
        long t0 = System.nanoTime();
        Suite suite = Suite.golden();
        double load = (System.nanoTime() - t0) / 1e9;
        double loadCpu = cpuTime ? (threads.getCurrentThreadCpuTime() - c0) / 1e9 : Double.NaN;
        t0 = System.nanoTime();
        Verifier verifier = Verifier.of(new Reference()).suite(suite);
        int n = verifier.vectors().size();
        double plan = (System.nanoTime() - t0) / 1e9;

        Passes all = new Passes(verifier);
        // One vector, for what a run pays once: its own verifier, planned before any clock.
        Passes one = new Passes(verifier.selection(Selection.all().ids(verifier.vectors().get(0).id())));
        if (one.vectors.size() != 1) {
            System.err.println("bench: the first vector's id selects " + one.vectors.size() + " vectors; no figure");
            System.exit(1);
        }
        // The figure's own loop is warmed alone, as every earlier release's bench warmed it: passes of
        // other loops mixed into its warm-up change what the JIT learns of the reference's call
        // sites, and the figure then fell into one of two speeds a third apart from run to run.
        int warm = 0;
        long warmStart = System.nanoTime();
        while (warm < MIN_WARM_UP_PASSES || (System.nanoTime() - warmStart) / 1e9 < WARM_UP_SECONDS) {
            check(verifier.countFailures(), n);
            warm++;
        }
        double warmSeconds = (System.nanoTime() - warmStart) / 1e9;
        double[] seconds = new double[PASSES];
        double[] cpu = new double[PASSES];
        for (int i = 0; i < PASSES; i++) {
            long c = cpuTime ? threads.getCurrentThreadCpuTime() : 0;
            long s = System.nanoTime();
            int failures = 0;
            for (int r = 0; r < ROUNDS; r++) {
                failures += verifier.countFailures();
            }
            seconds[i] = (System.nanoTime() - s) / 1e9 / ROUNDS;
            cpu[i] = cpuTime ? (threads.getCurrentThreadCpuTime() - c) / 1e9 / ROUNDS : Double.NaN;
            check(failures, n);
        }
        Arrays.sort(seconds);
        Arrays.sort(cpu);

        // The paired passes' warm-up, after the figure is taken: as many of each as before.
        for (int i = 0; i < PAIRED_WARM_UP; i++) {
            all.time(i % 2 == 0);
            one.time(i % 2 == 0);
        }
        // What a run pays once first (it is taken off every guarded pass), then the full passes.
        double[][] onePass = new double[3][PAIRS];
        double[][] allPass = new double[3][PAIRS];
        for (int i = 0; i < PAIRS; i++) {
            double[] t = one.time(i % 2 == 0);
            for (int k = 0; k < 3; k++) {
                onePass[k][i] = t[k];
            }
        }
        for (int i = 0; i < PAIRS; i++) {
            double[] t = all.time(i % 2 == 0);
            for (int k = 0; k < 3; k++) {
                allPass[k][i] = t[k];
            }
        }
        print(new Measured(n, suite.source(), load, loadCpu, plan, seconds, cpu, warm, warmSeconds, onePass, allPass));
    }

    /** What main measured, for {@link #print}. */
    private record Measured(int n, String source, double load, double loadCpu, double plan, double[] seconds, double[] cpu,
                            int warm, double warmSeconds, double[][] onePass, double[][] allPass) {
    }

    /** The table a person reads, then the JSON object bench-native reads. */
    private static void print(Measured m) {
        int n = m.n();
        double load = m.load();
        double loadCpu = m.loadCpu();
        double plan = m.plan();
        double[] seconds = m.seconds();
        double[] cpu = m.cpu();
        int warm = m.warm();
        double warmSeconds = m.warmSeconds();
        double[][] onePass = m.onePass();
        double[][] allPass = m.allPass();
        Figure guard = new Figure(allPass[0], allPass[1], onePass[0], onePass[1]);
        Figure tests = new Figure(allPass[0], allPass[2], onePass[0], onePass[2]);
        double median = seconds[PASSES / 2];
        double rate = n / median;
        double checkRate = n / median(allPass[0]);
        String row = "%-58s %8d %10.6f %,12.0f%n";
        String ratioRow = "%-58s %8s %10.3f%n";
        System.out.printf(Locale.ROOT, "%-58s %8s %10s %12s%n", "java verifier, golden set, in process", "vectors", "seconds",
                "vectors/s");
        System.out.printf(Locale.ROOT, "%-58s %8d %10.4f %12s%n", "load the vectors (" + m.source() + ")", n, load, "");
        System.out.printf(Locale.ROOT, "%-58s %8d %10.4f %12s%n", "  of which CPU time of the loading thread (cold JVM)", n,
                loadCpu, "");
        System.out.printf(Locale.ROOT, "%-58s %8d %10.4f %12s%n", "plan: expectations under the alternatives", n, plan, "");
        System.out.printf(Locale.ROOT, row, "judge with the reference (median sample, per pass)", n, median, rate);
        System.out.printf(Locale.ROOT, row, "  fastest sample, per pass", n, seconds[0], n / seconds[0]);
        System.out.printf(Locale.ROOT, row, "  median sample, CPU time of the judging thread", n, cpu[PASSES / 2],
                n / cpu[PASSES / 2]);
        System.out.printf(Locale.ROOT, "paired passes, %d iterations, median pass:%n", PAIRS);
        System.out.printf(Locale.ROOT, row, "  Verifier.check on each vector, unguarded", n, median(allPass[0]), checkRate);
        System.out.printf(Locale.ROOT, row, "  the same under the guard (bound and exit guard)", n, guard.median, n / guard.median);
        System.out.printf(Locale.ROOT, ratioRow, "    unguarded / guarded, median of pairs", "", guard.ratio);
        System.out.printf(Locale.ROOT, ratioRow, "    fastest unguarded / fastest guarded", "", guard.fastest);
        System.out.printf(Locale.ROOT, "%-58s %8d %10.7f%n", "    once per run (handed to the watchdog)", 1, guard.fixed);
        System.out.printf(Locale.ROOT, ratioRow, "    per vector (that taken off), median of pairs", "", guard.perVector);
        System.out.printf(Locale.ROOT, row, "  PlcvecTests' dynamic tests (the guard and the test's work)", n, tests.median,
                n / tests.median);
        System.out.printf(Locale.ROOT, ratioRow, "    unguarded / tests, median of pairs", "", tests.ratio);
        System.out.printf(Locale.ROOT, ratioRow, "    fastest unguarded / fastest tests", "", tests.fastest);
        System.out.printf(Locale.ROOT, "%-58s %8d %10.7f%n", "    once per run (handed to the watchdog)", 1, tests.fixed);
        System.out.printf(Locale.ROOT, ratioRow, "    per vector (that taken off), median of pairs", "", tests.perVector);
        System.out.printf(Locale.ROOT, "{\"lang\": \"java\", \"vectors\": %d, \"passes\": %d, \"load_seconds\": %.4f, "
                + "\"seconds\": %.6f, \"vectors_per_s\": %.0f, \"note\": \"median of %d samples of %d passes after %d warm-up passes "
                + "(%.1f s, JIT warmed) in one JVM, wall clock; %.0f/s by the thread's CPU time; loading and planning "
                + "timed apart. Then %d paired iterations, each an unguarded pass (Verifier.check on each vector), a guarded pass "
                + "(the same between the entry and exit of the library's per-vector bound and exit guard) and a pass of "
                + "PlcvecTests' dynamic tests (the guard and the test's own work), order reversed every other iteration: "
                + "*_vectors_per_s from each median pass; guarded_ratio (guarded_tests_ratio) the median of unguarded / "
                + "guarded seconds, *_fastest of the fastest passes; guard_fixed_seconds (guarded_tests_fixed_seconds), paid "
                + "once per run, the median guarded less unguarded pass over one vector, taken off in *_per_vector\", "
                + "\"unguarded_loop_vectors_per_s\": %.0f, \"check_vectors_per_s\": %.0f, \"guarded_vectors_per_s\": %.0f, "
                + "\"guarded_ratio\": %.3f, \"guarded_ratio_fastest\": %.3f, \"guarded_ratio_per_vector\": %.3f, "
                + "\"guard_fixed_seconds\": %.7f, \"guarded_tests_vectors_per_s\": %.0f, \"guarded_tests_ratio\": %.3f, "
                + "\"guarded_tests_ratio_fastest\": %.3f, \"guarded_tests_ratio_per_vector\": %.3f, "
                + "\"guarded_tests_fixed_seconds\": %.7f}%n",
                n, PASSES * ROUNDS, load + plan, median, rate, PASSES, ROUNDS, warm, warmSeconds, n / cpu[PASSES / 2], PAIRS,
                checkRate, checkRate, n / guard.median, guard.ratio, guard.fastest, guard.perVector, guard.fixed,
                n / tests.median, tests.ratio, tests.fastest, tests.perVector, tests.fixed);
    }

    /** The three passes over one selection: unguarded, under the guard, through the dynamic tests. */
    private static final class Passes {
        final Verifier verifier;
        final List<Vector> vectors;
        final PlcvecTests tests;

        Passes(Verifier verifier) {
            this.verifier = verifier;
            this.vectors = verifier.vectors();
            this.tests = PlcvecTests.of(verifier);
        }

        /** Seconds of each pass (unguarded, guarded, tests), in this order or the reverse. */
        double[] time(boolean forward) {
            double[] t = new double[3];
            for (int j = 0; j < 3; j++) {
                int k = forward ? j : 2 - j;
                t[k] = k == 0 ? timedCheck(verifier, vectors) : k == 1 ? timedGuard(verifier, vectors) : timedTests(tests,
                        vectors.size());
            }
            return t;
        }
    }

    /** A guarded figure against the unguarded passes paired with it. */
    private static final class Figure {
        final double median;
        final double fixed;
        final double ratio;
        final double perVector;
        final double fastest;

        Figure(double[] unguarded, double[] guarded, double[] unguardedOne, double[] guardedOne) {
            double[] extra = new double[guardedOne.length];
            for (int i = 0; i < extra.length; i++) {
                extra[i] = guardedOne[i] - unguardedOne[i];
            }
            fixed = median(extra);
            double[] ratios = new double[unguarded.length];
            double[] perVectorRatios = new double[unguarded.length];
            for (int i = 0; i < ratios.length; i++) {
                ratios[i] = unguarded[i] / guarded[i];
                perVectorRatios[i] = unguarded[i] / (guarded[i] - fixed);
            }
            median = median(guarded);
            ratio = median(ratios);
            perVector = median(perVectorRatios);
            fastest = min(unguarded) / min(guarded);
        }
    }

    private static double median(double[] xs) {
        double[] sorted = xs.clone();
        Arrays.sort(sorted);
        return sorted[sorted.length / 2];
    }

    private static double min(double[] xs) {
        return Arrays.stream(xs).min().orElseThrow();
    }

    /** Seconds taken by Verifier.check on each vector in turn; no figure unless every one passes. */
    private static double timedCheck(Verifier verifier, List<Vector> vectors) {
        long s = System.nanoTime();
        int failures = checkEach(verifier, vectors);
        double seconds = (System.nanoTime() - s) / 1e9;
        check(failures, vectors.size());
        return seconds;
    }

    /** Seconds taken by the same judging under the library's guard; no figure unless every vector passes. */
    private static double timedGuard(Verifier verifier, List<Vector> vectors) {
        double seconds = GuardedPass.seconds(verifier, vectors);
        if (seconds < 0) {
            System.err.println("bench: the reference did not pass a guarded vector; no figure");
            System.exit(1);
        }
        return seconds;
    }

    /** Verifier.check on each vector in turn: the number that did not pass. */
    private static int checkEach(Verifier verifier, List<Vector> vectors) {
        int failures = 0;
        for (int i = 0, k = vectors.size(); i < k; i++) {
            if (verifier.check(vectors.get(i)).status() != org.plcvec.verify.Status.PASS) {
                failures++;
            }
        }
        return failures;
    }

    /**
     * Seconds taken by the vectors' tests of a fresh run of PlcvecTests' dynamic tests, executed in
     * order as the JUnit engine does: the run (its tests made before the clock starts), the
     * vectors' tests, then the run's end (after the clock stops, its totals unprinted), which
     * fails if any vector did not pass.
     */
    private static double timedTests(PlcvecTests tests, int n) {
        Executable[] vectorTests = new Executable[n];
        int k = 0;
        Executable end = null;
        for (DynamicNode node : (Iterable<DynamicNode>) tests.stream()::iterator) {
            Executable e = ((DynamicTest) node).getExecutable();
            if (node.getDisplayName().equals(PlcvecTests.END)) {
                end = e;
            } else if (k < n) {
                vectorTests[k++] = e;
            } else {
                k++;
            }
        }
        if (k != n || end == null) {
            System.err.println("bench: PlcvecTests made " + k + " vector tests, not " + n + "; no figure");
            System.exit(1);
        }
        long s = System.nanoTime();
        try {
            for (int i = 0; i < n; i++) {
                vectorTests[i].execute();
            }
        } catch (Throwable t) {
            System.err.println("bench: the reference did not pass a guarded vector test: " + t.getMessage() + "; no figure");
            System.exit(1);
        }
        double seconds = (System.nanoTime() - s) / 1e9;
        PrintStream out = System.out;
        System.setOut(new PrintStream(OutputStream.nullOutputStream()));
        try {
            end.execute();
        } catch (Throwable t) {
            System.setOut(out);
            System.err.println("bench: the guarded run did not pass: " + t.getMessage() + "; no figure");
            System.exit(1);
        } finally {
            System.setOut(out);
        }
        return seconds;
    }

    private static void check(int failures, int n) {
        if (failures != 0) {
            System.err.println("bench: the reference did not pass the golden set (" + failures + " of " + n
                    + " vectors); no figure");
            System.exit(1);
        }
    }
}
