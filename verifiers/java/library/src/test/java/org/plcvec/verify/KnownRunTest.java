package org.plcvec.verify;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.opentest4j.AssertionFailedError;

/**
 * Known failures this release: a run of them alone proves nothing; an id merged into another
 * vector is named by the vector it became, the map followed to its end; what a report shows of a
 * value outside the word range or not finite.
 */
class KnownRunTest {
    @TempDir
    Path tmp;

    @Test
    void aRunOfKnownFailuresAloneDoesNotPass() {
        KnownFailures known = KnownFailures.parse("[[known-failure]]\nid = \"" + CompareTest.PROGRAM
                + "\"\nreason = \"off by one\"\n", "known.toml");
        PlcvecTests tests = PlcvecTests.of(Fakes.echo((s, d) -> d.put("D31", 41))).selection(Selection.all()
                .ids(CompareTest.PROGRAM)).expectations(known).environment(Environment.of(Map.of()));
        Report report = Verifier.of(Fakes.echo((s, d) -> d.put("D31", 41))).selection(Selection.all().ids(CompareTest.PROGRAM))
                .expectations(known).run();
        assertEquals(1, report.counts().get(Status.XFAIL));
        assertFalse(report.passed());
        assertEquals("nothing passed (1 known failures): the run proves nothing", report.shortfall());
        AssertionFailedError end = assertThrows(AssertionFailedError.class, () -> {
            for (var node : tests.stream().toList()) {
                try {
                    ((org.junit.jupiter.api.DynamicTest) node).getExecutable().execute();
                } catch (org.opentest4j.TestAbortedException knownFailure) {
                    // reported as skipped, as JUnit does
                }
            }
        });
        assertEquals("plcvec: nothing passed (1 known failures): the run proves nothing", end.getMessage());
    }

    @Test
    void aMergedIdIsNamedByTheVectorItBecame() {
        Suite suite = Suite.fromResources();
        KnownFailures known = KnownFailures.parse("[[known-failure]]\nid = \"cp1e-time-compare/AND <=DT/ordering/eq\"\n"
                + "reason = \"listed before the merge\"\n", "known.toml");
        assertEquals("listed as a known failure (known.toml:1) but the suite has no such vector: it was merged into "
                + "cp1e-time-compare/AND <=DT/logic/rlo-on/eq; list that id instead",
                known.unknownIds(suite).get(0).message());
    }

    @Test
    void aMergeIsFollowedToItsEnd() throws IOException {
        for (String name : List.of("cp1e-time-compare.jsonl", "fc6a-hour-meter.jsonl", "fx5-date-compare.jsonl",
                "fx5-time-add.jsonl", "fx5-time-compare.jsonl", "index.json")) {
            try (InputStream in = Suite.class.getResourceAsStream(Suite.RESOURCES + name)) {
                Files.copy(in, tmp.resolve(name));
            }
        }
        // a -> b -> an id the suite has: a names the last.
        Path index = tmp.resolve("index.json");
        var node = (tools.jackson.databind.node.ObjectNode) Suite.JSON.readTree(Files.readString(index));
        node.putObject("merged").putObject("fx5-time-add").put("fx5-time-add/a", "fx5-time-add/b")
                .put("fx5-time-add/b", CompareTest.PROGRAM);
        Files.writeString(index, node.toString());
        Suite suite = Suite.load(tmp);
        assertEquals(CompareTest.PROGRAM, suite.mergedInto("fx5-time-add/a"));
        assertEquals(null, suite.mergedInto("fx5-time-add/never-there"));
    }

    @Test
    void valuesOutsideTheWordRangeAndNotFiniteShowAsTheyAre() {
        DeviceImage image = DeviceImage.of(new java.util.LinkedHashMap<>(Map.of("D1", 65536)));
        assertEquals("65536", image.show(0));
        assertEquals("NaN", Values.showReported(Double.NaN));
        assertEquals("Infinity", Values.showReported(Double.POSITIVE_INFINITY));
        assertEquals("-Infinity", Values.showReported(Double.NEGATIVE_INFINITY));
        assertEquals("13.5", Values.showReported(13.5));
        assertEquals("-1", Values.showReported(-1));
        assertEquals("\"13\"", Values.showReported("13"));
        assertEquals("null", Values.showReported(null));
        assertEquals("[1,2]", Values.showReported(List.of(1, 2)));
        assertEquals("{\"a\":1,\"b\":2}", Values.showReported(new java.util.TreeMap<>(Map.of("b", 2, "a", 1)).descendingMap()));
    }
}
