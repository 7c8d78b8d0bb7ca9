package org.plcvec.verify;

import java.util.List;

/**
 * For the benchmark ({@code org.plcvec.reference.Bench}): the library's own per-vector guard
 * around the same judging as an unguarded pass, and nothing else. A run of {@link PlcvecTests}
 * ({@code PlcvecTests.Run}: the process's watchdog and the exit guard, and the bound of
 * {@code PLCVEC_TIMEOUT}) is made before the clock starts; each vector is then judged by
 * {@link Verifier#check} between the guard's entry and exit points, as a dynamic test judges it,
 * without the dynamic test's own work (keeping the verdict for the end of the run, turning it into
 * the test's outcome). Kept with the tests, in the library's package, because the guard's entry
 * points are not public API.
 */
public final class GuardedPass {
    private GuardedPass() {
    }

    /**
     * Seconds taken by one guarded pass over {@code vectors} (a fresh run, handed to the watchdog
     * with its first vector, as in a user's run), or -1 if a vector did not pass (or was not run).
     */
    public static double seconds(Verifier verifier, List<Vector> vectors) {
        PlcvecTests.Run run = new PlcvecTests.Run(verifier, vectors, Environment.current().timeout(), null,
                PlcvecTests.Run::endProcess);
        int failures = 0;
        long s = System.nanoTime();
        for (int i = 0, n = vectors.size(); i < n; i++) {
            if (!run.enter(i)) {
                failures++;
                break;
            }
            Verdict r = verifier.check(vectors.get(i));
            run.leave();
            if (r.status() != Status.PASS) {
                failures++;
            }
        }
        double seconds = (System.nanoTime() - s) / 1e9;
        run.stop();
        return failures == 0 ? seconds : -1;
    }
}
