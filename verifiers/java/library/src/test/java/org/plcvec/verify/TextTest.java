package org.plcvec.verify;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.junit.jupiter.api.Test;

import tools.jackson.databind.JsonNode;

/**
 * The one text (verifiers/parity/TEXT.md) against the shared cases in verifiers/parity/text/: the
 * cases' vectors loaded by this library, the cases' answers judged by its own run, and the text
 * compared byte for byte with the whole expected text: the failure blocks, the roll-up by reading,
 * the skips by reason and the summary lines.
 */
class TextTest {
    static final Path CASES = Path.of("../../parity/text");

    /** An implementation that declares the cases' hello and answers from the cases' answers. */
    static Implementation fromCases() throws IOException {
        JsonNode cases = Suite.JSON.readTree(Files.readString(CASES.resolve("answers.json"), StandardCharsets.UTF_8));
        JsonNode hello = cases.get("hello");
        JsonNode answers = cases.get("answers");
        Map<String, String> declared = new java.util.TreeMap<>();
        hello.get("interpretations").properties().forEach(e -> declared.put(e.getKey(), e.getValue().stringValue()));
        Set<String> cpuWrites = new java.util.TreeSet<>();
        hello.get("cpu_writes").forEach(d -> cpuWrites.add(d.stringValue()));
        return new Implementation() {
            @Override
            public String name() {
                return hello.get("adapter").get("name").stringValue();
            }

            @Override
            public String version() {
                return hello.get("adapter").get("version").stringValue();
            }

            @Override
            public Choices choices() {
                return Choices.of(declared);
            }

            @Override
            public Set<String> cpuWrites() {
                return cpuWrites;
            }

            @Override
            public List<StepState> run(VectorRequest vector) {
                JsonNode answer = answers.get(vector.id());
                if (answer.has("skip")) {
                    throw new SkipVector(answer.get("skip").stringValue());
                }
                if (answer.has("error")) {
                    throw new VectorError(answer.get("error").stringValue());
                }
                List<StepState> steps = new ArrayList<>();
                for (JsonNode step : answer.get("steps")) {
                    Map<String, Object> devices = new java.util.LinkedHashMap<>();
                    step.get("devices").properties().forEach(e -> devices.put(e.getKey(),
                            e.getValue().isBoolean() ? (Object) e.getValue().booleanValue() : (Object) e.getValue().intValue()));
                    JsonNode result = step.get("result");
                    steps.add(StepState.of(result == null || result.isNull() ? null : result.booleanValue(), devices));
                }
                return steps;
            }
        };
    }

    /** The run's text with what depends on the machine left out, as the shared cases hold it (TEXT.md). */
    static String shared(String text) {
        return text.replaceFirst("(?m)^plcvec verify: .*\n", "").replaceFirst(" in \\d+\\.\\d\\d s\n$", "\n");
    }

    /** The shared cases run by this library's own run, with the known failures of {@code known.toml} or none. */
    static Report run(boolean withKnown) throws IOException {
        Verifier verifier = Verifier.of(fromCases()).suite(Suite.load(CASES.resolve("vectors")));
        if (withKnown) {
            // As the cases give it: the file's name as the user gave it, which the text repeats.
            verifier = verifier.expectations(KnownFailures.parse(read("known.toml"), "known.toml"));
        }
        return verifier.run().declaring(Rollup::verifyDeclaration);
    }

    static String read(String name) throws IOException {
        return Files.readString(CASES.resolve(name), StandardCharsets.UTF_8);
    }

    @Test
    void theRunsTextIsTheOneText() throws IOException {
        assertEquals(read("expected.txt"), shared(run(false).summary()));
    }

    @Test
    void withKnownFailuresTheRunsTextIsTheOneText() throws IOException {
        assertEquals(read("expected-known.txt"), shared(run(true).summary()));
    }

    @Test
    void theEndOfARunIsTheTextAfterTheFailureBlocks() throws IOException {
        // What a test runner prints at its end (each block was shown by its own test): from the roll-up on.
        String expected = read("expected.txt");
        assertEquals(expected.substring(expected.indexOf("READINGS: ")), shared(run(false).totals()));
        String known = read("expected-known.txt");
        assertEquals(known.substring(known.indexOf("READINGS: ")), shared(run(true).totals()));
    }

    /**
     * The factory's own end of run (its last test) prints the same text, with the declarations in
     * Java's syntax: the shared text with each {@code declare:} line rewritten as this runner
     * writes it, the {@code --choose} pairs taken from the line itself.
     */
    @Test
    void theFactorysEndOfRunPrintsTheOneTextInJavasSyntax() throws Throwable {
        Path known = Files.createTempFile("plcvec-known", ".toml");
        try {
            Files.writeString(known, read("known.toml"));
            PlcvecTests tests = PlcvecTests.of(fromCases()).suite(Suite.load(CASES.resolve("vectors")))
                    .environment(Environment.of(Map.of(Environment.KNOWN_FAILURES, known.toString())));
            String printed = PlcvecTestsTest.endOfRun(tests);
            String expected = read("expected-known.txt").replace("known.toml", known.toString());
            StringBuilder java = new StringBuilder();
            for (String line : expected.substring(expected.indexOf("READINGS: ")).split("\n", -1)) {
                java.append(line.startsWith("    declare: ") ? "    declare: " + Rollup.javaDeclaration(choose(line)) : line)
                        .append('\n');
            }
            assertEquals(java.substring(0, java.length() - 1), shared(printed));
        } finally {
            Files.delete(known);
        }
    }

    /** The pairs of a {@code declare: --choose ID=alt ...} line. */
    private static Map<String, String> choose(String line) {
        Map<String, String> out = new java.util.TreeMap<>();
        for (String item : line.substring(line.indexOf("--choose ")).split(" ")) {
            if (item.contains("=")) {
                out.put(item.substring(0, item.indexOf('=')), item.substring(item.indexOf('=') + 1));
            }
        }
        return out;
    }

    /** TEXT.md's table of declarations: this runner's row, and plcvec verify's, rendered from the generated names. */
    @Test
    void theDeclarationIsTheOneTextMdGivesJava() throws IOException {
        String text = Files.readString(CASES.resolve("../TEXT.md"), StandardCharsets.UTF_8);
        Map<String, String> choice = Map.of("FX5-SM709-SCOPE", "all-words", "TADD-FLAGS-OFF", "set-only");
        assertEquals(row(text, "Java"), Rollup.javaDeclaration(choice));
        assertEquals(row(text, "`plcvec verify`"), Rollup.verifyDeclaration(choice));
    }

    private static String row(String text, String runner) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("(?m)^\\| " + java.util.regex.Pattern.quote(runner)
                + " \\| `(.*)` \\|$").matcher(text);
        org.junit.jupiter.api.Assertions.assertTrue(m.find(), "TEXT.md has no row for " + runner);
        return m.group(1);
    }
}
