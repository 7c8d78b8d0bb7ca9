package org.plcvec.verify;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;

/**
 * The processes an implementation started during a run and left running. One that inherited the
 * test process's standard output holds it open, and Surefire waits for that output to end before
 * it reports the run: a green run would wait for the child. They are kept running as long as the
 * test process runs (another test may use them), and ended when it exits, from the exit guard.
 */
final class LeftProcesses {
    /** How long a process asked to end may take before it is killed. */
    private static final long GRACE_MS = 1000;
    private static final Set<ProcessHandle> LEFT = ConcurrentHashMap.newKeySet();

    private LeftProcesses() {
    }

    /** This process's descendants now: taken when a run starts. */
    static Set<Long> now() {
        return ProcessHandle.current().descendants().map(ProcessHandle::pid).collect(Collectors.toSet());
    }

    /** At a run's end: the descendants started since {@code before} and still running are remembered. */
    static void since(Set<Long> before) {
        ProcessHandle.current().descendants().filter(p -> !before.contains(p.pid()) && p.isAlive()).forEach(LEFT::add);
    }

    /** At the test process's exit: end what the runs left running (asked first, then killed). */
    static void end() {
        for (ProcessHandle p : LEFT) {
            if (!p.isAlive()) {
                continue;
            }
            String command = p.info().commandLine().orElse("pid " + p.pid());
            p.destroy();
            try {
                p.onExit().get(GRACE_MS, TimeUnit.MILLISECONDS);
            } catch (Exception stillRunning) {
                p.destroyForcibly();
            }
            System.err.println("plcvec: note: ended " + command + ", which the implementation started during a run and "
                    + "left running (it would hold the test run's output open)");
        }
    }
}
