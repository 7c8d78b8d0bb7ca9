package org.plcvec.mutants;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.plcvec.spec.Family;
import org.plcvec.verify.Problem;
import org.plcvec.verify.Report;
import org.plcvec.verify.Verdict;
import org.plcvec.verify.Selection;
import org.plcvec.verify.Status;
import org.plcvec.verify.Suite;
import org.plcvec.verify.Verifier;

/**
 * The Java verifier rejects every mutant, by name: the run over the mutant's families fails, and
 * a named vector fails on a named field in the way the bug predicts (the aspect of the comparison
 * it shows).
 */
class MutantsTest {
    /** Which part of the comparison a mutant is caught by. */
    enum Aspect {
        RESULT, WORD, FLAG, UNCHANGED, OUTSIDE, INTERPRETATION
    }

    /** name -> (a vector that catches it, the field, the aspect). */
    record Catch(String vector, String field, Aspect aspect) {
    }

    static final Map<String, Catch> CAUGHT = Map.ofEntries(
            Map.entry("fx5-low-field-first", new Catch("fx5-time-compare/ANDTM</logic/rlo-on/gt", "result", Aspect.RESULT)),
            Map.entry("fx5-sm709-not-latched",
                    new Catch("fx5-time-compare/LDTM=/latch/already-on-valid-data", "SM709", Aspect.UNCHANGED)),
            Map.entry("fx5-clock-bit-ignored",
                    new Catch("fx5-date-compare/LDDT</current-clock/day-lt/dummy-invalid", "result", Aspect.RESULT)),
            Map.entry("fx5-date-calendar-check",
                    new Catch("fx5-date-compare/LDDT</manual-example/nonexistent/A<B/day", "SM709", Aspect.FLAG)),
            Map.entry("fx5-and-executed-when-off",
                    new Catch("fx5-time-compare/ANDTM</logic/rlo-off/invalid-data", "SM709", Aspect.INTERPRETATION)),
            Map.entry("tadd-no-wrap-at-24",
                    new Catch("fx5-time-add/TADD/carry/exact-wrap-halves/flags-off-before", "D300", Aspect.WORD)),
            Map.entry("tadd-sm8022-not-written",
                    new Catch("fx5-time-add/TADD/carry/carry-out-of-hour/flags-off-before", "SM8022", Aspect.FLAG)),
            Map.entry("taddp-every-scan", new Catch("fx5-time-add/TADDP/pulse/off-on-on-off-on-on", "D302", Aspect.UNCHANGED)),
            Map.entry("tadd-writes-past-d",
                    new Catch("fx5-time-add/TADD/carry/below-wrap/flags-off-before", "D303", Aspect.OUTSIDE)),
            // (d) = D201 over (s2) = D200: copied first, (s1) 11:30:30 makes (s2) 15:11:30, and the sum is
            // 2:42:00 with the carry, not 11:30:30 + 15:39:39 = 3:10:09.
            Map.entry("tadd-s1-copied-into-d-first", new Catch("fx5-time-add/TADD/overlap/d=s2+1", "D201", Aspect.WORD)),
            Map.entry("hour-drops-fraction", new Catch("fc6a-hour-meter/HOUR/input/off-on-off", "D202", Aspect.WORD)),
            Map.entry("hour-wrap-clears-d2", new Catch("fc6a-hour-meter/HOUR/wrap/output-stays-on", "M10", Aspect.UNCHANGED)),
            Map.entry("hour-input-off-resets",
                    new Catch("fc6a-hour-meter/HOUR/input/off-on-off", "D202", Aspect.INTERPRETATION)),
            Map.entry("cp1e-mask-inverted", new Catch("cp1e-time-compare/AND <=DT/logic/rlo-on/eq", "result", Aspect.RESULT)),
            Map.entry("cp1e-flags-not-reflected",
                    new Catch("cp1e-time-compare/AND <=DT/logic/rlo-off/eq", "P_EQ", Aspect.FLAG)),
            Map.entry("cp1e-bcd-read-as-binary",
                    new Catch("cp1e-time-compare/AND <=DT/logic/rlo-off/invalid-data", "P_ER", Aspect.FLAG)),
            // S1 at D8190: D8192 is past the end of D; read as 0 (year 00, month 00, compared as it is by
            // default) it is compared with S2 and P_ER stays off.
            Map.entry("cp1e-past-area-compared",
                    new Catch("cp1e-time-compare/AND <>DT/device-range/S1=D8190", "P_ER", Aspect.FLAG)));

    /** A mutant's verifier over its families and the run of it, made once: both factories below judge the same run. */
    record Run(Verifier verifier, Report report) {
    }

    private static final Map<String, Run> RUNS = new ConcurrentHashMap<>();

    private static Run run(Mutant m) {
        return RUNS.computeIfAbsent(m.name(), name -> {
            Verifier verifier = Verifier.of(m.create()).selection(Selection.all().families(m.families().toArray(new Family[0])));
            return new Run(verifier, verifier.run());
        });
    }

    @TestFactory
    Stream<DynamicTest> everyMutantIsRejected() {
        return Mutants.all().stream().map(m -> DynamicTest.dynamicTest(m.name(), () -> {
            Catch c = CAUGHT.get(m.name());
            assertNotNull(c, m.name() + " has no catching vector in this test's table");
            Run run = run(m);
            assertFalse(run.report().passed(), m.name() + " passed every vector of " + m.families());

            Verdict r = run.verifier().check(Suite.golden().byId(c.vector()));
            assertEquals(Status.FAIL, r.status(), m.name() + " on " + c.vector() + ": " + r.report());
            Problem p = r.problems().stream().filter(x -> x.field().equals(c.field())).findFirst().orElse(null);
            assertNotNull(p, m.name() + " on " + c.vector() + " should differ at " + c.field() + ":\n" + r.report());
            switch (c.aspect()) {
                case UNCHANGED:
                    assertEquals(p.expected(), p.before(), "the step must leave " + c.field() + " unchanged: " + p.line());
                    assertTrue(p.line().endsWith("(the step must leave it unchanged)"), p.line());
                    break;
                case OUTSIDE:
                    assertEquals("<not in the vector>", p.expected(), p.line());
                    break;
                case INTERPRETATION:
                    assertFalse(r.judgedBy().isEmpty(), "judged by an alternative: " + r.report());
                    assertTrue(r.report().contains("judged by: "), r.report());
                    break;
                case FLAG:
                    assertTrue(p.expected().equals("true") || p.expected().equals("false"), "a flag is a bit: " + p.line());
                    break;
                case WORD:
                    assertTrue(p.expected().matches("\\d+") && p.actual().matches("\\d+"), "a word: " + p.line());
                    break;
                default:
                    assertEquals("result", p.field());
            }
            assertTrue(r.report().startsWith("FAIL " + c.vector()), r.report());
            assertTrue(r.report().contains("spec clauses: "), r.report());
        }));
    }

    /**
     * No mutant is explained away by a reading (TEXT.md, "The roll-up by reading"): the roll-up of
     * a mutant's run may propose a declaration only marked partial, since the bug leaves failures
     * of the same families that no reading explains. A mutant whose failures one reading explains
     * entirely is that reading, not a bug.
     */
    @TestFactory
    Stream<DynamicTest> noMutantIsExplainedAwayByAReading() {
        return Mutants.all().stream().map(m -> DynamicTest.dynamicTest(m.name(), () -> {
            String summary = run(m).report().summary();
            for (String line : summary.split("\n")) {
                if (line.matches(" {4}[ \\d]{6}  [A-Z0-9-]+=.*")) {
                    assertTrue(line.contains(" (partial: "), m.name() + " is explained by a reading: " + line + "\n"
                            + summary.substring(summary.indexOf("READINGS: ")));
                }
            }
        }));
    }

    @Test
    void theMutantsCoverEveryFamilyAndEveryAspect() {
        assertTrue(Mutants.all().size() >= 10);
        Set<Family> families = Mutants.all().stream().flatMap(m -> m.families().stream()).collect(Collectors.toSet());
        assertEquals(EnumSet.allOf(Family.class), EnumSet.copyOf(families));
        assertEquals(EnumSet.allOf(Aspect.class), EnumSet.copyOf(CAUGHT.values().stream().map(Catch::aspect).toList()));
        assertEquals(CAUGHT.keySet(), Mutants.all().stream().map(Mutant::name).collect(Collectors.toSet()));
    }

    @Test
    void mutantsMdListsEveryMutant() throws IOException {
        List<String> lines = Files.readAllLines(Path.of("MUTANTS.md"));
        for (Mutant m : Mutants.all()) {
            assertTrue(lines.stream().anyMatch(l -> l.startsWith("| `" + m.name() + "` |")), "MUTANTS.md lacks " + m.name());
        }
    }
}
