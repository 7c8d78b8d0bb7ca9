package org.plcvec.reference;

import java.io.OutputStream;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

import org.junit.jupiter.api.DynamicNode;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.function.Executable;
import org.plcvec.verify.PlcvecTests;
import org.plcvec.verify.Suite;
import org.plcvec.verify.Verifier;
import org.plcvec.verify.Vector;

/**
 * How fast the Java verifier judges the golden set with the reference, in process: loading and
 * planning timed apart, then a warmed loop (the JIT compiles the hot path during the warm-up
 * passes, which are not counted), then the median of the measured samples (each a run of passes,
 * wall clock, beside the judging thread's CPU time). Every pass must judge
 * every vector a pass, or the figure is refused. The last line is the JSON object
 * {@code plcvec bench-native} reads.
 *
 * <p>Beside that figure ({@link Verifier#countFailures}, the verifier's fastest loop), in the same
 * JVM and in turn with it, sample by sample, so that each meets the same moments of a shared
 * machine: the same vectors one by one through {@link Verifier#check} (the judgement a JUnit run
 * makes, unguarded), and through {@link PlcvecTests}' dynamic tests (what a user's JUnit 5 run
 * executes: {@code check} under the per-vector bound and the exit guard), executed in order as the
 * engine executes them, without the engine. Their ratio is what the guards cost per vector.
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

        List<Vector> vectors = verifier.vectors();
        PlcvecTests guarded = PlcvecTests.of(verifier);
        int warm = 0;
        long warmStart = System.nanoTime();
        while (warm < MIN_WARM_UP_PASSES || (System.nanoTime() - warmStart) / 1e9 < WARM_UP_SECONDS) {
            check(verifier.countFailures(), n);
            if (warm % 4 == 0) {
                check(checkEach(verifier, vectors), n);
                guardedRounds(guarded, 1, n);
            }
            warm++;
        }
        double warmSeconds = (System.nanoTime() - warmStart) / 1e9;
        double[] seconds = new double[PASSES];
        double[] cpu = new double[PASSES];
        double[] checkSeconds = new double[PASSES];
        double[] guardedSeconds = new double[PASSES];
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
            s = System.nanoTime();
            failures = 0;
            for (int r = 0; r < ROUNDS; r++) {
                failures += checkEach(verifier, vectors);
            }
            checkSeconds[i] = (System.nanoTime() - s) / 1e9 / ROUNDS;
            check(failures, n);
            guardedSeconds[i] = guardedRounds(guarded, ROUNDS, n) / ROUNDS;
        }
        Arrays.sort(seconds);
        Arrays.sort(cpu);
        Arrays.sort(checkSeconds);
        Arrays.sort(guardedSeconds);
        double median = seconds[PASSES / 2];
        double rate = n / median;
        double checkRate = n / checkSeconds[PASSES / 2];
        double guardedRate = n / guardedSeconds[PASSES / 2];
        System.out.printf(Locale.ROOT, "%-52s %8s %10s %12s%n", "java verifier, golden set, in process", "vectors", "seconds",
                "vectors/s");
        System.out.printf(Locale.ROOT, "%-52s %8d %10.4f %12s%n", "load the vectors (" + suite.source() + ")", n, load, "");
        System.out.printf(Locale.ROOT, "%-52s %8d %10.4f %12s%n", "  of which CPU time of the loading thread (cold JVM)", n,
                loadCpu, "");
        System.out.printf(Locale.ROOT, "%-52s %8d %10.4f %12s%n", "plan: expectations under the alternatives", n, plan, "");
        System.out.printf(Locale.ROOT, "%-52s %8d %10.6f %,12.0f%n", "judge with the reference (median sample, per pass)", n, median, rate);
        System.out.printf(Locale.ROOT, "%-52s %8d %10.6f %,12.0f%n", "  fastest sample, per pass", n, seconds[0], n / seconds[0]);
        System.out.printf(Locale.ROOT, "%-52s %8d %10.6f %,12.0f%n", "  median sample, CPU time of the judging thread", n,
                cpu[PASSES / 2], n / cpu[PASSES / 2]);
        System.out.printf(Locale.ROOT, "%-52s %8d %10.6f %,12.0f%n", "check each vector, unguarded (median, per pass)", n,
                checkSeconds[PASSES / 2], checkRate);
        System.out.printf(Locale.ROOT, "%-52s %8d %10.6f %,12.0f%n", "  the same, guarded: PlcvecTests' dynamic tests", n,
                guardedSeconds[PASSES / 2], guardedRate);
        System.out.printf(Locale.ROOT, "%-52s %8s %10.3f%n", "  guarded / unguarded", "", guardedRate / checkRate);
        System.out.printf(Locale.ROOT, "{\"lang\": \"java\", \"vectors\": %d, \"passes\": %d, \"load_seconds\": %.4f, "
                + "\"seconds\": %.6f, \"vectors_per_s\": %.0f, \"note\": \"median of %d samples of %d passes after %d warm-up passes "
                + "(%.1f s, JIT warmed) in one JVM, wall clock; %.0f/s by the thread's CPU time; loading and planning "
                + "timed apart; check_vectors_per_s: Verifier.check on each vector; guarded_vectors_per_s: the same "
                + "through PlcvecTests (the per-vector bound and exit guard), guarded_ratio = guarded / check\", "
                + "\"check_vectors_per_s\": %.0f, \"guarded_vectors_per_s\": %.0f, \"guarded_ratio\": %.3f}%n",
                n, PASSES * ROUNDS, load + plan, median, rate, PASSES, ROUNDS, warm, warmSeconds,
                n / cpu[PASSES / 2], checkRate, guardedRate, guardedRate / checkRate);
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
     * Seconds taken by {@code rounds} passes over one run of PlcvecTests' dynamic tests, executed
     * in order as the JUnit engine does: one run (built before the clock starts, the planning
     * apart), the vectors' tests {@code rounds} times, then the run's end (after the clock stops,
     * its totals unprinted), which fails if any vector did not pass.
     */
    private static double guardedRounds(PlcvecTests tests, int rounds, int n) {
        List<Executable> vectorTests = new ArrayList<>(n);
        Executable end = null;
        for (DynamicNode node : (Iterable<DynamicNode>) tests.stream()::iterator) {
            Executable e = ((DynamicTest) node).getExecutable();
            if (node.getDisplayName().equals(PlcvecTests.END)) {
                end = e;
            } else {
                vectorTests.add(e);
            }
        }
        if (vectorTests.size() != n || end == null) {
            System.err.println("bench: PlcvecTests made " + vectorTests.size() + " vector tests, not " + n + "; no figure");
            System.exit(1);
        }
        long s = System.nanoTime();
        try {
            for (int r = 0; r < rounds; r++) {
                for (int i = 0; i < n; i++) {
                    vectorTests.get(i).execute();
                }
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
