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

    @Test
    void theRunsTextIsTheOneText() throws IOException {
        Report report = Verifier.of(fromCases()).suite(Suite.load(CASES.resolve("vectors"))).run();
        String expected = Files.readString(CASES.resolve("expected.txt"), StandardCharsets.UTF_8);
        assertEquals(expected, shared(report.summary()));
    }

    @Test
    void theEndOfARunIsTheTextAfterTheFailureBlocks() throws IOException {
        // What a test runner prints at its end (each block was shown by its own test): from the roll-up on.
        Report report = Verifier.of(fromCases()).suite(Suite.load(CASES.resolve("vectors"))).run();
        String expected = Files.readString(CASES.resolve("expected.txt"), StandardCharsets.UTF_8);
        assertEquals(expected.substring(expected.indexOf("READINGS: ")), shared(report.totals()));
    }
}
