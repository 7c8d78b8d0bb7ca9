package org.plcvec.verify;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import org.plcvec.spec.SuiteInfo;

import tools.jackson.core.JacksonException;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * A loaded vector set: the vectors of every family and each family file's header.
 *
 * <p>{@link #golden()} is the set this jar carries (the compact copy {@code plcvec export} writes:
 * {@code index.json} and one {@code <family>.jsonl} each), unless the environment variable
 * {@code PLCVEC_VECTORS} (or the system property {@code plcvec.vectors}) names another:
 * a compact folder, the repository's {@code vectors/} folder ({@code manifest.json} and
 * {@code <family>.json}), or one family file.
 */
public final class Suite {
    /** The environment variable that points the verifier at another copy of the vectors. */
    public static final String ENV = "PLCVEC_VECTORS";
    /** The system property that does the same (it wins over the environment). */
    public static final String PROPERTY = "plcvec.vectors";
    static final String RESOURCES = "/org/plcvec/vectors/";
    static final JsonMapper JSON = JsonMapper.builder().build();

    /** One interpretation as the family headers define it. */
    public record InterpretationInfo(String id, String question, String defaultAlternative, List<String> alternatives,
                                     List<String> families) {
    }

    private final List<Vector> vectors;
    private final Map<String, Vector> byId;
    private final Map<String, JsonNode> headers;
    private final String source;
    private final String suiteVersion;
    private final String schemaVersion;
    private final String specSha256;
    private final Map<String, InterpretationInfo> interpretations;

    private static volatile Suite golden;

    private Suite(List<Vector> vectors, Map<String, JsonNode> headers, String source, String suiteVersion,
                  String schemaVersion, String specSha256) {
        this.vectors = List.copyOf(vectors);
        this.headers = Collections.unmodifiableMap(headers);
        this.source = source;
        this.suiteVersion = suiteVersion;
        this.schemaVersion = schemaVersion;
        this.specSha256 = specSha256;
        Map<String, Vector> ids = new LinkedHashMap<>();
        for (Vector v : vectors) {
            if (ids.put(v.id(), v) != null) {
                throw new VerifyException(source + ": vector id " + v.id() + " appears twice");
            }
        }
        this.byId = Collections.unmodifiableMap(ids);
        this.interpretations = Collections.unmodifiableMap(readInterpretations());
    }

    /** The golden set: {@code PLCVEC_VECTORS} if set, else the copy inside this jar. Loaded once. */
    public static Suite golden() {
        Suite s = golden;
        if (s == null) {
            synchronized (Suite.class) {
                s = golden;
                if (s == null) {
                    Path override = Environment.current().vectors();
                    s = override == null ? fromResources() : load(override);
                    golden = s;
                }
            }
        }
        return s;
    }

    /** The copy of the vectors packaged with this library. */
    public static Suite fromResources() {
        Source src = name -> {
            InputStream in = Suite.class.getResourceAsStream(RESOURCES + name);
            if (in == null) {
                throw new NoSuchFileException("classpath:" + RESOURCES + name);
            }
            try (in) {
                return new String(in.readAllBytes(), StandardCharsets.UTF_8);
            }
        };
        return loadCompact(src, "classpath:" + RESOURCES);
    }

    /** A compact folder (index.json), a vectors/ folder (manifest.json), or one family file (.json or .jsonl). */
    public static Suite load(Path path) {
        if (Files.isDirectory(path)) {
            Source src = name -> Files.readString(path.resolve(name), StandardCharsets.UTF_8);
            if (Files.isRegularFile(path.resolve("index.json"))) {
                return loadCompact(src, path + "/");
            }
            if (Files.isRegularFile(path.resolve("manifest.json"))) {
                return loadManifest(src, path);
            }
            throw new VerifyException(path + ": neither index.json (an exported copy) nor manifest.json "
                    + "(a vectors/ folder); is this a plcvec vector folder?");
        }
        if (!Files.exists(path)) {
            throw new VerifyException(path + ": no such vector folder or file (from " + ENV + " or " + PROPERTY + "?)");
        }
        String text = read(name -> Files.readString(path, StandardCharsets.UTF_8), path.toString());
        List<Vector> vectors = new ArrayList<>();
        Map<String, JsonNode> headers = new TreeMap<>();
        if (path.toString().endsWith(".jsonl")) {
            readJsonl(text, path.toString(), vectors, headers);
        } else {
            readFamilyJson(text, path.toString(), vectors, headers);
        }
        return new Suite(vectors, headers, path.toString(), "", schemaOf(headers), specOf(headers, ""));
    }

    @FunctionalInterface
    private interface Source {
        String read(String name) throws IOException;
    }

    private static String read(Source src, String name) {
        try {
            return src.read(name);
        } catch (NoSuchFileException e) {
            throw new VerifyException(e.getFile() + ": no such file");
        } catch (IOException e) {
            throw new VerifyException(name + ": cannot read: " + e.getMessage());
        }
    }

    private static Suite loadCompact(Source src, String where) {
        String indexName = where + "index.json";
        JsonNode index = parse(read(src, "index.json"), indexName);
        JsonNode families = index.path("families");
        if (!families.isObject() || families.isEmpty()) {
            throw new VerifyException(indexName + ": no `families`; is this a copy written by plcvec export?");
        }
        List<Vector> vectors = new ArrayList<>();
        Map<String, JsonNode> headers = new TreeMap<>();
        for (Map.Entry<String, JsonNode> e : families.properties()) {
            String file = e.getValue().path("file").asString(e.getKey() + ".jsonl");
            String text = read(src, file);
            String name = where + file;
            int before = vectors.size();
            // Read first: a line that does not parse is named with its number, more use than a hash.
            readJsonl(text, name, vectors, headers);
            String sha = e.getValue().path("sha256").asString("");
            if (!sha.isEmpty() && !sha.equals(sha256(text))) {
                throw new VerifyException(name + ": its sha256 is not the one index.json records; the copy is damaged "
                        + "or edited by hand (run `plcvec export` again)");
            }
            int count = e.getValue().path("count").asInt(-1);
            if (count >= 0 && vectors.size() - before != count) {
                throw new VerifyException(name + ": " + (vectors.size() - before) + " vectors, but index.json says " + count);
            }
        }
        return new Suite(vectors, headers, where, index.path("suite_version").asString(""),
                index.path("schema_version").asString(schemaOf(headers)), index.path("spec_sha256").asString(""));
    }

    private static Suite loadManifest(Source src, Path dir) {
        String manifestName = dir.resolve("manifest.json").toString();
        JsonNode manifest = parse(read(src, "manifest.json"), manifestName);
        JsonNode families = manifest.path("families");
        if (!families.isObject() || families.isEmpty()) {
            throw new VerifyException(manifestName + ": no `families` with a `file` each; is this a plcvec vector folder?");
        }
        List<Vector> vectors = new ArrayList<>();
        Map<String, JsonNode> headers = new TreeMap<>();
        for (Map.Entry<String, JsonNode> e : families.properties()) {
            String file = e.getValue().path("file").asString("");
            if (file.isEmpty()) {
                throw new VerifyException(manifestName + ": family " + e.getKey() + " has no `file`");
            }
            readFamilyJson(read(src, file), dir.resolve(file).toString(), vectors, headers);
        }
        return new Suite(vectors, headers, dir.toString(), manifest.path("generator_version").asString(""),
                schemaOf(headers), manifest.path("spec_sha256").asString(specOf(headers, "")));
    }

    /** One family file: a header and `vectors`. */
    private static void readFamilyJson(String text, String name, List<Vector> vectors, Map<String, JsonNode> headers) {
        JsonNode data = parse(text, name);
        if (!data.isObject() || !data.path("vectors").isArray() || !data.path("family").isString()) {
            throw new VerifyException(name + ": not a plcvec vector file (no `family` and `vectors`)");
        }
        String family = header(data, name, headers);
        int i = 0;
        java.net.URI file = uri(name, 0);
        for (JsonNode v : data.get("vectors")) {
            Vector vector = vector(v, family, name, "#" + i++);
            vector.source(file);
            vectors.add(vector);
        }
    }

    /** The compact form: line 1 the header, then one vector per line. */
    private static void readJsonl(String text, String name, List<Vector> vectors, Map<String, JsonNode> headers) {
        String[] lines = text.split("\n", -1);
        String family = null;
        for (int n = 0; n < lines.length; n++) {
            if (lines[n].isBlank()) {
                continue;
            }
            JsonNode node = parse(lines[n], name + ":" + (n + 1));
            if (family == null) {
                if (!node.path("family").isString() || node.has("id")) {
                    throw new VerifyException(name + ":" + (n + 1) + ": the first line is not a family header");
                }
                family = header(node, name, headers);
            } else {
                Vector v = vector(node, family, name + ":" + (n + 1), "on this line");
                v.source(uri(name, n + 1));
                vectors.add(v);
            }
        }
        if (family == null) {
            throw new VerifyException(name + ": empty; not a plcvec vector file");
        }
    }

    private static String header(JsonNode data, String name, Map<String, JsonNode> headers) {
        String version = data.path("schema_version").asString("");
        String major = version.split("\\.", 2)[0];
        if (!major.equals(Integer.toString(SuiteInfo.SCHEMA_MAJOR))) {
            throw new VerifyException(name + ": schema_version " + (version.isEmpty() ? "(none)" : version) + " is not "
                    + SuiteInfo.SCHEMA_MAJOR + ".x; this verifier reads " + SuiteInfo.SCHEMA_MAJOR
                    + ".x files only (see CONTRACT.md, Versioning)");
        }
        String key = VectorParser.unknownKey(data, data.has("vectors") ? withVectors() : VectorParser.HEADER_KEYS, "");
        int i = 0;
        for (JsonNode interpretation : data.path("interpretations")) {
            String path = "interpretations/" + i++;
            key = key != null ? key : VectorParser.unknownKey(interpretation, VectorParser.INTERPRETATION_KEYS, path);
            int j = 0;
            for (JsonNode alt : interpretation.path("alternatives")) {
                key = key != null ? key
                        : VectorParser.unknownKey(alt, VectorParser.ALTERNATIVE_HEADER_KEYS, path + "/alternatives/" + j++);
            }
        }
        if (key != null) {
            throw new VerifyException(name + ": the family header has " + key + ", a key the schema does not have");
        }
        String family = data.get("family").stringValue();
        if (headers.containsKey(family)) {
            throw new VerifyException(name + ": family " + family + " is loaded twice");
        }
        headers.put(family, data);
        return family;
    }

    private static java.util.Set<String> withVectors() {
        java.util.Set<String> keys = new java.util.HashSet<>(VectorParser.HEADER_KEYS);
        keys.add("vectors");
        return keys;
    }

    /** A test source for JUnit: classpath or file, with the line when known. */
    private static java.net.URI uri(String name, int line) {
        String query = line > 0 ? "?line=" + line : "";
        try {
            if (name.startsWith("classpath:")) {
                return new java.net.URI("classpath", name.substring("classpath:".length()) + query, null);
            }
            return java.net.URI.create(Path.of(name).toAbsolutePath().toUri() + query);
        } catch (java.net.URISyntaxException | IllegalArgumentException e) {
            return null;   // a source link is a convenience; never a reason to refuse the vectors
        }
    }

    private static Vector vector(JsonNode v, String family, String where, String fallbackName) {
        try {
            return VectorParser.vector(v, family);
        } catch (VectorParser.Bad e) {
            String id = v.path("id").isString() ? v.get("id").stringValue() : fallbackName;
            throw new VerifyException(where + ": vector " + id + ": " + e.getMessage()
                    + " (is the file a plcvec vector file, unedited?)");
        }
    }

    private static JsonNode parse(String text, String name) {
        try {
            return JSON.readTree(text);
        } catch (JacksonException e) {
            String line = e.getLocation() != null && !name.matches(".*:\\d+$") ? ":" + e.getLocation().getLineNr() : "";
            throw new VerifyException(name + line + ": not valid JSON (" + e.getOriginalMessage() + ")");
        }
    }

    private static String schemaOf(Map<String, JsonNode> headers) {
        return String.join(", ", headers.values().stream().map(h -> h.path("schema_version").asString("")).distinct()
                .sorted().toList());
    }

    private static String specOf(Map<String, JsonNode> headers, String fallback) {
        List<String> hashes = headers.values().stream().map(h -> h.path("spec_sha256").asString(""))
                .filter(h -> !h.isEmpty()).distinct().sorted().toList();
        return hashes.isEmpty() ? fallback : String.join(", ", hashes);
    }

    static String sha256(String text) {
        try {
            MessageDigest md = MessageDigest.getInstance("SHA-256");
            return HexFormat.of().formatHex(md.digest(text.getBytes(StandardCharsets.UTF_8)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
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

    public List<Vector> vectors() {
        return vectors;
    }

    /** The vector with this id, or null. */
    public Vector byId(String id) {
        return byId.get(id);
    }

    /** The families, sorted. */
    public List<String> families() {
        return List.copyOf(headers.keySet());
    }

    /** A family's instructions, as its header lists them. */
    public List<String> instructions(String family) {
        List<String> out = new ArrayList<>();
        for (JsonNode i : headers.getOrDefault(family, JSON.createObjectNode()).path("instructions")) {
            out.add(i.asString());
        }
        return out;
    }

    /** Every interpretation (id → info), each once even when several families share it. */
    public Map<String, InterpretationInfo> interpretations() {
        return interpretations;
    }

    /** Where the vectors came from (a path, or the classpath). */
    public String source() {
        return source;
    }

    public String suiteVersion() {
        return suiteVersion;
    }

    public String schemaVersion() {
        return schemaVersion;
    }

    public String specSha256() {
        return specSha256;
    }

    @Override
    public String toString() {
        return source + " (" + vectors.size() + " vectors, suite " + suiteVersion + ")";
    }
}
