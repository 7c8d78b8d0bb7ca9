package org.plcvec.verify;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

import org.plcvec.spec.SuiteInfo;

import tools.jackson.databind.JsonNode;

/**
 * Loading a {@link Suite} from the forms CONTRACT.md names: the compact copy ({@code index.json}
 * and one {@code .jsonl} per family, as this jar carries it), the repository's {@code vectors/}
 * folder ({@code manifest.json} and one {@code .json} per family), or one family file; each file
 * read by {@link JsonFiles} (regular files only, UTF-8, no repeated key) and refused by file and
 * line or vector id.
 */
final class SuiteLoader {
    private SuiteLoader() {
    }

    /** One family file's bytes, by the name its index gives it. */
    @FunctionalInterface
    private interface Source {
        byte[] read(String name);
    }

    /** The resources folder of the copy inside this jar. */
    static final String RESOURCES = "/org/plcvec/vectors/";

    /** What a load read: what {@link Suite} is made of. */
    record Loaded(List<Vector> vectors, Map<String, JsonNode> headers, Map<String, String> merged, String source,
                  String suiteVersion, String schemaVersion, String specSha256) {
    }

    /** A family header as read: the family, and the minor version of the schema its file follows. */
    private record FamilyHeader(String family, int schemaMinor) {
    }

    /** The compact copy inside this jar. */
    static Loaded fromResources() {
        Source src = name -> {
            try (InputStream in = SuiteLoader.class.getResourceAsStream(RESOURCES + name)) {
                if (in == null) {
                    throw new VerifyException("classpath:" + RESOURCES + name + ": no such file");
                }
                return in.readAllBytes();
            } catch (IOException e) {
                throw new VerifyException("classpath:" + RESOURCES + name + ": cannot read: " + e.getMessage());
            }
        };
        return loadCompact(src, "classpath:" + RESOURCES);
    }

    static Loaded load(Path path, String variable) {
        if (Files.isDirectory(path)) {
            Source src = name -> bytes(path.resolve(name));
            // Present, not "a regular file": an index that is a pipe or a loop is refused by name.
            if (JsonFiles.present(path.resolve("index.json"))) {
                return loadCompact(src, path + "/");
            }
            if (JsonFiles.present(path.resolve("manifest.json"))) {
                return loadManifest(src, path);
            }
            throw new VerifyException(path + ": neither index.json (an exported copy) nor manifest.json "
                    + "(a vectors/ folder); is this a plcvec vector folder?");
        }
        if (!JsonFiles.present(path)) {
            throw new VerifyException(path + ": no such vector folder or file (from " + variable + "?)");
        }
        String name = path.toString();
        String text = JsonFiles.utf8(bytes(path), name);
        List<Vector> vectors = new ArrayList<>();
        Map<String, JsonNode> headers = new TreeMap<>();
        if (name.endsWith(".jsonl")) {
            readJsonl(text, name, vectors, headers);
        } else {
            readFamilyJson(text, name, vectors, headers);
        }
        return new Loaded(vectors, headers, Map.of(), name, "", schemaOf(headers), specOf(headers, ""));
    }

    private static byte[] bytes(Path path) {
        JsonFiles.requireRegularFile(path);
        try {
            return Files.readAllBytes(path);
        } catch (IOException e) {
            throw new VerifyException(path + ": cannot read: " + e.getMessage());
        }
    }

    /** An index ({@code index.json} or {@code manifest.json}): one object, its repeated keys refused. */
    private static JsonNode index(byte[] bytes, String name) {
        try {
            return JsonFiles.parse(JsonFiles.utf8(bytes, name), name, 1);
        } catch (JsonFiles.RepeatedKey e) {
            throw new VerifyException(name + ":" + e.line + ": " + e.getMessage());
        }
    }

    private static Loaded loadCompact(Source src, String where) {
        String indexName = where + "index.json";
        JsonNode index = index(src.read("index.json"), indexName);
        JsonNode families = index.path("families");
        if (!families.isObject() || families.isEmpty()) {
            throw new VerifyException(indexName + ": no `families`; is this a copy written by plcvec export?");
        }
        List<Vector> vectors = new ArrayList<>();
        Map<String, JsonNode> headers = new TreeMap<>();
        for (Map.Entry<String, JsonNode> e : families.properties()) {
            String file = e.getValue().path("file").asString(e.getKey() + ".jsonl");
            byte[] bytes = src.read(file);
            String name = where + file;
            int before = vectors.size();
            // Read first: a line that does not parse is named with its number, more use than a hash.
            readJsonl(JsonFiles.utf8(bytes, name), name, vectors, headers);
            String sha = e.getValue().path("sha256").asString("");
            if (!sha.isEmpty() && !sha.equals(sha256(bytes))) {
                throw new VerifyException(name + ": its sha256 is not the one index.json records; the copy is damaged "
                        + "or edited by hand (run `plcvec export` again)");
            }
            int count = e.getValue().path("count").asInt(-1);
            if (count >= 0 && vectors.size() - before != count) {
                throw new VerifyException(name + ": " + (vectors.size() - before) + " vectors, but index.json says " + count);
            }
        }
        return new Loaded(vectors, headers, merged(index), where, version(index),
                index.path("schema_version").asString(schemaOf(headers)), index.path("spec_sha256").asString(""));
    }

    private static Loaded loadManifest(Source src, Path dir) {
        String manifestName = dir.resolve("manifest.json").toString();
        JsonNode manifest = index(src.read("manifest.json"), manifestName);
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
            String name = dir.resolve(file).toString();
            readFamilyJson(JsonFiles.utf8(src.read(file), name), name, vectors, headers);
        }
        return new Loaded(vectors, headers, merged(manifest), dir.toString(), version(manifest), schemaOf(headers),
                manifest.path("spec_sha256").asString(specOf(headers, "")));
    }

    /** The suite version: {@code suite_version}, else its old name {@code generator_version}. */
    private static String version(JsonNode index) {
        return index.path("suite_version").asString(index.path("generator_version").asString(""));
    }

    /** The index's {@code merged} map, {family: {old id: new id}}, as one map of old id to new id. */
    private static Map<String, String> merged(JsonNode index) {
        Map<String, String> out = new TreeMap<>();
        for (Map.Entry<String, JsonNode> family : index.path("merged").properties()) {
            for (Map.Entry<String, JsonNode> e : family.getValue().properties()) {
                if (e.getValue().isString()) {
                    out.put(e.getKey(), e.getValue().stringValue());
                }
            }
        }
        return out;
    }

    /** One family file: a header and `vectors`. */
    private static void readFamilyJson(String text, String name, List<Vector> vectors, Map<String, JsonNode> headers) {
        JsonNode data;
        try {
            data = JsonFiles.parse(text, name, 1);
        } catch (JsonFiles.RepeatedKey e) {
            String id = JsonFiles.vectorAt(text, e.line);
            throw new VerifyException(name + ":" + e.line + ": " + (id != null ? "vector " + id + ": " : "") + e.getMessage());
        }
        if (!data.isObject() || !data.path("vectors").isArray() || !data.path("family").isString()) {
            throw new VerifyException(name + ": not a plcvec vector file (no `family` and `vectors`)");
        }
        FamilyHeader header = header(data, name, headers);
        int i = 0;
        java.net.URI file = uri(name, 0);
        for (JsonNode v : data.get("vectors")) {
            Vector vector = vector(v, header, name, "#" + i++);
            vector.source(file);
            vectors.add(vector);
        }
    }

    /** The compact form: line 1 the header, then one vector per line. */
    private static void readJsonl(String text, String name, List<Vector> vectors, Map<String, JsonNode> headers) {
        lastLineEnds(text, name);
        String[] lines = text.split("\n", -1);
        FamilyHeader header = null;
        for (int n = 0; n < lines.length; n++) {
            if (lines[n].isBlank()) {
                continue;
            }
            JsonNode node;
            try {
                node = JsonFiles.parse(lines[n], name, n + 1);
            } catch (JsonFiles.RepeatedKey e) {
                String id = header == null ? null : JsonFiles.idOf(lines[n]);
                throw new VerifyException(name + ":" + (n + 1) + ": " + (id != null ? "vector " + id + ": " : "")
                        + e.getMessage());
            }
            if (header == null) {
                if (!node.path("family").isString() || node.has("id")) {
                    throw new VerifyException(name + ":" + (n + 1) + ": the first line is not a family header");
                }
                header = header(node, name, headers);
            } else {
                Vector v = vector(node, header, name + ":" + (n + 1), "on this line");
                v.source(uri(name, n + 1));
                vectors.add(v);
            }
        }
        if (header == null) {
            throw new VerifyException(name + ": empty; not a plcvec vector file");
        }
    }

    /** A JSON-lines file whose last line does not end was cut, however well the rest parses. */
    private static void lastLineEnds(String text, String name) {
        if (!text.endsWith("\n")) {
            throw new VerifyException(name + ":" + text.split("\n", -1).length + ": the last line does not end: the file "
                    + "was cut");
        }
    }

    private static FamilyHeader header(JsonNode data, String name, Map<String, JsonNode> headers) {
        String version = data.path("schema_version").asString("");
        String[] parts = version.split("\\.", 3);
        if (!parts[0].equals(Integer.toString(SuiteInfo.SCHEMA_MAJOR))) {
            throw new VerifyException(name + ": schema_version " + (version.isEmpty() ? "(none)" : version) + " is not "
                    + SuiteInfo.SCHEMA_MAJOR + ".x; this verifier reads " + SuiteInfo.SCHEMA_MAJOR
                    + ".x files only (see CONTRACT.md, Versioning)");
        }
        int minor = parts.length > 1 && parts[1].matches("[0-9]{1,6}") ? Integer.parseInt(parts[1]) : 0;
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
        return new FamilyHeader(family, minor);
    }

    private static Set<String> withVectors() {
        Set<String> keys = new HashSet<>(VectorParser.HEADER_KEYS);
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

    private static Vector vector(JsonNode v, FamilyHeader header, String where, String fallbackName) {
        try {
            return VectorParser.vector(v, header.family(), header.schemaMinor());
        } catch (VectorParser.Bad e) {
            String id = v.path("id").isString() ? v.get("id").stringValue() : fallbackName;
            throw new VerifyException(where + ": vector " + id + ": " + e.getMessage()
                    + " (is the file a plcvec vector file, unedited?)");
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

    static String sha256(byte[] bytes) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    static String sha256(String text) {
        return sha256(text.getBytes(StandardCharsets.UTF_8));
    }
}
