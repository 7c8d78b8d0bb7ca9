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
 * compared byte for byte with the expected one. Today the skips by reason, the summary lines and
 * each failure block's {@code judged by:} line (the interpretations that decide a field), step
 * inputs, operand words and field lines (with the value the implementation held before the step);
 * the roll-up by reading is not yet this runner's text.
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
                    throw new IllegalStateException(answer.get("error").stringValue());
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

    @Test
    void theSkipsAndTheSummaryLinesAreTheOneText() throws IOException {
        Report report = Verifier.of(fromCases()).suite(Suite.load(CASES.resolve("vectors"))).run();
        String expected = Files.readString(CASES.resolve("expected.txt"), StandardCharsets.UTF_8);
        // From the skips to the end; the machine-dependent header line is not in the expected text.
        String tail = expected.substring(expected.indexOf("SKIPPED "));
        assertEquals(tail, report.skipsByReason() + "\n" + report.summaryLines() + "\n");
    }

    /** Each failing vector's {@code judged by:}, {@code step k inputs:}, {@code step k operands:} and field lines, by id. */
    private static Map<String, List<String>> stepLines(List<String> lines) {
        Map<String, List<String>> out = new java.util.TreeMap<>();
        String id = null;
        for (String line : lines) {
            if (line.startsWith("FAIL ")) {
                id = line.substring("FAIL ".length());
                out.put(id, new ArrayList<>());
            } else if (!line.startsWith("    ")) {
                id = null;
            } else if (id != null && line.matches("    (judged by: |step \\d+ (inputs|operands): |step \\d+ \\S+: expected |steps: expected ).*")) {
                out.get(id).add(line);
            }
        }
        return out;
    }

    @Test
    void theStepInputsOperandWordsAndFieldLinesAreTheOneText() throws IOException {
        Report report = Verifier.of(fromCases()).suite(Suite.load(CASES.resolve("vectors"))).run();
        String expected = Files.readString(CASES.resolve("expected.txt"), StandardCharsets.UTF_8);
        List<String> ours = new ArrayList<>();
        for (Verdict v : report.verdicts()) {
            if (v.status() == Status.FAIL) {
                ours.addAll(List.of(v.report().split("\n")));
            }
        }
        Map<String, List<String>> want = stepLines(List.of(expected.split("\n")));
        assertEquals(want, stepLines(ours));
        assertEquals(12, want.values().stream().filter(l -> !l.isEmpty()).count());   // the cases hold them
    }
}
