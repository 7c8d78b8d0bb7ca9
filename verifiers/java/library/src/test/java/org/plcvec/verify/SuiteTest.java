package org.plcvec.verify;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.plcvec.spec.Family;
import org.plcvec.spec.Interpretation;
import org.plcvec.spec.SuiteInfo;

class SuiteTest {
    @TempDir
    Path tmp;

    /** The repository's vectors/ folder, two levels above verifiers/java/library. */
    static final Path REPO_VECTORS = Path.of("../../../vectors").toAbsolutePath().normalize();

    @Test
    void theJarCarriesTheGoldenSet() {
        Suite s = Suite.fromResources();
        assertEquals(SuiteInfo.TOTAL, s.vectors().size());
        assertEquals(SuiteInfo.SPEC_SHA256, s.specSha256());
        assertEquals(Family.values().length, s.families().size());
        for (Family f : Family.values()) {
            assertTrue(s.families().contains(f.id()), f.id());
        }
        // An interpretation shared by two families is listed once, with both.
        assertEquals(List.of("fx5-date-compare", "fx5-time-compare"),
                s.interpretations().get(Interpretation.FX5_SM709_SCOPE.id()).families());
    }

    @Test
    void theRepositoryFolderLoadsTheSameVectors() {
        Suite repo = Suite.load(REPO_VECTORS);
        Suite jar = Suite.fromResources();
        assertEquals(jar.vectors().size(), repo.vectors().size());
        assertEquals(jar.vectors().get(0).id(), repo.vectors().get(0).id());
        assertEquals(jar.specSha256(), repo.specSha256());
    }

    private Path compactCopy() throws IOException {
        Path dir = tmp.resolve("copy");
        Files.createDirectories(dir);
        for (String name : List.of("index.json", "fx5-time-add.jsonl")) {
            try (var in = Suite.class.getResourceAsStream(Suite.RESOURCES + name)) {
                Files.write(dir.resolve(name), in.readAllBytes());
            }
        }
        // Keep only the one family in the index.
        String index = Files.readString(dir.resolve("index.json"));
        var node = (tools.jackson.databind.node.ObjectNode) Suite.JSON.readTree(index);
        var fams = (tools.jackson.databind.node.ObjectNode) node.get("families");
        fams.retain("fx5-time-add");
        Files.writeString(dir.resolve("index.json"), node.toString());
        return dir;
    }

    @Test
    void anOverrideFolderLoads() throws IOException {
        Suite s = Suite.load(compactCopy());
        assertEquals(List.of("fx5-time-add"), s.families());
    }

    @Test
    void aDamagedCopyIsNamedByFile() throws IOException {
        Path dir = compactCopy();
        Path file = dir.resolve("fx5-time-add.jsonl");
        Files.writeString(file, Files.readString(file).replace("\"TADD\"", "\"TADX\""));
        VerifyException e = assertThrows(VerifyException.class, () -> Suite.load(dir));
        assertTrue(e.getMessage().contains("fx5-time-add.jsonl: its sha256 is not the one index.json records"), e.getMessage());
    }

    @Test
    void aBrokenLineIsNamedByFileAndLine() throws IOException {
        List<String> lines = Files.readAllLines(compactCopy().resolve("fx5-time-add.jsonl"));
        lines.set(2, lines.get(2).substring(0, 40));
        Path file = tmp.resolve("one.jsonl");
        Files.write(file, lines, StandardCharsets.UTF_8);
        VerifyException e = assertThrows(VerifyException.class, () -> Suite.load(file));
        assertTrue(e.getMessage().startsWith(file + ":3: not valid JSON"), e.getMessage());
    }

    @Test
    void aVectorMissingWhatTheContractNeedsIsNamedById() throws IOException {
        List<String> lines = Files.readAllLines(compactCopy().resolve("fx5-time-add.jsonl"));
        var v = (tools.jackson.databind.node.ObjectNode) Suite.JSON.readTree(lines.get(1));
        String id = v.get("id").stringValue();
        v.remove("final");
        lines.set(1, v.toString());
        Path file = tmp.resolve("one.jsonl");
        Files.write(file, lines, StandardCharsets.UTF_8);
        VerifyException e = assertThrows(VerifyException.class, () -> Suite.load(file));
        assertEquals(file + ":2: vector " + id + ": no `final` (object) (is the file a plcvec vector file, unedited?)",
                e.getMessage());
    }

    @Test
    void anUnknownMajorSchemaVersionIsRefused() throws IOException {
        List<String> lines = Files.readAllLines(compactCopy().resolve("fx5-time-add.jsonl"));
        lines.set(0, lines.get(0).replace("\"schema_version\":\"1.", "\"schema_version\":\"2."));
        Path file = tmp.resolve("one.jsonl");
        Files.write(file, lines, StandardCharsets.UTF_8);
        VerifyException e = assertThrows(VerifyException.class, () -> Suite.load(file));
        assertTrue(e.getMessage().contains("is not 1.x; this verifier reads 1.x files only"), e.getMessage());
    }

    @Test
    void aMissingFolderIsNamed() {
        VerifyException e = assertThrows(VerifyException.class, () -> Suite.load(tmp.resolve("nope")));
        assertTrue(e.getMessage().startsWith(tmp.resolve("nope") + ": no such vector folder or file"), e.getMessage());
    }
}
