package org.plcvec.verify;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import tools.jackson.databind.node.ArrayNode;
import tools.jackson.databind.node.ObjectNode;

/**
 * Devices an alternative leaves unjudged (schema 1.1, /unjudged.md), on a vector made for it: one
 * TADD step over D10, D20, D30 and SM700 that expects D30 = 1 and SM700 kept false under the
 * default of TADD-FLAGS-OFF, and D30 = 1 with SM700 unjudged under set-only. Every expectation
 * below is worked out by hand from the rules.
 */
class UnjudgedTest {
    private static final String ID = "fx5-time-add/TADD/unjudged/v";
    private static final String FLAGS = "TADD-FLAGS-OFF";

    @TempDir
    Path tmp;

    /** The vector; {@code edit} changes its set-only entry before it is written. */
    private static ObjectNode vector(Consumer<ObjectNode> edit) {
        ObjectNode v = Suite.JSON.createObjectNode();
        v.put("id", ID).put("family", "fx5-time-add").put("instruction", "TADD").put("st", "TADD").put("description", "");
        v.putArray("tags");
        v.putArray("clauses");
        v.putObject("assumes").putObject("device_sizes").put("D", 8000);
        ObjectNode initial = v.putObject("initial");
        initial.putObject("devices").put("D10", 0).put("D20", 0).put("D30", 0).put("SM700", false);
        ObjectNode operands = initial.putObject("operands");
        operands.putObject("s1").put("device", "D10");
        operands.putObject("s2").put("device", "D20");
        operands.putObject("d").put("device", "D30");
        ObjectNode step = v.putArray("steps").addObject();
        step.put("en", true);
        step.putObject("expect").putObject("devices").put("D30", 1);
        v.putObject("final").putObject("devices").put("D10", 0).put("D20", 0).put("D30", 1).put("SM700", false);
        ObjectNode outcome = v.putObject("outcome");
        outcome.put("category", "implementation-defined").put("reason", "made for the test");
        outcome.putObject("default").put("category", "value");
        outcome.putArray("interpretations").add(FLAGS);
        ObjectNode a = v.putArray("alternatives").addObject();
        a.putObject("choices").put(FLAGS, "set-only");
        a.putArray("expect").addObject().putObject("devices").put("D30", 1);
        a.putObject("final").putObject("devices").put("D10", 0).put("D20", 0).put("D30", 1);
        a.putObject("outcome").put("category", "value");
        a.putObject("unjudged").putArray(FLAGS).add("SM700");
        edit.accept(a);
        return v;
    }

    /** A family file of the vector, with the shared cases' TADD header at {@code schema}. */
    private Suite suite(String schema, Consumer<ObjectNode> edit) throws IOException {
        Path cases = TextTest.CASES.resolve("vectors/fx5-time-add.json");
        ObjectNode family = (ObjectNode) Suite.JSON.readTree(Files.readString(cases, StandardCharsets.UTF_8));
        family.put("schema_version", schema).put("count", 1);
        ArrayNode list = family.putArray("vectors");
        list.add(vector(edit));
        Path file = tmp.resolve("fx5-time-add.json");
        Files.writeString(file, family.toString(), StandardCharsets.UTF_8);
        return Suite.load(file);
    }

    private Suite suite() throws IOException {
        return suite("1.1.0", a -> { });
    }

    /** An implementation declaring {@code alternative} of TADD-FLAGS-OFF that answers D30 and SM700. */
    private static Implementation answering(String alternative, int d30, boolean sm700) {
        return new Implementation() {
            @Override
            public Choices choices() {
                return Choices.of(Map.of(FLAGS, alternative));
            }

            @Override
            public List<StepState> run(VectorRequest vector) {
                return List.of(StepState.of(null, Map.of("D10", 0, "D20", 0, "D30", d30, "SM700", sm700)));
            }
        };
    }

    @Test
    void anUnjudgedDeviceIsNotComparedAndWritingItIsNoStrayWrite() throws IOException {
        Verdict r = Verifier.of(answering("set-only", 1, true)).suite(suite()).run().verdicts().get(0);
        assertEquals(Status.PASS, r.status(), r.report());
    }

    @Test
    void theBlockSaysWhatIsNotJudged() throws IOException {
        Verdict r = Verifier.of(answering("set-only", 2, true)).suite(suite()).run().verdicts().get(0);
        assertEquals("""
                FAIL fx5-time-add/TADD/unjudged/v
                    not judged under TADD-FLAGS-OFF=set-only: SM700
                    step 0 inputs: en=true
                    step 0 operands: d D30=0, s1 D10=0, s2 D20=0
                    step 0 D30: expected 1, got 2 (before the step: 0)""", r.report());
    }

    @Test
    void aReadingThatLeavesTheFieldUnjudgedDecidesIt() throws IOException {
        Verdict r = Verifier.of(answering("written-each-execution", 1, true)).suite(suite()).run().verdicts().get(0);
        assertEquals("""
                FAIL fx5-time-add/TADD/unjudged/v
                    judged by: TADD-FLAGS-OFF=written-each-execution
                    step 0 inputs: en=true
                    step 0 operands: d D30=0, s1 D10=0, s2 D20=0
                    step 0 SM700: expected false, got true (the step must leave it unchanged)""", r.report());
    }

    @Test
    void theReadingThatLeavesTheFailingDeviceUnjudgedExplainsTheFailure() throws IOException {
        Report report = Verifier.of(answering("written-each-execution", 1, true)).suite(suite()).run();
        assertEquals("""
                READINGS: 1 of 1 failing vectors pass under other alternatives:
                         1  TADD-FLAGS-OFF=set-only
                    declare: Choices.of(Alternatives.TaddFlagsOff.SET_ONLY)
                """, report.rollup());
    }

    @Test
    void aPassingVectorPassesWhereItsJudgedDevicesAreExpectedAlike() throws IOException {
        Vector v = suite().byId(ID);
        Map<String, String> defaults = Map.of(FLAGS, "written-each-execution");
        Expected byDefault = Expected.of(v, defaults, defaults);
        Expected setOnly = Expected.of(v, Map.of(FLAGS, "set-only"), defaults);
        // set-only judges D10, D20, D30, which the default expects alike: an answer passing the
        // default passes it too. The default judges SM700, which set-only leaves unjudged: an
        // answer passing set-only is not known to pass the default.
        assertTrue(setOnly.passesWherePasses(byDefault));
        assertFalse(byDefault.passesWherePasses(setOnly));
    }

    private String refused(String schema, Consumer<ObjectNode> edit) {
        return assertThrows(VerifyException.class, () -> suite(schema, edit)).getMessage();
    }

    @Test
    void aMalformedMapIsRefusedByVectorAndPath() {
        String at = "vector " + ID + ": at alternatives/0/unjudged";
        String unedited = " (is the file a plcvec vector file, unedited?)";
        assertTrue(refused("1.0.0", a -> { }).endsWith("vector " + ID
                + ": alternatives/0/unjudged: a key the schema does not have" + unedited));
        assertTrue(refused("1.1.0", a -> a.putObject("unjudged").putArray(FLAGS).add("SM999"))
                .endsWith(at + "/TADD-FLAGS-OFF: SM999 is not in initial/devices" + unedited));
        assertTrue(refused("1.1.0", a -> a.putObject("unjudged").putArray(FLAGS).add("SM700").add("D10"))
                .endsWith(at + "/TADD-FLAGS-OFF: the devices are not sorted" + unedited));
        assertTrue(refused("1.1.0", a -> a.putObject("unjudged").putArray("TADD-EXACT-24").add("SM700"))
                .endsWith(at + "/TADD-EXACT-24: TADD-EXACT-24 is not one of the entry's choices" + unedited));
        assertTrue(refused("1.1.0", a -> a.putObject("unjudged").putArray(FLAGS))
                .endsWith(at + "/TADD-FLAGS-OFF: [] is not a non-empty list of devices" + unedited));
        assertTrue(refused("1.1.0", a -> a.putObject("unjudged").putArray(FLAGS).add("D30"))
                .endsWith("vector " + ID + ": at alternatives/0/final/devices/D30: D30 is unjudged under "
                        + "TADD-FLAGS-OFF=set-only, so the entry cannot expect a value of it" + unedited));
    }
}
