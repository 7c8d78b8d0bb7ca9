package org.plcvec.verify;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;

import tools.jackson.core.JacksonException;
import tools.jackson.databind.JsonNode;

/**
 * Serves an {@link Implementation} over the stdio protocol (PROTOCOL.md), so
 * {@code plcvec verify --adapter "java -cp ... MyMain"} drives it as a process.
 *
 * <pre>{@code
 * public static void main(String[] args) {
 *     System.exit(StdioServer.serve(new MyEmulator()));
 * }
 * }</pre>
 *
 * <p>Malformed input never crashes it: a line that is not a protocol message is answered with
 * {@code fatal} (exit 2), a vector it cannot read with an {@code error} result for that vector.
 */
public final class StdioServer {
    /** The protocol version spoken. */
    public static final int PROTOCOL = 1;

    private StdioServer() {
    }

    /**
     * Serve on System.in and System.out until {@code bye} or end of input.
     *
     * @param implementation the implementation to serve
     * @return the exit status: 0, or 2 after a {@code fatal} message
     */
    public static int serve(Implementation implementation) {
        return serve(implementation, System.in, System.out);
    }

    /**
     * Serve on the given streams until {@code bye} or end of input.
     *
     * @param implementation the implementation to serve
     * @param in where the runner's messages are read
     * @param out where the answers are written
     * @return the exit status: 0, or 2 after a {@code fatal} message
     */
    public static int serve(Implementation implementation, InputStream in, OutputStream out) {
        PrintStream o = new PrintStream(out, false, StandardCharsets.UTF_8);
        BufferedReader reader = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8));
        int n = 0;
        try {
            String line;
            while ((line = reader.readLine()) != null) {
                n++;
                if (line.isBlank()) {
                    continue;
                }
                JsonNode msg;
                try {
                    msg = Suite.JSON.readTree(line);
                } catch (JacksonException e) {
                    return fatal(o, "line " + n + " is not JSON (" + e.getOriginalMessage() + "): " + clip(line));
                }
                String type = msg.path("type").asString("");
                switch (type) {
                    case "hello":
                        if (msg.path("protocol").asInt(-1) != PROTOCOL) {
                            fatal(o, "this adapter speaks protocol " + PROTOCOL + ", not " + msg.path("protocol"));
                            return 1;
                        }
                        String problem = hello(implementation, msg, o);
                        if (problem != null) {
                            return fatal(o, problem);
                        }
                        break;
                    case "run":
                        if (!msg.path("vectors").isArray()) {
                            return fatal(o, "line " + n + ": a run message needs `vectors` (a list)");
                        }
                        for (JsonNode v : msg.get("vectors")) {
                            if (!v.path("id").isString()) {
                                return fatal(o, "line " + n + ": a vector without an `id` cannot be answered: " + clip(v.toString()));
                            }
                            write(o, run(implementation, v));
                        }
                        o.flush();   // once per batch: a flush per result would cost more than the result
                        break;
                    case "bye":
                        o.flush();
                        return 0;
                    default:
                        return fatal(o, "line " + n + ": unknown message type '" + type + "' (expected hello, run or bye)");
                }
            }
        } catch (IOException e) {
            return fatal(o, "reading stdin: " + e.getMessage());
        }
        o.flush();
        return 0;
    }

    private static String hello(Implementation impl, JsonNode msg, PrintStream o) {
        TreeSet<String> instructions = new TreeSet<>();
        Map<String, String> interpretations = new LinkedHashMap<>();
        Map<String, String> declared = impl.choices().asMap();
        for (Map.Entry<String, JsonNode> f : msg.path("families").properties()) {
            for (JsonNode i : f.getValue().path("instructions")) {
                if (impl.supports(i.asString())) {
                    instructions.add(i.asString());
                }
            }
            for (Map.Entry<String, JsonNode> i : f.getValue().path("interpretations").properties()) {
                String alt = declared.getOrDefault(i.getKey(), i.getValue().path("default").asString(""));
                List<String> alternatives = new ArrayList<>();
                i.getValue().path("alternatives").forEach(a -> alternatives.add(a.asString()));
                if (!alternatives.isEmpty() && !alternatives.contains(alt)) {
                    return impl.name() + " follows " + i.getKey() + "=" + alt + ", which the runner's suite does not "
                            + "offer (" + String.join(", ", alternatives) + ")";
                }
                interpretations.put(i.getKey(), alt);
            }
        }
        Map<String, Object> answer = new LinkedHashMap<>();
        answer.put("type", "hello");
        answer.put("protocol", PROTOCOL);
        Map<String, Object> adapter = new LinkedHashMap<>();
        adapter.put("name", impl.name());
        adapter.put("version", impl.version());
        answer.put("adapter", adapter);
        answer.put("instructions", new ArrayList<>(instructions));
        answer.put("interpretations", interpretations);
        if (!impl.cpuWrites().isEmpty()) {
            answer.put("cpu_writes", new ArrayList<>(new java.util.TreeSet<>(impl.cpuWrites())));
        }
        write(o, answer);
        o.flush();
        return null;
    }

    private static Map<String, Object> run(Implementation impl, JsonNode v) {
        Map<String, Object> result = new LinkedHashMap<>();
        result.put("type", "result");
        result.put("id", v.get("id").stringValue());
        VectorRequest request;
        try {
            request = VectorParser.request(v);
        } catch (VectorParser.Bad e) {
            result.put("error", "the adapter cannot read this vector: " + e.getMessage());
            return result;
        }
        try {
            List<StepState> states = impl.run(request);
            List<Object> steps = new ArrayList<>();
            for (StepState st : states) {
                Map<String, Object> step = new LinkedHashMap<>();
                if (st.result() != null) {
                    step.put("result", st.result());
                }
                step.put("devices", st.devices().toMap());
                steps.add(step);
            }
            result.put("steps", steps);
        } catch (SkipVector s) {
            result.put("skip", s.getMessage());
        } catch (VectorError e) {   // the implementation's own words, as plcvec verify shows them
            result.put("error", e.getMessage());
        } catch (VirtualMachineError fatal) {
            throw fatal;
        } catch (Throwable t) {   // the implementation's failure on this vector, not the loop's
            result.put("error", Judge.describe(t));
        }
        return result;
    }

    private static int fatal(PrintStream o, String message) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("type", "fatal");
        m.put("message", message);
        write(o, m);
        o.flush();
        return 2;
    }

    private static void write(PrintStream o, Map<String, Object> message) {
        o.print(Suite.JSON.writeValueAsString(message));
        o.print('\n');
    }

    private static String clip(String s) {
        return s.length() > 200 ? s.substring(0, 200) + "..." : s;
    }
}
