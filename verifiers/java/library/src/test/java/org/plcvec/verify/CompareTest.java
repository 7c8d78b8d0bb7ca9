package org.plcvec.verify;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

/**
 * The comparison, exactly CONTRACT.md: the manual's TADD example (10:30:10 + 3:10:05 = 13:40:15
 * in D30..D32) answered correctly passes, and each kind of wrong answer is named field by field.
 */
class CompareTest {
    static final String PROGRAM = "fx5-time-add/TADD/manual-example/program";

    private static Verdict judge(Implementation impl) {
        Verifier v = Verifier.of(impl).selection(Selection.all().ids(PROGRAM));
        return v.check(v.vectors().get(0));
    }

    @Test
    void theExpectedStatePasses() {
        Verdict r = judge(Fakes.echo((s, d) -> { }));
        assertEquals(Status.PASS, r.status(), r.report());
        assertEquals(13, Suite.golden().byId(PROGRAM).expectation().finalValues()[
                List.of(Suite.golden().byId(PROGRAM).expectation().finalDevices()).indexOf(Address.of("D30"))]);
    }

    @Test
    void aChangedWordIsNamedWithItsValueBefore() {
        Verdict r = judge(Fakes.echo((s, d) -> d.put("D31", 41)));
        assertEquals(Status.FAIL, r.status());
        assertEquals("step 0 D31: expected 40, got 41 (before the step: 65535)", r.problems().get(0).line());
    }

    @Test
    void aBitReportedAsOneIsWrong() {
        Verdict r = judge(Fakes.echo((s, d) -> d.put("SM700", 0)));
        assertEquals(Status.FAIL, r.status());
        assertEquals("step 0 SM700: expected false, got 0 (the step must leave it unchanged)", r.problems().get(0).line());
    }

    @Test
    void aWordOutOfRangeOrOfAnotherTypeIsWrong() {
        Verdict r = judge(Fakes.echo((s, d) -> d.put("D30", 65536 + 13)));
        assertEquals("step 0 D30: expected 13, got 65549 (before the step: 65535)", r.problems().get(0).line());
        r = judge(Fakes.echo((s, d) -> d.put("D30", "13")));
        assertEquals("step 0 D30: expected 13, got \"13\" (before the step: 65535)", r.problems().get(0).line());
    }

    @Test
    void aWriteOutsideTheVectorIsReported() {
        Verdict r = judge(Fakes.echo((s, d) -> d.put("D33", 0)));
        assertEquals(Status.FAIL, r.status());
        assertEquals("step 0 D33: expected <not in the vector>, got 0", r.problems().get(0).line());
    }

    @Test
    void aMissingDeviceIsNotReported() {
        Verdict r = judge(Fakes.echo((s, d) -> d.remove("SD0")));
        // Not reported is not written: the value it held is shown, not "must leave it unchanged".
        assertEquals("step 0 SD0: expected 0, got <not reported> (before the step: 0)", r.problems().get(0).line());
    }

    @Test
    void theWrongNumberOfStepsFails() {
        Implementation none = request -> List.of();
        Verdict r = judge(none);
        assertEquals("steps: expected 1 steps, got 0 steps", r.problems().get(0).line());
    }

    @Test
    void anExceptionIsAnErrorAndSkipVectorASkip() {
        Implementation boom = request -> {
            throw new IllegalStateException("no such instruction");
        };
        Verdict r = judge(boom);
        assertEquals(Status.ERROR, r.status());
        assertTrue(r.message().startsWith("IllegalStateException: no such instruction"), r.message());
        Implementation skip = request -> {
            throw new SkipVector("no SD devices");
        };
        assertEquals(Status.SKIP, judge(skip).status());
    }

    @Test
    void theReportNamesIdAlternativesAndClauses() {
        Verifier v = Verifier.of(Fakes.echo((s, d) -> d.put("SM700", true)))
                .selection(Selection.all().ids("fx5-time-add/TADD/carry/below-wrap/flags-on-before"));
        Verdict r = v.check(v.vectors().get(0));
        String report = r.report();
        assertTrue(report.startsWith("FAIL fx5-time-add/TADD/carry/below-wrap/flags-on-before\n"), report);
        assertTrue(report.contains("    judged by: TADD-FLAGS-OFF=written-each-execution\n"), report);
        assertTrue(report.contains("    step 0 SM700: expected false, got true (before the step: true)\n"), report);
        assertTrue(report.contains("    spec clauses: fx5-time-add#"), report);
    }
}
