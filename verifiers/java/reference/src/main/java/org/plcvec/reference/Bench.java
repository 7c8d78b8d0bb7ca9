package org.plcvec.reference;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import java.util.Locale;

import org.plcvec.verify.Suite;
import org.plcvec.verify.Verifier;

/**
 * How fast the Java verifier judges the golden set with the reference, in process: loading and
 * planning timed apart, then a warmed loop (the JIT compiles the hot path during the warm-up
 * passes, which are not counted), then the median of the measured samples (each a run of passes,
 * wall clock, beside the judging thread's CPU time). Every pass must judge
 * every vector a pass, or the figure is refused. The last line is the JSON object
 * {@code plcvec bench-native} reads.
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

        int warm = 0;
        long warmStart = System.nanoTime();
        while (warm < MIN_WARM_UP_PASSES || (System.nanoTime() - warmStart) / 1e9 < WARM_UP_SECONDS) {
            check(verifier.countFailures(), n);
            warm++;
        }
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
        double median = seconds[PASSES / 2];
        double rate = n / median;
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
        System.out.printf(Locale.ROOT, "{\"lang\": \"java\", \"vectors\": %d, \"passes\": %d, \"load_seconds\": %.4f, "
                + "\"seconds\": %.6f, \"vectors_per_s\": %.0f, \"note\": \"median of %d samples of %d passes after %d warm-up passes "
                + "(%.1f s, JIT warmed) in one JVM, wall clock; %.0f/s by the thread's CPU time; loading and planning "
                + "timed apart\"}%n",
                n, PASSES * ROUNDS, load + plan, median, rate, PASSES, ROUNDS, warm, (System.nanoTime() - warmStart) / 1e9 - sum(seconds),
                n / cpu[PASSES / 2]);
    }

    private static double sum(double[] xs) {
        double s = 0;
        for (double x : xs) {
            s += x;
        }
        return s;
    }

    private static void check(int failures, int n) {
        if (failures != 0) {
            System.err.println("bench: the reference did not pass the golden set (" + failures + " of " + n
                    + " vectors); no figure");
            System.exit(1);
        }
    }
}
