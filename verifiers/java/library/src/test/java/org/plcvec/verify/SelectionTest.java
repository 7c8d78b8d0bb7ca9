package org.plcvec.verify;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.plcvec.spec.Family;
import org.plcvec.spec.Instruction;
import org.plcvec.spec.Tag;

class SelectionTest {
    private final Suite suite = Suite.golden();

    @Test
    void shardIsCrc32OfTheIdModuloNPlusOne() {
        // CRC-32's published check value: crc32("123456789") = 0xCBF43926 = 3421780262.
        assertEquals(3421780262L % 4 + 1, Selection.shardOf("123456789", 4));
        assertEquals(3421780262L % 7 + 1, Selection.shardOf("123456789", 7));
        assertEquals(1, Selection.shardOf("anything", 1));
    }

    @Test
    void shardsPartitionTheSuite() {
        Set<String> seen = new HashSet<>();
        int total = 0;
        for (int k = 1; k <= 3; k++) {
            List<Vector> part = Selection.all().shard(k, 3).apply(suite);
            assertFalse(part.isEmpty());
            part.forEach(v -> seen.add(v.id()));
            total += part.size();
        }
        assertEquals(suite.vectors().size(), total);
        assertEquals(suite.vectors().size(), seen.size());
    }

    @Test
    void filtersAreOrWithinAndAcross() {
        List<Vector> both = Selection.all().families(Family.FX5_TIME_ADD, Family.FC6A_HOUR_METER).apply(suite);
        assertTrue(both.stream().allMatch(v -> v.family().equals("fx5-time-add") || v.family().equals("fc6a-hour-meter")));
        assertTrue(both.stream().anyMatch(v -> v.family().equals("fc6a-hour-meter")));
        List<Vector> taddp = Selection.all().families(Family.FX5_TIME_ADD).instructions(Instruction.TADDP).apply(suite);
        assertFalse(taddp.isEmpty());
        assertTrue(taddp.stream().allMatch(v -> v.instruction().equals("TADDP")));
        List<Vector> tagged = Selection.all().tags(Tag.MANUAL_EXAMPLE).apply(suite);
        assertTrue(tagged.stream().allMatch(v -> v.tags().contains("manual-example")));
    }

    @Test
    void idGlobsAreFnmatch() {
        assertTrue(Selection.glob("fx5-time-add/*").matcher("fx5-time-add/TADD/a/b").matches());
        assertTrue(Selection.glob("fx5-time-?dd/*").matcher("fx5-time-add/x").matches());
        assertTrue(Selection.glob("LD[!A]*").matcher("LDTM=").matches());
        assertFalse(Selection.glob("LD[!T]*").matcher("LDTM=").matches());
        assertTrue(Selection.glob("a.b").matcher("a.b").matches());
        assertFalse(Selection.glob("a.b").matcher("axb").matches());
        assertTrue(Selection.glob("LD <=DT").matcher("LD <=DT").matches());
        assertEquals(1, Selection.all().ids("fx5-time-add/TADD/manual-example/program").apply(suite).size());
    }

    @Test
    void anUnknownNameIsAnErrorNotAnEmptyRun() {
        VerifyException e = assertThrows(VerifyException.class, () -> Selection.all().families("fx9-nothing").apply(suite));
        assertTrue(e.getMessage().contains("no family 'fx9-nothing'"), e.getMessage());
        assertThrows(VerifyException.class, () -> Selection.all().tags("no-such-tag").apply(suite));
        assertThrows(VerifyException.class, () -> Selection.all().shard(5, 4));
        assertThrows(VerifyException.class, () -> Selection.all().shard("2of4"));
    }

    @Test
    void theVariablesNarrowAndNeverWiden() {
        Environment env = Environment.of(Map.of("PLCVEC_INSTRUCTION", "TADDP"));
        List<Vector> vs = env.narrow(Selection.all().families(Family.FX5_TIME_ADD), suite).apply(suite);
        assertFalse(vs.isEmpty());
        assertTrue(vs.stream().allMatch(v -> v.instruction().equals("TADDP")));
        assertTrue(env.narrow(Selection.all().families(Family.FC6A_HOUR_METER), suite).apply(suite).isEmpty());
    }

    @Test
    void aSystemPropertyOverridesItsVariable() {
        assertEquals("plcvec.known-failures", Environment.property("PLCVEC_KNOWN_FAILURES"));
        System.setProperty("plcvec.instruction", "TADDP");
        try {
            assertEquals("TADDP", Environment.current().get("PLCVEC_INSTRUCTION"));
        } finally {
            System.clearProperty("plcvec.instruction");
        }
    }

    /** The same usage errors as {@code plcvec verify}, each naming the variable and its value. */
    @Test
    void aBadVariableNamesItselfAndItsValue() {
        String[][] cases = {
            {"PLCVEC_FAMILY", ",", "an empty name"},
            {"PLCVEC_FAMILY", "fx5-time-add,", "an empty name"},
            {"PLCVEC_FAMILY", "no-such-family", "known: "},
            {"PLCVEC_INSTRUCTION", "NO-SUCH-INSTRUCTION", "TADDP"},
            {"PLCVEC_TAG", "no-such-tag", "boundary"},
            {"PLCVEC_INTERPRETATION", "NO-SUCH-INTERPRETATION", "TADD-EXACT-24"},
            {"PLCVEC_ID", "no-such-family/*", "matches no vector id"},
            {"PLCVEC_SHARD", "3/2", "between 1 and N"},
            {"PLCVEC_SHARD", "0/2", "between 1 and N"},
            {"PLCVEC_SHARD", "half", "K/N"},
        };
        for (String[] c : cases) {
            Environment env = Environment.of(Map.of(c[0], c[1]));
            VerifyException e = assertThrows(VerifyException.class, () -> env.narrow(Selection.all(), suite), c[1]);
            assertTrue(e.getMessage().startsWith(c[0] + "=" + c[1] + ": "), e.getMessage());
            assertTrue(e.getMessage().contains(c[2]), e.getMessage());
        }
        for (String t : new String[] {"soon", "0", "-1", "NaN", "Infinity"}) {
            VerifyException e = assertThrows(VerifyException.class, () -> Environment.of(Map.of("PLCVEC_TIMEOUT", t)).timeout());
            assertTrue(e.getMessage().startsWith("PLCVEC_TIMEOUT=" + t + ": "), e.getMessage());
        }
        assertEquals(java.time.Duration.ofMillis(2500), Environment.of(Map.of("PLCVEC_TIMEOUT", "2.5")).timeout());
        assertEquals(java.time.Duration.ofSeconds(10), Environment.of(Map.of()).timeout());
    }
}
