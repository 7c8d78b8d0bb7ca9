package org.plcvec.verify;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Map;

import org.junit.jupiter.api.Test;

class KnownFailuresTest {
    static final String WRONG = "fx5-time-add/TADD/manual-example/program";
    static final String RIGHT = "fx5-time-add/TADD/carry/below-wrap/flags-off-before";

    /** Gets D31 wrong on the manual's example only. */
    private static Report run(String toml) {
        Implementation impl = Fakes.echo((s, d) -> {
            if (Integer.valueOf(40).equals(d.get("D31")) && Integer.valueOf(15).equals(d.get("D32"))) {
                d.put("D31", 41);
            }
        });
        return Verifier.of(impl).selection(Selection.all().ids(WRONG, RIGHT))
                .expectations(KnownFailures.parse(toml, "known.toml")).run();
    }

    @Test
    void aListedFailureIsXfailAndTheRunPasses() {
        Report r = run("[[known-failure]]\nid = \"" + WRONG + "\"\nreason = \"D31 off by one\"\n");
        assertTrue(r.passed(), r.summary());
        Verdict x = r.verdicts().stream().filter(y -> y.id().equals(WRONG)).findFirst().orElseThrow();
        assertEquals(Status.XFAIL, x.status());
        assertTrue(x.message().startsWith("known failure (known.toml:1): D31 off by one"), x.message());
    }

    @Test
    void aListedPassIsStaleAndFails() {
        Report r = run("[[known-failure]]\nid = \"" + WRONG + "\"\nreason = \"x\"\n\n[[known-failure]]\nid = \"" + RIGHT
                + "\"\nreason = \"fixed long ago\"\n");
        assertFalse(r.passed());
        Verdict x = r.verdicts().stream().filter(y -> y.id().equals(RIGHT)).findFirst().orElseThrow();
        assertEquals(Status.STALE, x.status());
        assertTrue(x.message().contains("known.toml:5"), x.message());
    }

    @Test
    void anUnknownIdIsStale() {
        Report r = run("[[known-failure]]\nid = \"" + WRONG + "\"\nreason = \"x\"\n[[known-failure]]\nid = \"gone/vector\"\n"
                + "reason = \"renamed\"\n");
        assertFalse(r.passed());
        assertEquals(1, r.counts().get(Status.STALE));
        assertTrue(r.summary().contains("STALE gone/vector"), r.summary());
    }

    @Test
    void theFailuresOfARunBecomeAStartingList(@org.junit.jupiter.api.io.TempDir java.nio.file.Path tmp) throws Exception {
        java.nio.file.Path file = tmp.resolve("known.toml");
        assertEquals(1, run("").writeExpectations(file, "not \"yet\" done"));
        KnownFailures written = KnownFailures.load(file);
        assertEquals(java.util.Set.of(WRONG), written.entries().keySet());
        assertEquals("not \"yet\" done", written.entries().get(WRONG).reason());
        assertEquals(3, written.entries().get(WRONG).line());
        assertTrue(run(java.nio.file.Files.readString(file)).passed());
    }

    @Test
    void mistakesAreNamedWithFileAndLine() {
        assertEquals("known.toml:3: x/y: every known failure needs a `reason`", assertThrows(VerifyException.class,
                () -> KnownFailures.parse("# c\n\n[[known-failure]]\nid = \"x/y\"\n", "known.toml")).getMessage());
        assertEquals("known.toml:4: x/y is listed twice (first at line 1)", assertThrows(VerifyException.class,
                () -> KnownFailures.parse("[[known-failure]]\nid = \"x/y\"\nreason = \"a\"\n[[known-failure]]\nid = \"x/y\"\n"
                        + "reason = \"b\"\n", "known.toml")).getMessage());
        assertEquals("known.toml:1: unknown key 'skip'; an expectations file holds only [[known-failure]] entries",
                assertThrows(VerifyException.class, () -> KnownFailures.parse("skip = 1\n", "known.toml")).getMessage());
        assertEquals("known.toml:1: unknown key 'pattern' (an entry has `id` and `reason`)", assertThrows(
                VerifyException.class, () -> KnownFailures.parse("[[known-failure]]\npattern = \"*\"\n", "known.toml"))
                .getMessage());
        String bad = assertThrows(VerifyException.class, () -> KnownFailures.parse("[[known-failure]\nid = 1\n", "known.toml"))
                .getMessage();
        assertTrue(bad.matches("known.toml:[12]: not valid TOML: .*"), bad);   // the line the parser stopped on
        assertEquals(Map.of(), KnownFailures.parse("", "empty.toml").entries());
    }
}
