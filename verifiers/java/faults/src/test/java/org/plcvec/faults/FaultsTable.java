package org.plcvec.faults;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicContainer;
import org.junit.jupiter.api.DynamicNode;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.function.Executable;
import org.opentest4j.TestAbortedException;
import org.plcvec.verify.Environment;
import org.plcvec.verify.PlcvecTests;

import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * Many rows of the table of faults in one Surefire run (faults-entry --batch, for the rows that
 * leave the process as they found it): each row is a container of the dynamic tests the README's
 * factory gives under the row's own settings ({@link PlcvecTests#environment}), executed by JUnit
 * as a row run alone would be, with what the row prints captured apart. A row's status is what
 * Surefire's would be (1 when one of its tests failed or errored); its output, what it printed and
 * each failing test's message as Surefire's list of failures shows it. The plan and the folder of
 * results are {@code -Dplcvec.faults.plan} and {@code -Dplcvec.faults.out}. Not a test class by
 * Surefire's default names: it runs only when faults-entry names it.
 */
class FaultsTable {
    private static final JsonMapper JSON = JsonMapper.builder().build();

    @TestFactory
    Stream<DynamicNode> rows() throws IOException {
        Path plan = Path.of(System.getProperty("plcvec.faults.plan"));
        Path out = Path.of(System.getProperty("plcvec.faults.out"));
        List<DynamicNode> rows = new ArrayList<>();
        for (JsonNode row : JSON.readTree(Files.readString(plan, StandardCharsets.UTF_8))) {
            Row r = new Row(row.get("id").stringValue(), settings(row.get("env")), out);
            rows.add(DynamicContainer.dynamicContainer(r.id, Stream.of(r).flatMap(Row::tests)));
        }
        return rows.stream();
    }

    /** The row's PLCVEC_* variables, as its process would hold them. */
    private static Map<String, String> settings(JsonNode env) {
        Map<String, String> out = new TreeMap<>();
        env.properties().forEach(e -> {
            if (e.getKey().startsWith("PLCVEC_")) {
                out.put(e.getKey(), e.getValue().stringValue());
            }
        });
        return out;
    }

    /** One row: its tests, run with what they print captured, then its result written. */
    private static final class Row {
        final String id;
        final Map<String, String> env;
        final Path out;
        final ByteArrayOutputStream printed = new ByteArrayOutputStream();
        final PrintStream capture = new PrintStream(printed, true, StandardCharsets.UTF_8);
        final List<String> failures = new ArrayList<>();
        long started;

        Row(String id, Map<String, String> env, Path out) {
            this.id = id;
            this.env = env;
            this.out = out;
        }

        /** The factory's tests under the row's settings (built when the row starts), then the row's end. */
        Stream<DynamicNode> tests() {
            started = System.nanoTime();
            List<DynamicNode> nodes = new ArrayList<>();
            capturing(() -> {
                try {
                    PlcvecTests.of(Hostile.from(env)).environment(Environment.of(env)).stream()
                            .forEach(n -> nodes.add(wrapped((DynamicTest) n)));
                } catch (RuntimeException e) {   // as JUnit reports a factory that throws
                    failures.add("plcvec() \u00bb " + e.getClass().getSimpleName() + " " + e.getMessage());
                }
            });
            nodes.add(DynamicTest.dynamicTest("row result", this::write));
            return nodes.stream();
        }

        /** The test as JUnit runs it, its output captured; a failure recorded, as Surefire lists it, not thrown. */
        private DynamicNode wrapped(DynamicTest test) {
            return DynamicTest.dynamicTest(test.getDisplayName(), () -> captured(() -> {
                try {
                    test.getExecutable().execute();
                } catch (TestAbortedException skipped) {
                    // skipped: not a failure of the run
                } catch (AssertionError e) {
                    failures.add("FaultsTest." + test.getDisplayName() + " " + e.getMessage());
                } catch (Throwable e) {
                    failures.add("FaultsTest." + test.getDisplayName() + " \u00bb " + e.getClass().getSimpleName() + " "
                            + e.getMessage());
                }
            }));
        }

        private void captured(Executable body) throws Throwable {
            PrintStream stdout = System.out;
            PrintStream stderr = System.err;
            System.setOut(capture);
            System.setErr(capture);
            try {
                body.execute();
            } finally {
                System.setOut(stdout);
                System.setErr(stderr);
            }
        }

        private void capturing(Runnable body) {
            try {
                captured((Executable) body::run);
            } catch (Throwable e) {
                throw new IllegalStateException(e);
            }
        }

        /** The row's result: exit 1 when a test failed, as Surefire's; what it printed, then the failures. */
        private void write() throws IOException {
            StringBuilder output = new StringBuilder(printed.toString(StandardCharsets.UTF_8));
            if (!failures.isEmpty()) {
                output.append("[ERROR] Failures:\n");
                failures.forEach(f -> output.append("[ERROR]   ").append(f).append('\n'));
            }
            Map<String, Object> result = new TreeMap<>();
            result.put("status", failures.isEmpty() ? 0 : 1);
            result.put("output", output.toString());
            result.put("seconds", (System.nanoTime() - started) / 1e9);
            Files.writeString(out.resolve(id + ".json"), JSON.writeValueAsString(result), StandardCharsets.UTF_8);
        }
    }
}
