package org.plcvec.verify;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

/**
 * The settings (verifiers/CONTRACT.md, "The environment"): the one PLCVEC_TIMEOUT rule, the old
 * name read as the new one, misspellings named with the nearest setting, in CONTRACT.md's words.
 */
class EnvironmentTest {
    private static Environment env(String... pairs) {
        Map<String, String> m = new java.util.TreeMap<>();
        for (int i = 0; i < pairs.length; i += 2) {
            m.put(pairs[i], pairs[i + 1]);
        }
        return Environment.of(m);
    }

    @Test
    void theTimeoutIsDigitsWithAnOptionalFractionAbove0AndAtMostADay() {
        assertEquals(Duration.ofSeconds(10), env().timeout());
        assertEquals(Duration.ofMillis(2500), env("PLCVEC_TIMEOUT", "2.5").timeout());
        assertEquals(Duration.ofSeconds(86400), env("PLCVEC_TIMEOUT", "86400").timeout());
        assertEquals(Duration.ofMillis(1), env("PLCVEC_TIMEOUT", "0.001").timeout());
        for (String bad : List.of("1e9", "1e12", "86401", "86400.5", "0", "0.0", "-1", "+2", " 2", "2.", ".5", "soon",
                "1_0", "0x10", "99999999999999999999999")) {
            VerifyException e = assertThrows(VerifyException.class, () -> env("PLCVEC_TIMEOUT", bad).timeout(), bad);
            assertEquals("PLCVEC_TIMEOUT=" + bad + ": the bound must be a number of seconds above 0 and at most 86400, "
                    + "written as digits with an optional fraction (2, 0.5)", e.getMessage());
        }
    }

    @Test
    void theOldNameIsReadAsTheNewOneWithAWarning() {
        Environment old = env("PLCVEC_EXPECTATIONS", "k.toml");
        assertEquals(Path.of("k.toml"), old.knownFailures());
        assertEquals(List.of("plcvec: warning: PLCVEC_EXPECTATIONS is the old name of PLCVEC_KNOWN_FAILURES, read as it "
                + "until plcvec 0.3.0; set PLCVEC_KNOWN_FAILURES instead"), old.warnings());
        Environment both = env("PLCVEC_EXPECTATIONS", "old.toml", "PLCVEC_KNOWN_FAILURES", "new.toml");
        assertEquals(Path.of("new.toml"), both.knownFailures());
        assertEquals(List.of("plcvec: warning: PLCVEC_EXPECTATIONS is ignored: it is the old name of "
                + "PLCVEC_KNOWN_FAILURES, which is set too"), both.warnings());
    }

    @Test
    void aVariableThatIsNoSettingIsNamedWithTheNearestOne() {
        assertEquals(List.of("plcvec: warning: PLCVEC_TAGG is not a plcvec setting; did you mean PLCVEC_TAG?"),
                env("PLCVEC_TAGG", "boundary").warnings());
        // Two letters swapped: two edits from PLCVEC_SHARD.
        assertEquals(List.of("plcvec: warning: PLCVEC_SHRAD is not a plcvec setting; did you mean PLCVEC_SHARD?"),
                env("PLCVEC_SHRAD", "1/2").warnings());
        // Nearest to the old name: named as the setting it became.
        assertEquals(List.of("plcvec: warning: PLCVEC_EXPECTATION is not a plcvec setting; did you mean "
                + "PLCVEC_KNOWN_FAILURES?"), env("PLCVEC_EXPECTATION", "k.toml").warnings());
        // Nothing within three edits: every setting, in the table's order (CONTRACT.md's table).
        assertEquals(List.of("plcvec: warning: PLCVEC_COLOUR is not a plcvec setting; the settings are PLCVEC_VECTORS, "
                + "PLCVEC_ID, PLCVEC_FAMILY, PLCVEC_INSTRUCTION, PLCVEC_TAG, PLCVEC_INTERPRETATION, PLCVEC_SHARD, "
                + "PLCVEC_KNOWN_FAILURES, PLCVEC_WRITE_EXPECTATIONS, PLCVEC_TIMEOUT"), env("PLCVEC_COLOUR", "no").warnings());
        // In variable order, one line each.
        assertEquals(2, env("PLCVEC_ZZZZZZZZZZZ", "1", "PLCVEC_TAGG", "1").warnings().size());
        assertEquals("plcvec: warning: PLCVEC_TAGG", env("PLCVEC_ZZZZZZZZZZZ", "1", "PLCVEC_TAGG", "1").warnings().get(0)
                .substring(0, "plcvec: warning: PLCVEC_TAGG".length()));
    }

    @Test
    void settingsAndTheToolsOwnNamesAreNoMisspellings() {
        assertEquals(List.of(), env("PLCVEC_TAG", "boundary", "PLCVEC_HOSTILE", "panic", "PLCVEC_CACHE_DIR", "/tmp",
                "PLCVEC_TEST_ANYTHING", "1", "PLCVEC_HOSTILE_CHOICE", "X=y").warnings());
    }

    @Test
    void eachRunWarnsOnceOnStandardError() throws Throwable {
        PrintStream err = System.err;
        ByteArrayOutputStream printed = new ByteArrayOutputStream();
        System.setErr(new PrintStream(printed, true, StandardCharsets.UTF_8));
        try {
            PlcvecTestsTest.endOfRun(PlcvecTests.of(Fakes.echo((s, d) -> { })).environment(env("PLCVEC_TAGG", "x",
                    "PLCVEC_ID", CompareTest.PROGRAM)));
        } finally {
            System.setErr(err);
        }
        String text = printed.toString(StandardCharsets.UTF_8);
        assertEquals(1, text.split("PLCVEC_TAGG is not a plcvec setting; did you mean PLCVEC_TAG\\?", -1).length - 1, text);
    }

    @Test
    void aPropertySetToNothingUnsetsItsVariable() {
        // The library's tests run with every setting's property set to nothing (IgnoreUserSettings):
        // whatever the builder's environment holds, no setting is read from it.
        for (String name : SettingNames.SETTINGS) {
            assertNull(Environment.current().get(name), name);
        }
    }

    @Test
    void editDistanceIsLevenshteins() {
        assertEquals(0, Environment.editDistance("PLCVEC_TAG", "PLCVEC_TAG"));
        assertEquals(1, Environment.editDistance("PLCVEC_TAGG", "PLCVEC_TAG"));
        assertEquals(2, Environment.editDistance("PLCVEC_SHRAD", "PLCVEC_SHARD"));
        assertEquals(3, Environment.editDistance("kitten", "sitting"));
    }
}
