package org.plcvec.verify;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Consumer;
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
 * accident. A vector that gives no answer within {@code PLCVEC_TIMEOUT} (10 s) ends the run: its
 * error, the run's totals (every vector after it not run) and why it ended are written to standard
 * error, and the process ends with status 1, which fails the build. The vectors run on the test's
 * own thread, and a thread that never returns cannot be stopped: a watchdog thread, one per
 * process, sees that a run's vector in progress has not changed for the bound.
 */
public final class PlcvecTests {
    /**
     * Set when a factory's tests are built in this process, for {@link FilterWatch}. Kept here, not
     * there: FilterWatch is a launcher listener, and these tests are built where no launcher is.
     */
    static volatile boolean factoryRan;

    private final Verifier verifier;
    /** The settings given ({@link #environment}), or null for this process's, read anew by each run. */
    private final Environment env;
    private final Consumer<String> timedOut;

    private PlcvecTests(Verifier verifier) {
        this(verifier, null, Run::endProcess);
    }

    private PlcvecTests(Verifier verifier, Environment env, Consumer<String> timedOut) {
        this.verifier = verifier;
        this.env = env;
        this.timedOut = timedOut;
    }

    /**
     * The same tests under these settings instead of this process's {@code PLCVEC_*} variables:
     * for a test that pins its settings, or one process that runs several configurations. The
     * vectors are then {@code PLCVEC_VECTORS} of {@code env} (else the copy in this jar), unless
     * {@link #suite(Suite)} names others.
     *
     * @param env the settings, e.g. {@code Environment.of(Map.of("PLCVEC_FAMILY", "fx5-time-add"))}
     * @return the same tests under {@code env}
     */
    public PlcvecTests environment(Environment env) {
        return new PlcvecTests(verifier, env, timedOut);
    }

    /**
     * The same tests, with what the watchdog says when a vector outlives the bound handed to
     * {@code timedOut} instead of written to standard error before the process ends (for tests).
     */
    PlcvecTests onTimeout(Consumer<String> timedOut) {
        return new PlcvecTests(verifier, env, timedOut);
    }

    /**
     * The tests of an implementation against the golden set, every vector selected.
     *
     * @param implementation the implementation under test
     * @return its tests
     */
    public static PlcvecTests of(Implementation implementation) {
        return new PlcvecTests(Verifier.of(implementation));
    }

    /**
     * The tests a verifier describes (its suite, selection and known failures).
     *
     * @param verifier the verifier
     * @return its tests
     */
    public static PlcvecTests of(Verifier verifier) {
        return new PlcvecTests(verifier);
    }

    /**
     * The same tests over other vectors than the golden set.
     *
     * @param suite the vectors
     * @return the same tests over {@code suite}
     */
    public PlcvecTests suite(Suite suite) {
        return new PlcvecTests(verifier.suite(suite), env, timedOut);
    }

    /**
     * The same tests over part of the vectors ({@code PLCVEC_*} narrows it further).
     *
     * @param selection the vectors to run
     * @return the same tests over {@code selection}
     */
    public PlcvecTests selection(Selection selection) {
        return new PlcvecTests(verifier.selection(selection), env, timedOut);
    }

    /**
     * The same tests with a known-failures file ({@code PLCVEC_KNOWN_FAILURES} names another).
     *
     * @param file the TOML file
     * @return the same tests with those known failures
     * @throws VerifyException when the file cannot be read
     */
    public PlcvecTests expectations(Path file) {
        return new PlcvecTests(verifier.expectations(file), env, timedOut);
    }

    /**
     * The same tests with these known failures ({@code PLCVEC_KNOWN_FAILURES} names another file).
     *
     * @param known the known failures
     * @return the same tests with them
     */
    public PlcvecTests expectations(KnownFailures known) {
        return new PlcvecTests(verifier.expectations(known), env, timedOut);
    }

    /**
     * The dynamic tests, for a {@code @TestFactory} method to return: one per selected vector,
     * named by its id, then one per stale known failure, then {@value #END} (the run's totals,
     * and a failure when nothing passed or the run ended early).
     *
     * @return the tests, in run order
     */
    public Stream<DynamicNode> stream() {
        factoryRan = true;
        Environment settings = env != null ? env : Environment.current();
        settings.warn();
        Run run;
        try {
            run = plan(settings);
        } catch (VerifyException e) {
            return Stream.of(usage(e.getMessage()));
        }
        List<Vector> vectors = run.vectors;
        List<DynamicNode> tests = new ArrayList<>(vectors.size() + 2);
        for (int i = 0; i < vectors.size(); i++) {
            Vector vector = vectors.get(i);
            int index = i;
            // The test source lets an IDE open the vector's line in the vector file.
            tests.add(DynamicTest.dynamicTest(vector.id(), vector.source(), () -> verdict(run.check(vector, index))));
        }
        for (Verdict stale : run.verifier.knownFailures().unknownIds(run.verifier.suite())) {
            run.record(stale);
            tests.add(failing("expectations: " + stale.id(), stale.report()));
        }
        tests.add(DynamicTest.dynamicTest(END, run::end));
        return tests.stream();
    }

    /**
     * The run these settings make: the vectors ({@code PLCVEC_VECTORS} of the environment unless a
     * suite was given), the selection narrowed by the environment, the known failures, the bound on
     * each vector and the file to write the failures to, each refused here, before any vector runs.
     */
    private Run plan(Environment env) {
        Verifier v = verifier.hasSuite() ? verifier : verifier.suite(this.env == null ? Suite.golden() : env.suite());
        Selection narrowed = env.narrow(v.selection(), v.suite());
        // Narrowed by nothing: the same verifier, and the plan it may have made already.
        v = narrowed == v.selection() ? v : v.selection(narrowed);
        Path known = env.knownFailures();
        if (known != null) {
            v = v.expectations(known);
        }
        Duration timeout = env.timeout();
        Path write = env.writeExpectations();
        if (write != null) {
            try {
                KnownFailures.checkWritable(write);
            } catch (VerifyException e) {
                throw new VerifyException(Environment.WRITE_EXPECTATIONS + "=" + write + ": " + e.getMessage());
            }
        }
        return new Run(v, v.vectors(), timeout, write, timedOut);
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
     * One run of the factory's tests: each vector on the test's own thread, watched by the
     * process's watchdog thread ({@link Watchdog}), which ends the process when a vector outlives
     * {@code PLCVEC_TIMEOUT}; the verdicts kept for the end of the run, and the vector in progress
     * kept for a guard that speaks if the process ends before the run does.
     */
    static final class Run {
        private final Verifier verifier;
        private final List<Vector> vectors;
        private final Duration timeout;
        private final Path write;
        private final Consumer<String> timedOut;
        private final List<Verdict> verdicts;
        private final long start = System.nanoTime();
        /**
         * The watchdog's view, one word written twice per vector with no fence (a clock read per
         * vector would cost more than the rest of the guard): the vectors started so far, times
         * 2^32, plus 1 + the index of the vector in progress (0 between vectors).
         */
        private final AtomicLong beat = new AtomicLong();
        private long started;                // vectors started (the test thread's own count)
        private volatile String ended;       // the vector after which the run ended, or null
        private volatile boolean finished;
        private boolean watched;             // handed to the watchdog (on the run's first vector)
        /** The bound, and how often the watchdog looks: every eighth of the bound, 10 ms to 1 s. */
        final long bound;
        final long tick;
        private final java.util.Set<Long> processes;   // this process's descendants when the run started
        private long seen = -1;              // the watchdog's own: the beat it saw last, and since when
        private long since;

        Run(Verifier verifier, List<Vector> vectors, Duration timeout, Path write, Consumer<String> timedOut) {
            this.verifier = verifier;
            this.vectors = vectors;
            this.timeout = timeout;
            this.write = write;
            this.timedOut = timedOut;
            this.bound = timeout.toNanos();
            this.tick = Math.max(10_000_000L, Math.min(1_000_000_000L, bound / 8));
            // Room for every vector's verdict and a stale known failure or two: no growth mid-run.
            this.verdicts = Collections.synchronizedList(new ArrayList<>(vectors.size() + 8));
            ExitGuard.watch(this);
            this.processes = LeftProcesses.now();
        }

        void record(Verdict r) {
            verdicts.add(r);
        }

        Verdict check(Vector vector, int index) {
            if (!enter(index)) {
                Verdict notRun = notRun(vector);
                verdicts.add(notRun);
                return notRun;
            }
            Verdict r = verifier.check(vector);
            leave();
            verdicts.add(r);
            return r;
        }

        /**
         * The guard's entry: vector {@code index} is in progress from now on, unless the run has
         * ended (false: it is not to be run). One read and one store without a fence; no
         * allocation, no clock, no handoff (the process's watchdog, given the run with its first
         * vector, reads the word on its own tick).
         */
        boolean enter(int index) {
            if (ended != null) {
                return false;
            }
            if (!watched) {
                watched = true;
                Watchdog.watch(this);
            }
            started++;
            beat.lazySet(started << 32 | (index + 1));
            return true;
        }

        /** The guard's exit: the vector in progress has its verdict; none is in progress. */
        void leave() {
            beat.lazySet(started << 32);
        }

        /**
         * The run is over: the watchdog and the exit guard forget it (a process that makes many
         * runs keeps none of them).
         */
        void stop() {
            LeftProcesses.since(processes);
            finished = true;
            Watchdog.forget(this);
            ExitGuard.forget(this);
        }

        private Verdict notRun(Vector vector) {
            return Judge.verdict(vector, verifier.expected(vector), Status.NOT_RUN, "not run: the run ended before it");
        }

        /**
         * The watchdog's look at the run, at {@code now}: whether the same vector has been in
         * progress for the bound; if so, the run ends there (false: the run is not to be watched
         * any more).
         */
        boolean look(long now) {
            if (finished) {
                return false;
            }
            long b = beat.get();
            if (b != seen) {
                seen = b;
                since = now;
            } else if ((b & 0xffff_ffffL) != 0 && now - since >= bound && !finished) {
                timedOut.accept(timedOutText((int) (b & 0xffff_ffffL) - 1));
                return false;
            }
            return true;
        }

        /**
         * What the run says when vector {@code index} outlived the bound: the vector's error, the
         * end of the run's text (every vector after it not run), and why the run ended; the
         * expectations file is written as at the end of a run.
         */
        private String timedOutText(int index) {
            Vector v = vectors.get(index);
            ended = v.id();
            Verdict late = Judge.verdict(v, verifier.expected(v), Status.ERROR, "no answer within " + seconds(timeout)
                    + " (" + Environment.TIMEOUT + "); the run ends here: the vectors after it are not run");
            List<Verdict> all;
            synchronized (verdicts) {
                all = new ArrayList<>(verdicts);
            }
            all.add(late);
            for (int i = index + 1; i < vectors.size(); i++) {
                all.add(notRun(vectors.get(i)));
            }
            StringBuilder text = new StringBuilder(late.report()).append('\n');
            Report report = report(all);
            text.append(report.totals());
            if (write != null) {
                try {
                    int n = report.writeExpectations(write, "not triaged yet");
                    text.append("plcvec: ").append(n).append(" known failures written to ").append(write).append('\n');
                } catch (RuntimeException e) {
                    text.append("plcvec: ").append(e.getMessage()).append('\n');
                }
            }
            return text.append(endedText(all)).append('\n').toString();
        }

        /** The watchdog's end of the process: a thread that never returns cannot be stopped. */
        static void endProcess(String text) {
            // The original standard error: a test runner's capture would be lost with the process.
            java.io.PrintStream err = new java.io.PrintStream(new java.io.FileOutputStream(java.io.FileDescriptor.err), true,
                    java.nio.charset.StandardCharsets.UTF_8);
            err.print(text);
            err.flush();
            // halt, not exit: the exit guard's hook would say it again, and a hook could wait on
            // what the stuck thread holds.
            Runtime.getRuntime().halt(1);
        }

        private Report report(List<Verdict> all) {
            String aborted = ended == null ? null : ended + ": no answer within " + seconds(timeout) + " ("
                    + Environment.TIMEOUT + "); the run ended there";
            return new Report(verifier.header(), all, (System.nanoTime() - start) / 1e9, aborted);
        }

        private String endedText(List<Verdict> all) {
            long notRun = all.stream().filter(r -> r.status() == Status.NOT_RUN).count();
            return "plcvec: the run ended at " + ended + ", which gave no answer within " + seconds(timeout) + " ("
                    + Environment.TIMEOUT + "); " + notRun + " vectors were not run";
        }

        /**
         * The last test: the end of the run's text, the expectations file, and a failure when the
         * run ended early or nothing passed (every vector skipped or a known failure).
         */
        void end() {
            stop();
            List<Verdict> all;
            synchronized (verdicts) {
                all = List.copyOf(verdicts);
            }
            Report report = report(all);
            System.out.print(report.totals());
            System.out.flush();
            if (write != null) {
                try {
                    int n = report.writeExpectations(write, "not triaged yet");
                    System.out.println("plcvec: " + n + " known failures written to " + write);
                } catch (VerifyException e) {
                    throw quiet(new AssertionFailedError("plcvec: " + Environment.WRITE_EXPECTATIONS + "=" + write + ": "
                            + e.getMessage()));
                }
            }
            if (ended != null) {
                throw quiet(new AssertionFailedError(endedText(all)));
            }
            if (!report.passed() && report.failing().isEmpty()) {
                throw quiet(new AssertionFailedError("plcvec: " + (all.isEmpty()
                        ? "nothing tested: no selected vector was run (did the test runner's own filter leave them out? "
                        + "select vectors with " + Environment.ID + " instead); a run of nothing proves nothing"
                        : report.shortfall())));
            }
        }

        /** Said by the exit guard when the process ends before {@link #end()}. */
        String unfinished() {
            if (finished) {
                return null;
            }
            long b = beat.get();
            int at = (int) (b & 0xffff_ffffL) - 1;
            return at >= 0
                    ? "plcvec: the process ended while vector " + vectors.get(at).id() + " was running (System.exit or a crash in the "
                    + "implementation?); " + verdicts.size() + " of " + vectors.size() + " vectors were judged, the run did not finish"
                    : null;
        }
    }

    private static String seconds(Duration d) {
        double s = d.toNanos() / 1e9;
        return (s == Math.rint(s) ? String.valueOf((long) s) : String.valueOf(s)) + " s";
    }

    /**
     * The watchdog: one daemon thread per process, started with the first run's first vector,
     * that looks at every run in progress on the shortest tick among them and ends the run (the
     * process) whose vector outlived its bound. One per process, not per run: a run starts and
     * ends no thread, and nothing of it runs beside the vectors but a look at one word a tick.
     */
    static final class Watchdog {
        private static final List<Run> WATCHED = new java.util.concurrent.CopyOnWriteArrayList<>();
        private static Thread thread;
        /**
         * The tick the watchdog sleeps on (Long.MAX_VALUE: until a run is handed over): a run
         * whose own tick is not shorter wakes nobody. Set to MAX before the watchdog reads the runs,
         * so that a run handed over meanwhile is either among those read or sees MAX and wakes it.
         */
        private static volatile long sleeping = Long.MAX_VALUE;

        private Watchdog() {
        }

        static synchronized void watch(Run run) {
            WATCHED.add(run);
            if (thread == null) {
                thread = new Thread(Watchdog::loop, "plcvec-watchdog");
                thread.setDaemon(true);
                thread.start();
            } else if (run.tick < sleeping) {
                LockSupport.unpark(thread);   // to sleep on the shorter tick
            }
        }

        static void forget(Run run) {
            WATCHED.remove(run);
        }

        private static void loop() {
            while (true) {
                sleeping = Long.MAX_VALUE;
                long tick = Long.MAX_VALUE;
                for (Run r : WATCHED) {
                    tick = Math.min(tick, r.tick);
                }
                sleeping = tick;
                if (tick == Long.MAX_VALUE) {
                    LockSupport.park();       // no run in progress: until one is handed over
                } else {
                    LockSupport.parkNanos(tick);
                }
                long now = System.nanoTime();
                for (Run r : WATCHED) {
                    try {
                        if (!r.look(now)) {
                            WATCHED.remove(r);
                        }
                    } catch (RuntimeException | Error e) {
                        // One run's failure (its text could not be made) is not every run's: said
                        // as an uncaught exception would be, and the other runs stay watched.
                        WATCHED.remove(r);
                        Thread.currentThread().getUncaughtExceptionHandler().uncaughtException(Thread.currentThread(), e);
                    }
                }
            }
        }
    }

    /**
     * A shutdown hook that names the vector in progress when the process ends in the middle of a
     * run (an implementation calling {@code System.exit}): without it, the test runner reports only
     * that its process went away. It also ends the processes the runs' implementations left
     * running ({@link LeftProcesses}). {@code Runtime.halt} and signals run no hook; the vector's name
     * is then in the test runner's record of the test that started and never ended.
     */
    static final class ExitGuard {
        private static final List<Run> RUNS = new java.util.concurrent.CopyOnWriteArrayList<>();
        private static boolean installed;

        static void forget(Run run) {
            RUNS.remove(run);
        }

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
                    LeftProcesses.end();
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
