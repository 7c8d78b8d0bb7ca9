package org.plcvec.verify;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import tools.jackson.databind.JsonNode;

/**
 * Turns the JSON of a vector (or of a run request) into {@link Vector} / {@link VectorRequest},
 * checking what the runner reads so that a damaged file is reported by vector id, not half-way
 * through a run.
 */
final class VectorParser {
    private VectorParser() {
    }

    /** A problem with one vector; the caller adds the file. */
    static final class Bad extends Exception {
        private static final long serialVersionUID = 1L;

        Bad(String message) {
            super(message);
        }
    }

    // The keys the schema (vectors/schema/vector-file.schema.json) has at each level. A key outside
    // them is refused, not ignored (CONTRACT.md, Loading): it may carry a meaning this runner would
    // silently miss.
    private static final Set<String> VECTOR_KEYS = Set.of("id", "family", "instruction", "st", "printed",
            "description", "tags", "clauses", "assumes", "initial", "steps", "final", "outcome", "alternatives");
    private static final Set<String> INITIAL_KEYS = Set.of("devices", "operands", "scratch");
    private static final Set<String> OPERAND_KEYS = Set.of("device", "constant");
    private static final Set<String> STEP_KEYS = Set.of("set", "rlo_in", "clock", "en", "input", "elapsed_ms", "expect");
    private static final Set<String> EXPECT_KEYS = Set.of("devices", "result");
    private static final Set<String> FINAL_KEYS = Set.of("devices");
    private static final Set<String> ASSUMES_KEYS = Set.of("device_sizes");
    private static final Set<String> OUTCOME_KEYS = Set.of("category", "errors");
    private static final Set<String> DEFINED_KEYS = Set.of("category", "interpretations", "default", "reason");
    private static final Set<String> ERROR_KEYS = Set.of("step", "code", "device");
    private static final Set<String> ALTERNATIVE_KEYS = Set.of("choices", "expect", "final", "outcome");
    /** An {@code alternatives} entry from schema 1.1 on: the devices it leaves unjudged, too. */
    private static final Set<String> ALTERNATIVE_KEYS_1_1 = Set.of("choices", "expect", "final", "outcome", "unjudged");
    static final Set<String> HEADER_KEYS = Set.of("count", "family", "generated", "instructions", "interpretations",
            "kind", "schema_version", "spec_file", "spec_sha256", "tags", "title");
    static final Set<String> INTERPRETATION_KEYS = Set.of("id", "question", "default", "alternatives");
    static final Set<String> ALTERNATIVE_HEADER_KEYS = Set.of("id", "says");

    /** A key the schema does not have at {@code path}: the first one, or null. */
    static String unknownKey(JsonNode node, Set<String> allowed, String path) {
        if (node == null || !node.isObject()) {
            return null;
        }
        for (String key : node.propertyNames()) {
            if (!allowed.contains(key)) {
                return (path.isEmpty() ? "" : path + "/") + key;
            }
        }
        return null;
    }

    private static void known(JsonNode node, Set<String> allowed, String path) throws Bad {
        String key = unknownKey(node, allowed, path);
        if (key != null) {
            throw new Bad(key + ": a key the schema does not have");
        }
    }

    private static void outcomeKeys(JsonNode outcome, String path) throws Bad {
        known(outcome, outcome.has("interpretations") ? DEFINED_KEYS : OUTCOME_KEYS, path);
        int i = 0;
        for (JsonNode e : outcome.path("errors")) {
            known(e, ERROR_KEYS, path + "/errors/" + i++);
        }
        if (outcome.has("default")) {
            outcomeKeys(outcome.get("default"), path + "/default");
        }
    }

    private static void knownKeys(JsonNode v, int schemaMinor) throws Bad {
        known(v, VECTOR_KEYS, "");
        known(v.path("assumes"), ASSUMES_KEYS, "assumes");
        known(v.get("initial"), INITIAL_KEYS, "initial");
        for (java.util.Map.Entry<String, JsonNode> operand : v.get("initial").path("operands").properties()) {
            known(operand.getValue(), OPERAND_KEYS, "initial/operands/" + operand.getKey());
        }
        int i = 0;
        for (JsonNode st : v.get("steps")) {
            known(st, STEP_KEYS, "steps/" + i);
            known(st.get("expect"), EXPECT_KEYS, "steps/" + i++ + "/expect");
        }
        known(v.get("final"), FINAL_KEYS, "final");
        outcomeKeys(v.get("outcome"), "outcome");
        i = 0;
        for (JsonNode alt : v.path("alternatives")) {
            String path = "alternatives/" + i++;
            known(alt, schemaMinor >= 1 ? ALTERNATIVE_KEYS_1_1 : ALTERNATIVE_KEYS, path);
            int s = 0;
            for (JsonNode e : alt.path("expect")) {
                known(e, EXPECT_KEYS, path + "/expect/" + s++);
            }
            known(alt.path("final"), FINAL_KEYS, path + "/final");
            if (alt.has("outcome")) {
                outcomeKeys(alt.get("outcome"), path + "/outcome");
            }
        }
    }

    /**
     * One vector of a family file whose schema is 1.{@code schemaMinor}: the keys that version
     * names, what the schema and {@link Validate} check of it, and its expectations.
     */
    static Vector vector(JsonNode v, String family, int schemaMinor) throws Bad {
        if (!v.isObject()) {
            throw new Bad("not a JSON object");
        }
        for (String key : new String[] {"id", "family", "instruction"}) {
            if (!v.path(key).isString()) {
                throw new Bad("no `" + key + "` (string)");
            }
        }
        if (family != null && !family.equals(v.get("family").stringValue())) {
            throw new Bad("family '" + v.get("family").stringValue() + "' in a '" + family + "' file");
        }
        for (String key : new String[] {"initial", "final", "outcome"}) {
            if (!v.path(key).isObject()) {
                throw new Bad("no `" + key + "` (object)");
            }
        }
        JsonNode steps = v.path("steps");
        if (!steps.isArray() || steps.isEmpty()) {
            throw new Bad("no `steps` (a non-empty list)");
        }
        for (JsonNode st : steps) {
            if (!st.path("expect").isObject()) {
                throw new Bad("every step needs an `expect`");
            }
        }
        if (!v.path("final").path("devices").isObject()) {
            throw new Bad("`final` needs `devices`");
        }
        knownKeys(v, schemaMinor);
        String problem = Validate.vectorProblem(v);
        if (problem != null) {
            throw new Bad(problem);
        }
        Set<String> names = new LinkedHashSet<>();
        JsonNode outcome = v.get("outcome");
        List<String> interpretations = strings(outcome.path("interpretations"), "outcome.interpretations");
        Vector.Expectation expectation;
        List<Vector.Variant> variants = new ArrayList<>();
        // First pass: every device the vector names, so the device table is complete.
        collectStepNames(steps, names);
        collectNames(v.get("final").get("devices"), names);
        for (JsonNode alt : v.path("alternatives")) {
            collectStepNames(alt.path("expect"), names);
            collectNames(alt.path("final").path("devices"), names);
        }
        VectorRequest request = request(v, names);
        String category = interpretations.isEmpty() ? outcome.path("category").asString("")
                : outcome.path("default").path("category").asString("");
        expectation = expectation(steps, v.get("final").get("devices"), category, request.steps().size());
        JsonNode alts = v.path("alternatives");
        if (!alts.isMissingNode() && !alts.isArray()) {
            throw new Bad("`alternatives` is not a list");
        }
        for (JsonNode alt : alts) {
            JsonNode choices = alt.path("choices");
            if (!choices.isObject() || !alt.path("expect").isArray() || !alt.path("final").path("devices").isObject()) {
                throw new Bad("an entry of `alternatives` needs `choices`, `expect` and `final.devices`");
            }
            Map<String, String> chosen = new LinkedHashMap<>();
            for (Map.Entry<String, JsonNode> e : choices.properties()) {
                chosen.put(e.getKey(), e.getValue().asString());
            }
            if (alt.get("expect").size() != request.steps().size()) {
                throw new Bad(request.steps().size() + " steps but an alternative gives " + alt.get("expect").size()
                        + " expectations");
            }
            variants.add(new Vector.Variant(chosen, expectation(alt.get("expect"), alt.get("final").get("devices"),
                    alt.path("outcome").path("category").asString(""), request.steps().size()), unjudged(alt)));
        }
        return new Vector(request, v.path("description").asString(""), strings(v.path("tags"), "tags"),
                strings(v.path("clauses"), "clauses"), interpretations, expectation, variants);
    }

    /** An entry's {@code unjudged} map (checked by {@link Validate}): interpretation to devices, both sorted. */
    private static Map<String, List<String>> unjudged(JsonNode alt) {
        Map<String, List<String>> out = new java.util.TreeMap<>();
        for (Map.Entry<String, JsonNode> e : alt.path("unjudged").properties()) {
            List<String> devices = new ArrayList<>();
            e.getValue().forEach(d -> devices.add(d.stringValue()));
            out.put(e.getKey(), List.copyOf(devices));
        }
        return out;
    }

    /** A run request (the protocol's vector without expectations). */
    static VectorRequest request(JsonNode v) throws Bad {
        if (!v.isObject()) {
            throw new Bad("not a JSON object");
        }
        for (String key : new String[] {"id", "family", "instruction"}) {
            if (!v.path(key).isString()) {
                throw new Bad("no `" + key + "` (string)");
            }
        }
        if (!v.path("initial").isObject() || !v.path("steps").isArray()) {
            throw new Bad("needs `initial` and `steps`");
        }
        Set<String> names = new LinkedHashSet<>();
        collectStepNames(v.get("steps"), names);
        return request(v, names);
    }

    private static VectorRequest request(JsonNode v, Set<String> others) throws Bad {
        JsonNode initial = v.get("initial");
        JsonNode devices = initial.path("devices");
        JsonNode operands = initial.path("operands");
        if (!devices.isObject() || !operands.isObject()) {
            throw new Bad("`initial` needs `devices` and `operands`");
        }
        Map<String, Integer> table = new LinkedHashMap<>();
        List<Integer> values = new ArrayList<>();
        for (Map.Entry<String, JsonNode> e : devices.properties()) {
            table.put(e.getKey(), table.size());
            values.add(value(e.getValue(), "initial.devices." + e.getKey()));
        }
        int listed = table.size();
        Set<String> scratch = new LinkedHashSet<>(strings(initial.path("scratch"), "initial.scratch"));
        for (String name : scratch) {
            table.putIfAbsent(name, table.size());
        }
        for (String name : others) {
            table.putIfAbsent(name, table.size());
        }
        Address[] slots = new Address[table.size()];
        int[] init = new int[table.size()];
        boolean[] compared = new boolean[table.size()];
        for (Map.Entry<String, Integer> e : table.entrySet()) {
            int i = e.getValue();
            slots[i] = Address.of(e.getKey());
            init[i] = i < listed ? values.get(i) : Values.ABSENT;
            compared[i] = !scratch.contains(e.getKey());
        }
        Map<String, Operand> ops = new LinkedHashMap<>();
        for (Map.Entry<String, JsonNode> e : operands.properties()) {
            JsonNode o = e.getValue();
            if (o.path("device").isString()) {
                ops.put(e.getKey(), Operand.device(o.get("device").stringValue()));
            } else if (o.path("constant").isIntegralNumber()) {
                ops.put(e.getKey(), Operand.constant(o.get("constant").longValue()));
            } else {
                throw new Bad("operand " + e.getKey() + " is neither {\"device\": ...} nor {\"constant\": ...}");
            }
        }
        Map<String, Integer> sizes = new LinkedHashMap<>();
        for (Map.Entry<String, JsonNode> e : v.path("assumes").path("device_sizes").properties()) {
            if (!e.getValue().canConvertToInt()) {
                throw new Bad("assumes.device_sizes." + e.getKey() + " is not an integer");
            }
            sizes.put(e.getKey(), e.getValue().intValue());
        }
        List<Step> steps = new ArrayList<>();
        for (JsonNode st : v.get("steps")) {
            steps.add(step(st, steps.size()));
        }
        return new VectorRequest(v.get("id").stringValue(), v.get("family").stringValue(),
                v.get("instruction").stringValue(), new DeviceSizes(sizes), ops, scratch, steps, slots, init, compared,
                listed);
    }

    private static Step step(JsonNode st, int index) throws Bad {
        if (!st.isObject()) {
            throw new Bad("step " + index + " is not an object");
        }
        JsonNode set = st.path("set");
        Address[] setDevices = new Address[set.size()];
        int[] setValues = new int[set.size()];
        int i = 0;
        for (Map.Entry<String, JsonNode> e : set.properties()) {
            setDevices[i] = Address.of(e.getKey());
            setValues[i++] = value(e.getValue(), "steps[" + index + "].set." + e.getKey());
        }
        Map<String, Integer> clock = null;
        if (st.path("clock").isObject()) {
            clock = new LinkedHashMap<>();
            for (Map.Entry<String, JsonNode> e : st.get("clock").properties()) {
                clock.put(e.getKey(), e.getValue().asInt());
            }
        }
        return new Step(index, setDevices, setValues, bool(st, "rlo_in", index), clock, bool(st, "en", index),
                bool(st, "input", index), st.path("elapsed_ms").isIntegralNumber() ? st.get("elapsed_ms").longValue() : null);
    }

    private static Boolean bool(JsonNode st, String key, int index) throws Bad {
        JsonNode n = st.get(key);
        if (n == null || n.isNull()) {
            return null;
        }
        if (!n.isBoolean()) {
            throw new Bad("steps[" + index + "]." + key + " is not true/false");
        }
        return n.booleanValue();
    }

    private static Vector.Expectation expectation(JsonNode expects, JsonNode fin, String category, int steps) throws Bad {
        if (expects.size() != steps) {
            throw new Bad(steps + " steps but " + expects.size() + " expectations");
        }
        List<Vector.StepExpect> out = new ArrayList<>();
        for (JsonNode st : expects) {
            JsonNode e = st.has("expect") ? st.get("expect") : st;
            JsonNode result = e.get("result");
            if (result != null && !result.isBoolean()) {
                throw new Bad("an expected `result` is not true/false");
            }
            JsonNode devices = e.path("devices");
            Address[] a = new Address[devices.size()];
            int[] v = new int[devices.size()];
            int i = 0;
            for (Map.Entry<String, JsonNode> d : devices.properties()) {
                a[i] = Address.of(d.getKey());
                v[i++] = value(d.getValue(), "expect.devices." + d.getKey());
            }
            out.add(new Vector.StepExpect(result == null ? null : result.booleanValue(), a, v));
        }
        Address[] fa = new Address[fin.size()];
        int[] fv = new int[fin.size()];
        int i = 0;
        for (Map.Entry<String, JsonNode> d : fin.properties()) {
            fa[i] = Address.of(d.getKey());
            fv[i++] = value(d.getValue(), "final.devices." + d.getKey());
        }
        return new Vector.Expectation(out, fa, fv, category);
    }

    private static void collectStepNames(JsonNode steps, Set<String> names) {
        for (JsonNode st : steps) {
            collectNames(st.path("set"), names);
            JsonNode e = st.has("expect") ? st.get("expect") : st;
            collectNames(e.path("devices"), names);
        }
    }

    private static void collectNames(JsonNode devices, Set<String> names) {
        names.addAll(devices.propertyNames());
    }

    /** A device value: a word 0..65535 or a bit true/false, nothing else. */
    private static int value(JsonNode n, String where) throws Bad {
        if (n.isBoolean()) {
            return Values.bit(n.booleanValue());
        }
        if (n.isIntegralNumber() && n.canConvertToInt() && Values.isWord(n.intValue())) {
            return n.intValue();
        }
        throw new Bad(where + " is " + n + ", neither a word 0..65535 nor true/false");
    }

    static List<String> strings(JsonNode n, String where) throws Bad {
        List<String> out = new ArrayList<>();
        if (n.isMissingNode() || n.isNull()) {
            return out;
        }
        if (!n.isArray()) {
            throw new Bad("`" + where + "` is not a list");
        }
        for (JsonNode s : n) {
            if (!s.isString()) {
                throw new Bad("`" + where + "` holds " + s + ", not a string");
            }
            out.add(s.stringValue());
        }
        return out;
    }
}
