package org.plcvec.verify;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.stream.Stream;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.DynamicNode;
import org.junit.jupiter.api.DynamicTest;
import org.opentest4j.AssertionFailedError;

/**
 * JUnit 5 integration: one dynamic test per selected vector, displayed by its id, so the IDE's
 * tree, Surefire's reports and re-running one test work in the implementer's own project.
 *
 * <pre>{@code
 * class MyEmulatorConformanceTest {
 *     @TestFactory
 *     Stream<DynamicNode> plcvec() {
 *         return PlcvecTests.of(new MyEmulator())
 *                 .selection(Selection.all().families(Family.FX5_TIME_ADD))
 *                 .expectations(Path.of("src/test/resources/plcvec-known.toml"))
 *                 .stream();
 *     }
 * }
 * }</pre>
 *
 * <p>A failing vector fails its test with the field-level diff (and expected/actual for the IDE's
 * comparison view); a skipped vector or a known failure is aborted (reported as skipped, with the
 * reason); a stale known failure fails; an exception of the implementation is an error of its
 * vector. The {@code PLCVEC_*} variables ({@link Environment}) narrow the selection and set the
 * known-failures file and the bound on each vector:
 * {@code PLCVEC_ID='fx5-time-add/TADDP/*' mvn test}. An empty selection, an unknown name, or a run
 * in which nothing passes (every vector skipped or unsupported) fails: a gate never passes by
 * accident. A vector that gives no answer within {@code PLCVEC_TIMEOUT} (10 s) is an error and ends
 * the run: every vector after it is not run (an error of its test), and the end of the run says why.
 */
public final class PlcvecTests {
    private final Verifier verifier;
    private final Environment env;

    private PlcvecTests(Verifier verifier) {
        this(verifier, Environment.current());
    }

    private PlcvecTests(Verifier verifier, Environment env) {
        this.verifier = verifier;
        this.env = env;
    }

    /** The same tests under other {@code PLCVEC_*} values than this process's (for tests). */
    PlcvecTests environment(Environment env) {
        return new PlcvecTests(verifier, env);
    }

    public static PlcvecTests of(Implementation implementation) {
        return new PlcvecTests(Verifier.of(implementation));
    }

    public static PlcvecTests of(Verifier verifier) {
        return new PlcvecTests(verifier);
    }

    public PlcvecTests suite(Suite suite) {
        return new PlcvecTests(verifier.suite(suite), env);
    }

    public PlcvecTests selection(Selection selection) {
        return new PlcvecTests(verifier.selection(selection), env);
    }

    public PlcvecTests expectations(Path file) {
        return new PlcvecTests(verifier.expectations(file), env);
    }

    public PlcvecTests expectations(KnownFailures known) {
        return new PlcvecTests(verifier.expectations(known), env);
    }

    /**
     * The dynamic tests, for a {@code @TestFactory} method to return: one per selected vector,
     * named by its id, then one per stale known failure, then {@value #END} (the run's totals,
     * and a failure when nothing was tested or the run ended early).
     */
    public Stream<DynamicNode> stream() {
        FilterWatch.factoryRan = true;
        Verifier v;
        List<Vector> vectors;
        Duration timeout;
        Path write;
        try {
            v = verifier.selection(env.narrow(verifier.selection(), verifier.suite()));
            Path known = env.knownFailures();
            if (known != null) {
                v = v.expectations(known);
            }
            timeout = env.timeout();
            write = env.writeExpectations();
            vectors = v.vectors();
        } catch (VerifyException e) {
            return Stream.of(usage(e.getMessage()));
        }
        Run run = new Run(v, vectors.size(), timeout, write);
        List<DynamicNode> tests = new ArrayList<>(vectors.size() + 2);
        for (Vector vector : vectors) {
            // The test source lets an IDE open the vector's line in the vector file.
            tests.add(DynamicTest.dynamicTest(vector.id(), vector.source(), () -> verdict(run.check(vector))));
        }
        for (Verdict stale : v.knownFailures().unknownIds(v.suite())) {
            run.record(stale);
            tests.add(failing("expectations: " + stale.id(), stale.report()));
        }
        tests.add(DynamicTest.dynamicTest(END, run::end));
        return tests.stream();
    }

    /** The name of the test that ends a run. */
    public static final String END = "plcvec: end of run";

    /** A user's mistake (a name, a file, a variable): its message alone, without a stack trace. */
    private static DynamicTest usage(String message) {
        return DynamicTest.dynamicTest("plcvec: cannot run", () -> {
            throw quiet(new AssertionFailedError("plcvec: " + message));
        });
    }

    private static <T extends Throwable> T quiet(T t) {
        t.setStackTrace(new StackTraceElement[0]);
        return t;
    }

    private static DynamicTest failing(String name, String message) {
        return DynamicTest.dynamicTest(name, () -> {
            throw quiet(new AssertionFailedError(message));
        });
    }

    /**
     * What the implementation threw on a vector (or a vector it never answered): an error of the
     * test, not a failed assertion, with the implementation's own stack trace as its cause.
     */
    public static final class ImplementationError extends RuntimeException {
        private static final long serialVersionUID = 1L;

        ImplementationError(String message, Throwable cause) {
            super(message, cause);
            setStackTrace(new StackTraceElement[0]);
        }
    }

    /** Turn a verdict into the test's outcome. */
    static void verdict(Verdict r) {
        switch (r.status()) {
            case PASS:
                return;
            case SKIP:
            case XFAIL:
                Assumptions.abort(r.status().label() + ": " + r.message());
                return;
            case FAIL:
                throw quiet(new AssertionFailedError(r.report(), side(r, true), side(r, false)));
            case ERROR:
            case NOT_RUN:    // as plcvec verify's JUnit XML counts it: an error, not a failed assertion
                throw new ImplementationError(r.report(), r.cause());
            default:
                throw quiet(new AssertionFailedError(r.report()));
        }
    }

    /**
     * One run of the factory's tests: each vector on a watchdog thread bounded by
     * {@code PLCVEC_TIMEOUT}, the verdicts kept for the end of the run, and the vector in progress
     * kept for a guard that speaks if the process ends before the run does.
     */
    static final class Run {
        private final Verifier verifier;
        private final int selected;
        private final Duration timeout;
        private final Path write;
        private final List<Verdict> verdicts = Collections.synchronizedList(new ArrayList<>());
        private final long start = System.nanoTime();
        private volatile String current;     // the vector being run
        private volatile String ended;       // the vector after which the run ended, or null
        private volatile boolean finished;
        private ExecutorService worker;

        Run(Verifier verifier, int selected, Duration timeout, Path write) {
            this.verifier = verifier;
            this.selected = selected;
            this.timeout = timeout;
            this.write = write;
            ExitGuard.watch(this);
        }

        void record(Verdict r) {
            verdicts.add(r);
        }

        Verdict check(Vector vector) {
            if (ended != null) {
                Verdict notRun = new Verdict(vector.id(), vector, Status.NOT_RUN, List.of(),
                        "not run: the run ended before it", Map.of());
                verdicts.add(notRun);
                return notRun;
            }
            current = vector.id();
            Future<Verdict> answer = worker().submit(() -> verifier.check(vector));
            Verdict r;
            try {
                r = answer.get(timeout.toNanos(), TimeUnit.NANOSECONDS);
            } catch (TimeoutException e) {
                // A thread cannot be stopped safely: the stuck one is left (a daemon, so the process
                // can still end) and nothing more is run, as the implementation may be broken.
                answer.cancel(true);
                worker.shutdownNow();
                ended = vector.id();
                r = new Verdict(vector.id(), vector, Status.ERROR, List.of(), "no answer within " + seconds(timeout)
                        + " (" + Environment.TIMEOUT + "); the run ends here: the vectors after it are not run",
                        Map.of());
            } catch (ExecutionException e) {
                throw new IllegalStateException("plcvec: judging " + vector.id() + " failed", e.getCause());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("plcvec: interrupted while " + vector.id() + " ran", e);
            }
            current = null;
            verdicts.add(r);
            return r;
        }

        private ExecutorService worker() {
            if (worker == null) {
                worker = Executors.newSingleThreadExecutor(task -> {
                    Thread t = new Thread(task, "plcvec-vector");
                    t.setDaemon(true);
                    return t;
                });
            }
            return worker;
        }

        /** The last test: the totals, the expectations file, and a failure if nothing was tested. */
        void end() {
            finished = true;
            if (worker != null) {
                worker.shutdown();
            }
            List<Verdict> all;
            synchronized (verdicts) {
                all = List.copyOf(verdicts);
            }
            String aborted = ended == null ? null : ended + ": no answer within " + seconds(timeout) + " ("
                    + Environment.TIMEOUT + "); the run ended there";
            Report report = new Report(verifier.header(), all, (System.nanoTime() - start) / 1e9, aborted);
            System.out.print(report.totals());
            System.out.flush();
            if (write != null) {
                int n = report.writeExpectations(write, "not triaged yet");
                System.out.println("plcvec: " + n + " known failures written to " + write);
            }
            if (ended != null) {
                long notRun = all.stream().filter(r -> r.status() == Status.NOT_RUN).count();
                throw quiet(new AssertionFailedError("plcvec: the run ended at " + ended + ", which gave no answer within "
                        + seconds(timeout) + " (" + Environment.TIMEOUT + "); " + notRun + " vectors were not run"));
            }
            if (!report.passed() && report.failing().isEmpty()) {
                throw quiet(new AssertionFailedError("plcvec: nothing tested: " + (all.isEmpty()
                        ? "no selected vector was run (did the test runner's own filter leave them out? select "
                        + "vectors with " + Environment.ID + " instead)"
                        : "every one of the " + all.size() + " vectors run was skipped") + "; a run of nothing proves nothing"));
            }
        }

        /** Said by the exit guard when the process ends before {@link #end()}. */
        String unfinished() {
            if (finished) {
                return null;
            }
            String at = current;
            return at != null
                    ? "plcvec: the process ended while vector " + at + " was running (System.exit or a crash in the "
                    + "implementation?); " + verdicts.size() + " of " + selected + " vectors were judged, the run did not finish"
                    : null;
        }
    }

    private static String seconds(Duration d) {
        double s = d.toNanos() / 1e9;
        return (s == Math.rint(s) ? String.valueOf((long) s) : String.valueOf(s)) + " s";
    }

    /**
     * A shutdown hook that names the vector in progress when the process ends in the middle of a
     * run (an implementation calling {@code System.exit}): without it, the test runner reports only
     * that its process went away. {@code Runtime.halt} and signals run no hook; the vector's name
     * is then in the test runner's record of the test that started and never ended.
     */
    static final class ExitGuard {
        private static final List<Run> RUNS = new java.util.concurrent.CopyOnWriteArrayList<>();
        private static boolean installed;

        static synchronized void watch(Run run) {
            RUNS.add(run);
            if (!installed) {
                installed = true;
                Runtime.getRuntime().addShutdownHook(new Thread(() -> {
                    for (Run r : RUNS) {
                        String said = r.unfinished();
                        if (said != null) {
                            // The original standard error: a test runner's capture may be gone by now.
                            java.io.PrintStream err = new java.io.PrintStream(
                                    new java.io.FileOutputStream(java.io.FileDescriptor.err), true,
                                    java.nio.charset.StandardCharsets.UTF_8);
                            err.println(said);
                            System.err.println(said);
                        }
                    }
                }, "plcvec-exit-guard"));
            }
        }
    }

    /** One side of the IDE's comparison view: a line per differing field. */
    private static String side(Verdict r, boolean expected) {
        StringBuilder sb = new StringBuilder();
        for (Problem p : r.problems()) {
            String where = p.step() == Problem.WHOLE ? p.field() : "step " + p.step() + " " + p.field();
            sb.append(where).append(" = ").append(expected ? p.expected() : p.actual()).append('\n');
        }
        return sb.toString();
    }
}
