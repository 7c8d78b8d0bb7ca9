package org.plcvec.verify;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
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
 * reason); a stale known failure fails. The {@code plcvec.*} system properties narrow the
 * selection ({@link Selection#withSystemProperties()}):
 * {@code mvn test -Dtest=MyEmulatorConformanceTest -Dplcvec.id='fx5-time-add/TADDP/*'}.
 * An empty selection, an unknown name, or an implementation that supports none of the selected
 * instructions is one failing test: a gate never passes by accident.
 */
public final class PlcvecTests {
    private final Verifier verifier;

    private PlcvecTests(Verifier verifier) {
        this.verifier = verifier;
    }

    public static PlcvecTests of(Implementation implementation) {
        return new PlcvecTests(Verifier.of(implementation));
    }

    public static PlcvecTests of(Verifier verifier) {
        return new PlcvecTests(verifier);
    }

    public PlcvecTests suite(Suite suite) {
        return new PlcvecTests(verifier.suite(suite));
    }

    public PlcvecTests selection(Selection selection) {
        return new PlcvecTests(verifier.selection(selection));
    }

    public PlcvecTests expectations(Path file) {
        return new PlcvecTests(verifier.expectations(file));
    }

    public PlcvecTests expectations(KnownFailures known) {
        return new PlcvecTests(verifier.expectations(known));
    }

    /** The dynamic tests, for a {@code @TestFactory} method to return. */
    public Stream<DynamicNode> stream() {
        Verifier v;
        List<Vector> vectors;
        try {
            v = verifier.selection(verifier.selection().withSystemProperties());
            vectors = v.vectors();
        } catch (VerifyException e) {
            return Stream.of(failing("plcvec: cannot run", e.getMessage()));
        }
        Implementation impl = v.implementation();
        List<DynamicNode> tests = new ArrayList<>(vectors.size() + 1);
        if (vectors.stream().noneMatch(x -> impl.supports(x.instruction()))) {
            tests.add(failing("plcvec: nothing to run", impl.name() + " supports none of the instructions of the "
                    + vectors.size() + " selected vectors (" + v.selection() + "); a run of nothing proves nothing"));
        }
        final Verifier run = v;
        for (Vector vector : vectors) {
            // The test source lets an IDE open the vector's line in the vector file.
            tests.add(DynamicTest.dynamicTest(vector.id(), vector.source(), () -> verdict(run.check(vector))));
        }
        for (Result stale : v.knownFailures().unknownIds(v.suite())) {
            tests.add(failing("expectations: " + stale.id(), stale.message()));
        }
        return tests.stream();
    }

    private static DynamicTest failing(String name, String message) {
        return DynamicTest.dynamicTest(name, () -> {
            throw new AssertionFailedError(message);
        });
    }

    /** Turn a verdict into the test's outcome. */
    static void verdict(Result r) {
        switch (r.status()) {
            case PASS:
                return;
            case SKIP:
            case XFAIL:
                Assumptions.abort(r.status().label() + ": " + r.message());
                return;
            case FAIL:
                throw new AssertionFailedError(r.report(), side(r, true), side(r, false));
            default:
                throw new AssertionFailedError(r.report());
        }
    }

    /** One side of the IDE's comparison view: a line per differing field. */
    private static String side(Result r, boolean expected) {
        StringBuilder sb = new StringBuilder();
        for (Problem p : r.problems()) {
            String where = p.step() == Problem.WHOLE ? p.field() : "step " + p.step() + " " + p.field();
            sb.append(where).append(" = ").append(expected ? p.expected() : p.actual()).append('\n');
        }
        return sb.toString();
    }
}
