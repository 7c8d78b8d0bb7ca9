package org.plcvec.verify;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;

import tools.jackson.databind.JsonNode;

/**
 * What the vector-file schema cannot say of one vector, checked on load as {@code plcvec verify}
 * checks it (CONTRACT.md, "Loading"), so that a damaged vector is refused by its id and JSON path
 * instead of being blamed on the implementation:
 * <ul>
 * <li>an entry's {@code unjudged} map (schema 1.1): its shape, each interpretation one of the
 * entry's choices, each device sorted, listed in {@code initial.devices} and expected nowhere by
 * the entry;</li>
 * <li>one JSON type per device across {@code initial}, each step's {@code set} and {@code expect},
 * {@code final} and the alternatives: a bit holding {@code 2} anywhere is a word where a bit is.</li>
 * </ul>
 */
final class Validate {
    /** The schema's patterns for an interpretation id and a device name. */
    private static final Pattern INTERPRETATION = Pattern.compile("[A-Za-z0-9][A-Za-z0-9_.<>=-]*");
    private static final Pattern DEVICE = Pattern.compile("[A-Za-z_]+[0-9]*");

    private Validate() {
    }

    /**
     * The first thing wrong with vector {@code v} that the schema cannot say.
     *
     * @return {@code at <path>: <what>}, or null when there is nothing
     */
    static String vectorProblem(JsonNode v) {
        String problem = unjudgedProblem(v);
        return problem != null ? problem : typeProblem(v);
    }

    private static String unjudgedProblem(JsonNode v) {
        JsonNode listed = v.path("initial").path("devices");
        int a = 0;
        for (JsonNode alt : v.path("alternatives")) {
            String at = "at alternatives/" + a++ + "/unjudged";
            JsonNode map = alt.get("unjudged");
            if (map == null) {
                continue;
            }
            if (!map.isObject() || map.isEmpty()) {
                return at + ": " + map + " is not an object of at least one interpretation";
            }
            for (Map.Entry<String, JsonNode> e : map.properties()) {
                String problem = entryProblem(alt, listed, e.getKey(), e.getValue(), at + "/" + e.getKey(), a - 1);
                if (problem != null) {
                    return problem;
                }
            }
        }
        return null;
    }

    /** One interpretation's devices in entry {@code a}'s {@code unjudged} map. */
    private static String entryProblem(JsonNode alt, JsonNode listed, String interpretation, JsonNode devices, String at,
                                       int a) {
        if (!INTERPRETATION.matcher(interpretation).matches()) {
            return at + ": '" + interpretation + "' is not an interpretation id";
        }
        if (!alt.path("choices").has(interpretation)) {
            return at + ": " + interpretation + " is not one of the entry's choices";
        }
        if (!devices.isArray() || devices.isEmpty()) {
            return at + ": " + devices + " is not a non-empty list of devices";
        }
        List<String> names = new ArrayList<>();
        for (JsonNode d : devices) {
            if (!d.isString() || !DEVICE.matcher(d.stringValue()).matches()) {
                return at + ": " + d + " is not a device name";
            }
            names.add(d.stringValue());
        }
        if (new HashSet<>(names).size() != names.size()) {
            return at + ": " + devices + " has non-unique elements";
        }
        if (!names.equals(names.stream().sorted().toList())) {
            return at + ": the devices are not sorted";
        }
        for (String device : names) {
            if (!listed.has(device)) {
                return at + ": " + device + " is not in initial/devices";
            }
            String expected = alt.path("final").path("devices").has(device) ? "final/devices/" + device : null;
            int s = 0;
            for (JsonNode e : alt.path("expect")) {
                expected = expected != null || !e.path("devices").has(device) ? expected
                        : "expect/" + s + "/devices/" + device;
                s++;
            }
            if (expected != null) {
                return "at alternatives/" + a + "/" + expected + ": " + device + " is unjudged under " + interpretation + "="
                        + alt.path("choices").path(interpretation).asString("") + ", so the entry cannot expect a value of it";
            }
        }
        return null;
    }

    /**
     * A device whose JSON type differs from one place to another, in the order {@code plcvec verify}
     * visits them: initial, final, each step's set and expect, each alternative's expect and final.
     */
    private static String typeProblem(JsonNode v) {
        Map<String, JsonNode> places = new LinkedHashMap<>();
        places.put("initial/devices", v.path("initial").path("devices"));
        places.put("final/devices", v.path("final").path("devices"));
        int i = 0;
        for (JsonNode step : v.path("steps")) {
            places.put("steps/" + i + "/set", step.path("set"));
            places.put("steps/" + i++ + "/expect/devices", step.path("expect").path("devices"));
        }
        int a = 0;
        for (JsonNode alt : v.path("alternatives")) {
            i = 0;
            for (JsonNode expect : alt.path("expect")) {
                places.put("alternatives/" + a + "/expect/" + i++ + "/devices", expect.path("devices"));
            }
            places.put("alternatives/" + a++ + "/final/devices", alt.path("final").path("devices"));
        }
        Map<String, String> firstWhere = new LinkedHashMap<>();
        Map<String, JsonNode> firstValue = new LinkedHashMap<>();
        for (Map.Entry<String, JsonNode> place : places.entrySet()) {
            for (Map.Entry<String, JsonNode> d : place.getValue().properties()) {
                JsonNode first = firstValue.putIfAbsent(d.getKey(), d.getValue());
                if (first == null) {
                    firstWhere.put(d.getKey(), place.getKey());
                } else if (first.isBoolean() != d.getValue().isBoolean()) {
                    return "at " + place.getKey() + "/" + d.getKey() + ": " + d.getValue() + " is " + kind(d.getValue())
                            + ", but at " + firstWhere.get(d.getKey()) + "/" + d.getKey() + " the same device holds " + first
                            + ", " + kind(first);
                }
            }
        }
        return null;
    }

    private static String kind(JsonNode value) {
        return value.isBoolean() ? "a bit (true/false)" : "a word";
    }

    /** The devices an entry leaves unjudged, all interpretations together. */
    static Set<String> union(Map<String, List<String>> unjudged) {
        Set<String> out = new HashSet<>();
        unjudged.values().forEach(out::addAll);
        return out;
    }
}
