package org.plcvec.verify;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.DynamicNode;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.opentest4j.AssertionFailedError;
import org.opentest4j.TestAbortedException;
import org.plcvec.spec.Family;

/** The JUnit layer: one test per vector named by id, and a gate that cannot pass by accident. */
class PlcvecTestsTest {
    private static List<DynamicNode> nodes(PlcvecTests t) {
        return t.stream().toList();
    }

    @Test
    void oneTestPerVectorDisplayedByItsId() throws Throwable {
        List<DynamicNode> n = nodes(PlcvecTests.of(Fakes.echo((s, d) -> { })).selection(Selection.all().families(Family.FX5_TIME_ADD)));
        assertEquals(Selection.all().families(Family.FX5_TIME_ADD).apply(Suite.golden()).size() + 1, n.size());
        assertEquals(PlcvecTests.END, n.get(n.size() - 1).getDisplayName());
        assertEquals(Suite.golden().vectors().stream().filter(v -> v.family().equals("fx5-time-add")).findFirst().orElseThrow().id(),
                n.get(0).getDisplayName());
        ((DynamicTest) n.get(0)).getExecutable().execute();
        // The IDE can open the vector's own line: line 1 of a .jsonl copy is the header.
        assertEquals("classpath:/org/plcvec/vectors/fx5-time-add.jsonl?line=2", n.get(0).getTestSourceUri().orElseThrow().toString());
    }

    @Test
    void aFailureCarriesTheDiffAndBothSides() {
        List<DynamicNode> n = nodes(PlcvecTests.of(Fakes.echo((s, d) -> d.put("D31", 41)))
                .selection(Selection.all().ids(CompareTest.PROGRAM)));
        AssertionFailedError e = assertThrows(AssertionFailedError.class, () -> ((DynamicTest) n.get(0)).getExecutable().execute());
        assertTrue(e.getMessage().contains("step 0 D31: expected 40, got 41"), e.getMessage());
        assertEquals("step 0 D31 = 40\n", e.getExpected().getStringRepresentation());
        assertEquals("step 0 D31 = 41\n", e.getActual().getStringRepresentation());
    }

    @Test
    void aSkippedVectorIsAborted() {
        Implementation none = new Implementation() {
            @Override
            public boolean supports(String instruction) {
                return instruction.equals("TADD");
            }

            @Override
            public List<StepState> run(VectorRequest vector) {
                throw new SkipVector("not today");
            }
        };
        List<DynamicNode> n = nodes(PlcvecTests.of(none).selection(Selection.all().ids(CompareTest.PROGRAM)));
        TestAbortedException e = assertThrows(TestAbortedException.class, () -> ((DynamicTest) n.get(0)).getExecutable().execute());
        assertEquals("skip: not today", e.getMessage());
    }

    @Test
    void anEmptySelectionOrNothingSupportedIsOneFailingTest() {
        List<DynamicNode> n = nodes(PlcvecTests.of(Fakes.echo((s, d) -> { })).selection(Selection.all().ids("no/such/*")));
        assertEquals(1, n.size());
        assertEquals("plcvec: cannot run", n.get(0).getDisplayName());
        assertThrows(AssertionFailedError.class, () -> ((DynamicTest) n.get(0)).getExecutable().execute());

        Implementation nothing = new Implementation() {
            @Override
            public boolean supports(String instruction) {
                return false;
            }

            @Override
            public List<StepState> run(VectorRequest vector) {
                return List.of();
            }
        };
        AssertionFailedError e = assertThrows(AssertionFailedError.class,
                () -> runAll(PlcvecTests.of(nothing).selection(Selection.all().families(Family.FC6A_HOUR_METER))));
        int hour = Selection.all().families(Family.FC6A_HOUR_METER).apply(Suite.golden()).size();
        assertEquals("plcvec: nothing passed (" + hour + " skipped): the run proves nothing", e.getMessage());
    }

    /**
     * Every node run as JUnit would, in order, whatever each test's outcome: what the run printed
     * on standard output (the end of run's text).
     */
    static String endOfRun(PlcvecTests t) {
        java.io.PrintStream out = System.out;
        java.io.ByteArrayOutputStream printed = new java.io.ByteArrayOutputStream();
        System.setOut(new java.io.PrintStream(printed, true, java.nio.charset.StandardCharsets.UTF_8));
        try {
            for (DynamicNode node : nodes(t)) {
                try {
                    ((DynamicTest) node).getExecutable().execute();
                } catch (Throwable outcome) {
                    // as JUnit: a failed or skipped test is reported, and the next one runs
                }
            }
        } finally {
            System.setOut(out);
        }
        return printed.toString(java.nio.charset.StandardCharsets.UTF_8);
    }

    /** Run every node as JUnit would, in order; skipped vectors are aborted and go on. */
    private static void runAll(PlcvecTests t) throws Throwable {
        for (DynamicNode node : nodes(t)) {
            try {
                ((DynamicTest) node).getExecutable().execute();
            } catch (TestAbortedException skipped) {
                // as JUnit: the next test runs
            }
        }
    }

    @Test
    void skippingEverythingIsNotAPass() {
        Implementation skips = new Implementation() {
            @Override
            public List<StepState> run(VectorRequest vector) {
                throw new SkipVector("by design");
            }
        };
        Selection family = Selection.all().families(Family.FX5_TIME_ADD);
        int count = family.apply(Suite.golden()).size();    // the family's vectors, however many the spec gives
        assertTrue(count > 0, "no fx5-time-add vector loaded");
        AssertionFailedError e = assertThrows(AssertionFailedError.class,
                () -> runAll(PlcvecTests.of(skips).selection(family)));
        assertEquals("plcvec: nothing passed (" + count + " skipped): the run proves nothing", e.getMessage());
    }

    @Test
    void aVectorThatNeverAnswersEndsTheRunNamingIt() throws Throwable {
        java.util.concurrent.atomic.AtomicBoolean released = new java.util.concurrent.atomic.AtomicBoolean();
        Implementation loops = new Implementation() {
            @Override
            public List<StepState> run(VectorRequest vector) throws Exception {
                if (vector.id().equals(CompareTest.PROGRAM)) {
                    while (!released.get()) {
                        Thread.onSpinWait();   // deaf to interrupts, like a real endless loop
                    }
                }
                return Fakes.echo((s, d) -> { }).run(vector);
            }
        };
        // What the watchdog would write to standard error before it ends the process.
        java.util.concurrent.CompletableFuture<String> said = new java.util.concurrent.CompletableFuture<>();
        List<DynamicNode> n = nodes(PlcvecTests.of(loops).selection(Selection.all().families(Family.FX5_TIME_ADD))
                .environment(Environment.of(java.util.Map.of("PLCVEC_TIMEOUT", "0.3"))).onTimeout(said::complete));
        int at = indexOf(n, CompareTest.PROGRAM);
        for (int i = 0; i < at; i++) {
            ((DynamicTest) n.get(i)).getExecutable().execute();
        }
        // The vector runs on the test's own thread: here a thread of this test, freed once the
        // watchdog has spoken (a real endless loop is never freed: the process ends).
        Thread stuck = new Thread(() -> {
            try {
                ((DynamicTest) n.get(at)).getExecutable().execute();
            } catch (Throwable ignored) {
                // what the vector gives once freed does not matter: the run has ended
            }
        });
        stuck.setDaemon(true);
        long t0 = System.nanoTime();
        stuck.start();
        String text;
        try {
            text = said.get(30, java.util.concurrent.TimeUnit.SECONDS);
        } finally {
            released.set(true);
            stuck.join(10_000);
        }
        double waited = (System.nanoTime() - t0) / 1e9;
        assertTrue(waited >= 0.3 && waited < 10, "the watchdog spoke after " + waited + " s");
        int notRun = n.size() - 1 - (at + 1);
        assertTrue(notRun > 0);
        // The vector's error block (TEXT.md), then the end of the run's text: the late vector and
        // those not run are failing vectors no reading explains, then why the run was stopped,
        // then the totals with the vectors not run, then why the run ended.
        assertTrue(text.startsWith("ERROR " + CompareTest.PROGRAM + "\n"), text);
        assertTrue(text.contains("no answer within 0.3 s (PLCVEC_TIMEOUT); the run ends here"), text);
        assertTrue(text.contains("\nNOT EXPLAINED by any reading: " + (notRun + 1) + " failing vectors, by the clauses"), text);
        assertTrue(text.contains("\nABORTED: " + CompareTest.PROGRAM + ": no answer within 0.3 s (PLCVEC_TIMEOUT); the run "
                + "ended there\n\nplcvec verify: "), text);
        assertTrue(text.contains("\n" + (n.size() - 1) + " vectors: " + at + " pass, 0 fail, 1 error, 0 skip, " + notRun
                + " not-run in "), text);
        assertTrue(text.endsWith("plcvec: the run ended at " + CompareTest.PROGRAM + ", which gave no answer within "
                + "0.3 s (PLCVEC_TIMEOUT); " + notRun + " vectors were not run\n"), text);
        // Where the process goes on (here), nothing more is run: every vector after it is not run.
        for (int i = at + 1; i < n.size() - 1; i++) {
            DynamicTest t = (DynamicTest) n.get(i);
            PlcvecTests.ImplementationError e = assertThrows(PlcvecTests.ImplementationError.class,
                    () -> t.getExecutable().execute());
            assertTrue(e.getMessage().startsWith("NOT-RUN " + t.getDisplayName() + "\n"), e.getMessage());
        }
    }

    @Test
    void runsShareOneWatchdogThread() throws Throwable {
        // Three runs in progress at once (each past its first vector, its end not run yet), as
        // three test classes' factories in one test process: one watchdog thread watches them all,
        // and a run starts and ends no thread of its own.
        List<List<DynamicNode>> runs = new java.util.ArrayList<>();
        for (int i = 0; i < 3; i++) {
            List<DynamicNode> n = nodes(PlcvecTests.of(Fakes.echo((s, d) -> { })).selection(Selection.all().ids(CompareTest.PROGRAM)));
            ((DynamicTest) n.get(0)).getExecutable().execute();
            runs.add(n);
        }
        long watchdogs = Thread.getAllStackTraces().keySet().stream()
                .filter(t -> t.getName().equals("plcvec-watchdog") && t.isAlive()).count();
        assertEquals(1, watchdogs);
        for (List<DynamicNode> n : runs) {
            ((DynamicTest) n.get(n.size() - 1)).getExecutable().execute();
        }
    }

    @Test
    void aLambdaIsNamedByTheClassItIsWrittenIn() {
        Emulator lambda = (vector, memory) -> step -> null;
        // Not the JVM's made-up PlcvecTestsTest$$Lambda$123/0x...: the same name in every run.
        assertEquals("PlcvecTestsTest", lambda.name());
        assertEquals("PlcvecTestsTest", Verifier.of(lambda).header().implementation());
    }

    private static int indexOf(List<DynamicNode> n, String id) {
        for (int i = 0; i < n.size(); i++) {
            if (n.get(i).getDisplayName().equals(id)) {
                return i;
            }
        }
        throw new AssertionError(id);
    }

    @Test
    void anExceptionIsAnErrorLocatedInTheImplementation() {
        Implementation throwsFromTheJdk = new Implementation() {
            @Override
            public List<StepState> run(VectorRequest vector) {
                java.time.LocalDate.of(2023, 2, 29);   // the line the message must give
                return List.of();
            }
        };
        List<DynamicNode> n = nodes(PlcvecTests.of(throwsFromTheJdk).selection(Selection.all().ids(CompareTest.PROGRAM)));
        PlcvecTests.ImplementationError e = assertThrows(PlcvecTests.ImplementationError.class,
                () -> ((DynamicTest) n.get(0)).getExecutable().execute());
        assertTrue(e.getMessage().contains("DateTimeException: Invalid date 'February 29' as '2023' is not a leap year"
                + " (PlcvecTestsTest.java:"), e.getMessage());   // the caller's line, not LocalDate.java
        assertTrue(e.getCause() instanceof java.time.DateTimeException);
    }

    @Test
    void anUnknownInterpretationIsRefused() {
        Implementation wrong = new Implementation() {
            @Override
            public Choices choices() {
                return Choices.parse(List.of("TADD-EXACT-24=carry-at-25"));
            }

            @Override
            public List<StepState> run(VectorRequest vector) {
                return List.of();
            }
        };
        List<DynamicNode> n = nodes(PlcvecTests.of(wrong));
        AssertionFailedError e = assertThrows(AssertionFailedError.class, () -> ((DynamicTest) n.get(0)).getExecutable().execute());
        assertTrue(e.getMessage().contains("TADD-EXACT-24=carry-at-25, but TADD-EXACT-24 has the alternatives carry-at-24, "
                + "carry-above-24"), e.getMessage());
    }
}
