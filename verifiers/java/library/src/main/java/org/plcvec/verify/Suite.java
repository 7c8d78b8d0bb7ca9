package org.plcvec.verify;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * A loaded vector set: the vectors of every family, each family file's header, and the ids that
 * were merged into other vectors.
 *
 * <p>{@link #golden()} is the set this jar carries (the compact copy {@code plcvec export} writes:
 * {@code index.json} and one {@code <family>.jsonl} each), unless the environment variable
 * {@code PLCVEC_VECTORS} (or the system property {@code plcvec.vectors}) names another:
 * a compact folder, the repository's {@code vectors/} folder ({@code manifest.json} and
 * {@code <family>.json}), or one family file. Loading refuses, by file and line or vector id, what
 * CONTRACT.md's "Loading" refuses.
 */
public final class Suite {
    /** The environment variable that points the verifier at another copy of the vectors. */
    public static final String ENV = "PLCVEC_VECTORS";
    /** The system property that does the same (it wins over the environment). */
    public static final String PROPERTY = "plcvec.vectors";
    static final String RESOURCES = SuiteLoader.RESOURCES;
    static final JsonMapper JSON = JsonFiles.JSON;

    /**
     * One interpretation as the family headers define it.
     *
     * @param id the interpretation's id ({@code FX5-SM709-SCOPE})
     * @param question what the pages leave open
     * @param defaultAlternative the alternative followed when none is declared
     * @param alternatives every alternative, in the order the files list them
     * @param families the families whose vectors it may decide
     */
    public record InterpretationInfo(String id, String question, String defaultAlternative, List<String> alternatives,
                                     List<String> families) {
    }

    private final List<Vector> vectors;
    private final Map<String, Vector> byId;
    private final Map<String, JsonNode> headers;
    private final Map<String, String> merged;
    private final String source;
    private final String suiteVersion;
    private final String schemaVersion;
    private final String specSha256;
    private final Map<String, InterpretationInfo> interpretations;

    private static volatile Suite golden;
    private static volatile Suite bundled;

    private Suite(SuiteLoader.Loaded loaded) {
        this.vectors = List.copyOf(loaded.vectors());
        this.headers = Collections.unmodifiableMap(loaded.headers());
        this.merged = Collections.unmodifiableMap(new TreeMap<>(loaded.merged()));
        this.source = loaded.source();
        this.suiteVersion = loaded.suiteVersion();
        this.schemaVersion = loaded.schemaVersion();
        this.specSha256 = loaded.specSha256();
        Map<String, Vector> ids = new LinkedHashMap<>();
        for (Vector v : this.vectors) {
            if (ids.put(v.id(), v) != null) {
                throw new VerifyException(source + ": vector id " + v.id() + " appears twice");
            }
        }
        this.byId = Collections.unmodifiableMap(ids);
        this.interpretations = Collections.unmodifiableMap(readInterpretations());
    }

    /**
     * The golden set, loaded once: {@code PLCVEC_VECTORS} (or {@code -Dplcvec.vectors}) if set,
     * else the copy inside this jar.
     *
     * @return the vectors a run judges by default
     */
    public static Suite golden() {
        Suite s = golden;
        if (s == null) {
            synchronized (Suite.class) {
                s = golden;
                if (s == null) {
                    String override = System.getProperty(PROPERTY);   // set, even to nothing, it wins
                    if (override == null) {
                        override = System.getenv(ENV);
                    }
                    s = override == null || override.isEmpty() ? bundled() : load(Path.of(override));
                    golden = s;
                }
            }
        }
        return s;
    }

    /**
     * The copy of the vectors packaged with this library, loaded once.
     *
     * @return the vectors inside this jar
     */
    static Suite bundled() {
        Suite s = bundled;
        if (s == null) {
            synchronized (Suite.class) {
                s = bundled;
                if (s == null) {
                    s = fromResources();
                    bundled = s;
                }
            }
        }
        return s;
    }

    /**
     * The copy of the vectors packaged with this library, loaded anew.
     *
     * @return the vectors inside this jar
     */
    public static Suite fromResources() {
        return new Suite(SuiteLoader.fromResources());
    }

    /**
     * A compact folder (index.json), a vectors/ folder (manifest.json), or one family file (.json
     * or .jsonl).
     *
     * @param path the folder or file
     * @return the vectors there
     * @throws VerifyException when the files are missing, damaged or not plcvec vector files,
     *         naming the file (and line) or the vector id
     */
    public static Suite load(Path path) {
        return new Suite(SuiteLoader.load(path, ENV + " or " + PROPERTY));
    }

    private Map<String, InterpretationInfo> readInterpretations() {
        Map<String, InterpretationInfo> out = new TreeMap<>();
        for (Map.Entry<String, JsonNode> h : headers.entrySet()) {
            for (JsonNode i : h.getValue().path("interpretations")) {
                String id = i.path("id").asString("");
                List<String> alternatives = new ArrayList<>();
                for (JsonNode a : i.path("alternatives")) {
                    alternatives.add(a.path("id").asString(""));
                }
                InterpretationInfo seen = out.get(id);
                String def = i.path("default").asString("");
                if (seen == null) {
                    List<String> families = new ArrayList<>();
                    families.add(h.getKey());
                    out.put(id, new InterpretationInfo(id, i.path("question").asString(""), def, List.copyOf(alternatives),
                            families));
                } else if (!seen.defaultAlternative().equals(def) || !seen.alternatives().equals(alternatives)) {
                    throw new VerifyException(source + ": interpretation " + id + " has other alternatives or another "
                            + "default in " + h.getKey() + " than in " + seen.families().get(0));
                } else {
                    seen.families().add(h.getKey());
                }
            }
        }
        out.replaceAll((k, v) -> new InterpretationInfo(v.id(), v.question(), v.defaultAlternative(), v.alternatives(),
                List.copyOf(v.families())));
        return out;
    }

    /**
     * Every vector, in the order of the families (by name), each family's in file order.
     *
     * @return the vectors
     */
    public List<Vector> vectors() {
        return vectors;
    }

    /**
     * The vector with an id.
     *
     * @param id the vector's id
     * @return the vector, or null
     */
    public Vector byId(String id) {
        return byId.get(id);
    }

    /**
     * The vector a merged id became: the index's {@code merged} map followed to its end (a vector
     * merged into one that was merged again is named by the one it is now).
     *
     * @param id an id the suite does not have
     * @return the id of the vector it became, or null when it was never merged
     */
    public String mergedInto(String id) {
        String at = merged.get(id);
        for (int hops = 0; at != null && merged.containsKey(at) && hops < merged.size(); hops++) {
            at = merged.get(at);
        }
        return at;
    }

    /**
     * The families, sorted.
     *
     * @return the family names as the vectors spell them
     */
    public List<String> families() {
        return List.copyOf(headers.keySet());
    }

    /**
     * A family's instructions, as its header lists them.
     *
     * @param family the family as the vectors spell it
     * @return its instructions (empty for a family the suite does not have)
     */
    public List<String> instructions(String family) {
        List<String> out = new ArrayList<>();
        for (JsonNode i : headers.getOrDefault(family, JSON.createObjectNode()).path("instructions")) {
            out.add(i.asString());
        }
        return out;
    }

    /**
     * Every interpretation, each once even when several families share it.
     *
     * @return interpretation id to what the headers say of it
     */
    public Map<String, InterpretationInfo> interpretations() {
        return interpretations;
    }

    /**
     * Where the vectors came from.
     *
     * @return a path, or the classpath folder
     */
    public String source() {
        return source;
    }

    /**
     * The suite version ({@code suite_version} of the index).
     *
     * @return the version, or "" for a lone family file
     */
    public String suiteVersion() {
        return suiteVersion;
    }

    /**
     * The vector files' schema version.
     *
     * @return the version (several, comma-separated, if the files differ)
     */
    public String schemaVersion() {
        return schemaVersion;
    }

    /**
     * The sha256 of the spec the vectors were generated from.
     *
     * @return the hash as hex
     */
    public String specSha256() {
        return specSha256;
    }

    @Override
    public String toString() {
        return source + " (" + vectors.size() + " vectors, suite " + suiteVersion + ")";
    }
}
