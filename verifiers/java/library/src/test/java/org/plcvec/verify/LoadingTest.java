package org.plcvec.verify;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import tools.jackson.databind.node.ObjectNode;

/**
 * What loading refuses (verifiers/CONTRACT.md, "Loading"), on a copy of the vectors in this jar
 * damaged for each case: a path that is not a regular file, by name and without waiting on it; a
 * repeated key, by file, line and vector; bytes that are not UTF-8, by file and line; a device of
 * two JSON types in one vector; a JSON-lines file whose last line does not end.
 */
class LoadingTest {
    private static final String FAMILY = "fx5-time-add";
    private static final Duration NO_WAIT = Duration.ofSeconds(20);

    @TempDir
    Path dir;
    private Path file;

    @BeforeEach
    void copy() throws IOException {
        for (String name : List.of("index.json", "cp1e-time-compare.jsonl", "fc6a-hour-meter.jsonl", "fx5-date-compare.jsonl",
                "fx5-time-add.jsonl", "fx5-time-compare.jsonl")) {
            try (InputStream in = Suite.class.getResourceAsStream(Suite.RESOURCES + name)) {
                Files.copy(in, dir.resolve(name));
            }
        }
        file = dir.resolve(FAMILY + ".jsonl");
    }

    private String refused() {
        return assertTimeoutPreemptively(NO_WAIT, () -> assertThrows(VerifyException.class, () -> Suite.load(dir)))
                .getMessage();
    }

    private static void run(String... command) throws IOException, InterruptedException {
        assertEquals(0, new ProcessBuilder(command).inheritIO().start().waitFor(), String.join(" ", command));
    }

    @Test
    void aFamilyFileThatIsANamedPipeIsRefusedByNameWithoutWaiting() throws Exception {
        Files.delete(file);
        run("mkfifo", file.toString());
        assertEquals(file + ": not a regular file (a named pipe)", refused());
    }

    @Test
    void anIndexThatIsANamedPipeIsRefusedByName() throws Exception {
        Path index = dir.resolve("index.json");
        Files.delete(index);
        run("mkfifo", index.toString());
        assertEquals(index + ": not a regular file (a named pipe)", refused());
    }

    @Test
    void aDeviceAFolderAndALoopAreRefusedByName() throws IOException {
        Files.delete(file);
        Files.createSymbolicLink(file, Path.of("/dev/zero"));
        assertEquals(file + ": not a regular file (a device)", refused());
        Files.delete(file);
        Files.createDirectory(file);
        assertEquals(file + ": not a regular file (a folder)", refused());
        Files.delete(file);
        Files.createSymbolicLink(file, file.getFileName());
        assertEquals(file + ": a loop of symbolic links", refused());
    }

    @Test
    void aKnownFailuresFileThatIsANamedPipeIsRefusedByName() throws Exception {
        Path known = dir.resolve("known.toml");
        run("mkfifo", known.toString());
        VerifyException e = assertTimeoutPreemptively(NO_WAIT, () -> assertThrows(VerifyException.class,
                () -> KnownFailures.load(known)));
        assertEquals(known + ": not a regular file (a named pipe)", e.getMessage());
    }

    /** The file's lines; line 1 is the header, line 2 the first vector. */
    private List<String> lines() throws IOException {
        return new ArrayList<>(List.of(Files.readString(file, StandardCharsets.UTF_8).split("\n")));
    }

    private void write(List<String> lines) throws IOException {
        Files.writeString(file, String.join("\n", lines) + "\n", StandardCharsets.UTF_8);
    }

    @Test
    void aRepeatedKeyIsRefusedByFileLineAndVector() throws IOException {
        List<String> lines = lines();
        String id = Suite.JSON.readTree(lines.get(2)).get("id").stringValue();
        lines.set(2, lines.get(2).replaceFirst("\\{", "{\"description\":\"a second one\","));
        write(lines);
        assertEquals(file + ":3: vector " + id + ": repeated key \"description\"", refused());
    }

    @Test
    void aRepeatedKeyInTheIndexIsRefusedByFileAndLine() throws IOException {
        Path index = dir.resolve("index.json");
        // Line 1 is "{", line 2 the index's own "families": the second occurrence, now that line 1 has one.
        Files.writeString(index, Files.readString(index).replaceFirst("\\{", "{\"families\": {}, "));
        assertEquals(index + ":2: repeated key \"families\"", refused());
    }

    @Test
    void aRepeatedKeyInAVectorsFolderIsRefusedByTheLineOfTheVector() throws IOException {
        Path folder = dir.resolve("vectors");
        Files.createDirectory(folder);
        Path cases = TextTest.CASES.resolve("vectors");
        try (var files = Files.list(cases)) {
            for (Path p : files.toList()) {
                Files.copy(p, folder.resolve(p.getFileName()));
            }
        }
        Path json = folder.resolve(FAMILY + ".json");
        List<String> lines = new ArrayList<>(List.of(Files.readString(json).split("\n", -1)));
        int at = -1;
        for (int i = 0; i < lines.size() && at < 0; i++) {
            at = lines.get(i).trim().startsWith("\"description\"") ? i : -1;
        }
        String id = null;
        for (int i = at; id == null; i--) {
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("\"id\": \"([^\"]*)\"").matcher(lines.get(i));
            id = m.find() ? m.group(1) : null;
        }
        lines.add(at, lines.get(at));   // the vector's description twice, on two lines
        Files.writeString(json, String.join("\n", lines));
        VerifyException e = assertThrows(VerifyException.class, () -> Suite.load(folder));
        assertEquals(json + ":" + (at + 2) + ": vector " + id + ": repeated key \"description\"", e.getMessage());
    }

    @Test
    void aByteThatIsNotUtf8IsNamedByFileAndLine() throws IOException {
        byte[] bytes = Files.readAllBytes(file);
        int second = new String(bytes, StandardCharsets.UTF_8).indexOf('\n') + 1;   // line 2 starts here
        bytes[second + 10] = (byte) 0xFF;
        Files.write(file, bytes);
        assertEquals(file + ":2: not UTF-8 text (byte " + (second + 10) + ")", refused());
    }

    @Test
    void aLastLineThatDoesNotEndIsACutFile() throws IOException {
        String text = Files.readString(file);
        Files.writeString(file, text.substring(0, text.length() - 1));
        assertEquals(file + ":" + text.split("\n").length + ": the last line does not end: the file was cut", refused());
    }

    /** Vector 2 of the file (line 3), with {@code edit} applied, written back. */
    private String damage(java.util.function.Consumer<ObjectNode> edit) throws IOException {
        List<String> lines = lines();
        ObjectNode v = (ObjectNode) Suite.JSON.readTree(lines.get(2));
        edit.accept(v);
        lines.set(2, v.toString());
        write(lines);
        return v.get("id").stringValue();
    }

    @Test
    void aBitHolding2AnywhereIsRefusedByVectorAndPath() throws IOException {
        String id = damage(v -> ((ObjectNode) v.get("final").get("devices")).put("SM700", 2));
        assertEquals(file + ":3: vector " + id + ": at final/devices/SM700: 2 is a word, but at initial/devices/SM700 the "
                + "same device holds true, a bit (true/false) (is the file a plcvec vector file, unedited?)", refused());
        copyBack();
        id = damage(v -> ((ObjectNode) v.get("steps").get(0)).putObject("set").put("SM8020", 2));
        assertEquals(file + ":3: vector " + id + ": at steps/0/set/SM8020: 2 is a word, but at initial/devices/SM8020 the "
                + "same device holds true, a bit (true/false) (is the file a plcvec vector file, unedited?)", refused());
    }

    private void copyBack() throws IOException {
        try (InputStream in = Suite.class.getResourceAsStream(Suite.RESOURCES + FAMILY + ".jsonl")) {
            Files.copy(in, file, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        }
    }
}
