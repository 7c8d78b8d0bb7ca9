package org.plcvec.verify;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.StandardCopyOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import tools.jackson.core.JacksonException;
import tools.jackson.databind.JsonNode;
import tools.jackson.dataformat.toml.TomlMapper;

/**
 * The expectations file: vectors an implementation is known to fail, each with a reason (the
 * same TOML file {@code plcvec verify --expectations} reads).
 *
 * <pre>
 * [[known-failure]]
 * id = "fx5-date-compare/LDDT&lt;/nonexistent/2024-2-30/s1/vs-previous"
 * reason = "our calendar check rejects 2008/02/31"
 * </pre>
 *
 * <p>A listed vector that fails is XFAIL and does not fail the run; a listed vector that passes
 * is STALE and fails it, and so does an id the suite does not have: the list can only shrink.
 * Ids are exact, never patterns: a pattern would hide tomorrow's new failures.
 */
public final class KnownFailures {
    static final String SECTION = "known-failure";
    private static final TomlMapper TOML = TomlMapper.builder().build();

    /** One entry, with the line its {@code [[known-failure]]} header is on. */
    public record Entry(String id, String reason, int line) {
    }

    private static final KnownFailures NONE = new KnownFailures("(none)", Map.of());
    private final String path;
    private final Map<String, Entry> entries;

    private KnownFailures(String path, Map<String, Entry> entries) {
        this.path = path;
        this.entries = Collections.unmodifiableMap(entries);
    }

    /**
     * No known failure.
     *
     * @return the empty list
     */
    public static KnownFailures none() {
        return NONE;
    }

    /**
     * Read a known-failures file. A path that is not a regular file (a named pipe nobody writes, a
     * folder, a loop of symbolic links) is refused by name before it is opened, so no load waits.
     *
     * @param file the TOML file
     * @return its entries
     * @throws VerifyException when it cannot be read or is not a known-failures file, naming the
     *         file and line
     */
    public static KnownFailures load(Path file) {
        if (!JsonFiles.present(file)) {
            throw new VerifyException(file + ": cannot read the expectations file: no such file");
        }
        return parse(JsonFiles.read(file), file.toString());
    }

    /**
     * Read the text of a known-failures file.
     *
     * @param text the TOML
     * @param path the file's name as the messages give it
     * @return its entries
     * @throws VerifyException when it is not a known-failures file, naming the path and line
     */
    public static KnownFailures parse(String text, String path) {
        JsonNode data;
        try {
            data = TOML.readTree(text);
        } catch (JacksonException e) {
            String line = e.getLocation() != null && e.getLocation().getLineNr() > 0 ? ":" + e.getLocation().getLineNr() : "";
            throw new VerifyException(path + line + ": not valid TOML: " + e.getOriginalMessage());
        }
        String[] lines = text.split("\n", -1);
        for (String key : data.propertyNames()) {
            if (!key.equals(SECTION)) {
                throw new VerifyException(path + ":" + lineOf(lines, key) + ": unknown key '" + key
                        + "'; an expectations file holds only [[" + SECTION + "]] entries");
            }
        }
        List<Integer> headers = new ArrayList<>();
        for (int i = 0; i < lines.length; i++) {
            if (lines[i].strip().startsWith("[[" + SECTION + "]]")) {
                headers.add(i + 1);
            }
        }
        Map<String, Entry> entries = new LinkedHashMap<>();
        JsonNode list = data.path(SECTION);
        if (!list.isMissingNode() && !list.isArray()) {
            throw new VerifyException(path + ":" + lineOf(lines, SECTION) + ": " + SECTION
                    + " must be an array of tables ([[" + SECTION + "]])");
        }
        int n = 0;
        for (JsonNode entry : list) {
            int line = n < headers.size() ? headers.get(n) : 0;
            n++;
            if (!entry.isObject()) {
                throw new VerifyException(path + ":" + line + ": [[" + SECTION + "]] must be a table");
            }
            for (String key : entry.propertyNames()) {
                if (!key.equals("id") && !key.equals("reason")) {
                    throw new VerifyException(path + ":" + line + ": unknown key '" + key + "' (an entry has `id` and `reason`)");
                }
            }
            JsonNode id = entry.path("id");
            JsonNode reason = entry.path("reason");
            if (!id.isString() || id.stringValue().isEmpty()) {
                throw new VerifyException(path + ":" + line + ": entry without an `id`");
            }
            if (!reason.isString() || reason.stringValue().isBlank()) {
                throw new VerifyException(path + ":" + line + ": " + id.stringValue() + ": every known failure needs a `reason`");
            }
            Entry first = entries.get(id.stringValue());
            if (first != null) {
                throw new VerifyException(path + ":" + line + ": " + id.stringValue() + " is listed twice (first at line "
                        + first.line() + ")");
            }
            entries.put(id.stringValue(), new Entry(id.stringValue(), reason.stringValue().strip(), line));
        }
        return new KnownFailures(path, entries);
    }

    private static int lineOf(String[] lines, String key) {
        for (int i = 0; i < lines.length; i++) {
            String l = lines[i].strip();
            if (l.startsWith(key) || l.startsWith("[" + key) || l.startsWith("[[" + key)) {
                return i + 1;
            }
        }
        return 1;
    }

    /**
     * The entries, in file order.
     *
     * @return vector id to its entry
     */
    public Map<String, Entry> entries() {
        return entries;
    }

    /**
     * The file's name as it was given.
     *
     * @return the path, or {@code (none)}
     */
    public String path() {
        return path;
    }

    /** Turn a listed failure into XFAIL and a listed pass into STALE (in place). */
    void apply(Verdict r) {
        Entry e = entries.get(r.id());
        if (e == null) {
            return;
        }
        String where = path + ":" + e.line();
        if (r.status() == Status.FAIL || r.status() == Status.ERROR) {
            r.mark(Status.XFAIL, "known failure (" + where + "): " + e.reason()
                    + (r.message().isEmpty() ? "" : "; " + r.message()));
        } else if (r.status() == Status.PASS) {
            r.mark(Status.STALE, "listed as a known failure (" + where + ": " + e.reason()
                    + ") but it passes; remove it from the expectations file");
        }
    }

    /**
     * Entries naming a vector the suite does not have (whatever the selection): each is a STALE
     * verdict, naming the vector an id merged into another became.
     */
    List<Verdict> unknownIds(Suite suite) {
        List<Verdict> out = new ArrayList<>();
        for (Entry e : entries.values()) {
            if (suite.byId(e.id()) == null) {
                String into = suite.mergedInto(e.id());
                out.add(new Verdict(e.id(), null, Status.STALE, List.of(), "listed as a known failure (" + path + ":"
                        + e.line() + ") but the suite has no such vector" + (into != null ? ": it was merged into " + into
                        + "; list that id instead" : "; remove it from the expectations file"), null));
            }
        }
        return out;
    }

    /**
     * Refuse, before a run, a path the run's failures could not be written to: one that is there
     * and is not a regular file, or whose folder is not a folder that can be written.
     *
     * @param file the expectations file to write
     * @throws VerifyException naming the file and why
     */
    static void checkWritable(Path file) {
        if (JsonFiles.present(file)) {
            JsonFiles.requireRegularFile(file);
            if (!Files.isWritable(file)) {
                throw new VerifyException(file + ": cannot write the expectations file: not writable");
            }
        }
        Path dir = file.toAbsolutePath().getParent();
        if (dir == null || !Files.isDirectory(dir)) {
            throw new VerifyException(file + ": cannot write the expectations file: no such folder " + dir);
        }
        if (!Files.isWritable(dir)) {
            throw new VerifyException(file + ": cannot write the expectations file: the folder " + dir + " is not writable");
        }
    }

    /**
     * Write the failing vectors of {@code verdicts} as an expectations file, atomically: the file is
     * whole or untouched.
     *
     * @return the number of entries written
     * @throws VerifyException when it cannot be written, naming the file
     */
    static int write(Path file, List<Verdict> verdicts, String reason) {
        StringBuilder sb = new StringBuilder("# Known failures: each passing entry fails the run as stale, so fix and delete.\n\n");
        int n = 0;
        for (Verdict r : verdicts.stream().sorted(java.util.Comparator.comparing(Verdict::id)).toList()) {
            if (r.vector() != null && (r.status() == Status.FAIL || r.status() == Status.ERROR || r.status() == Status.XFAIL)) {
                sb.append("[[").append(SECTION).append("]]\nid = ").append(toml(r.id())).append("\nreason = ")
                        .append(toml(reason)).append("\n\n");
                n++;
            }
        }
        checkWritable(file);
        Path dir = file.toAbsolutePath().getParent();
        try {
            Path tmp = Files.createTempFile(dir, "." + file.getFileName(), ".tmp");
            try {
                Files.writeString(tmp, sb, StandardCharsets.UTF_8);
                Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            } finally {
                Files.deleteIfExists(tmp);
            }
        } catch (IOException e) {
            throw new VerifyException(file + ": cannot write the expectations file: " + e.getMessage(), e);
        }
        return n;
    }

    private static String toml(String s) {
        StringBuilder sb = new StringBuilder("\"");
        for (char c : s.toCharArray()) {
            if (c == '"' || c == '\\') {
                sb.append('\\').append(c);
            } else if (c < 0x20 || c == 0x7f) {
                sb.append(String.format("\\u%04X", (int) c));
            } else {
                sb.append(c);
            }
        }
        return sb.append('"').toString();
    }
}
