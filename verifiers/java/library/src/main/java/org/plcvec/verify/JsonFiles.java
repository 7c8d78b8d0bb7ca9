package org.plcvec.verify;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import tools.jackson.core.JacksonException;
import tools.jackson.core.JsonParser;
import tools.jackson.core.JsonToken;
import tools.jackson.databind.DeserializationFeature;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

/**
 * Reading the files a run trusts (the index, the family files, the known-failures file) as
 * CONTRACT.md's "Loading" asks: a path that is not a regular file is refused by name before it is
 * opened (a named pipe nobody writes would block the read for ever, a device never ends), bytes
 * that are not UTF-8 are named by file and line, and a JSON object that holds one key twice is
 * refused by file and line: JSON parsers disagree on which value wins, so neither is taken.
 */
final class JsonFiles {
    /**
     * The vectors' parser: a repeated key is an error. Checked as the tree is built (the object
     * being filled already holds the key), which costs a lookup the tree makes anyway.
     */
    static final JsonMapper JSON = JsonMapper.builder().enable(DeserializationFeature.FAIL_ON_READING_DUP_TREE_KEY).build();
    /** The parser that takes the last of a repeated key: only to find whose vector a repeated key is in. */
    private static final JsonMapper LENIENT = JsonMapper.builder().build();
    private static final Pattern DUPLICATE = Pattern.compile("Duplicate (?:field|property) [\"'](.*?)[\"'] for");
    /** The file type bits of a {@code unix:mode} attribute, and those of the files that are not regular. */
    private static final int TYPE = 0170000;
    private static final int FIFO = 0010000;
    private static final int SOCKET = 0140000;
    private static final int CHARACTER_DEVICE = 0020000;
    private static final int BLOCK_DEVICE = 0060000;

    private JsonFiles() {
    }

    /** A JSON object with one key twice: the key, and the line of its second occurrence. */
    static final class RepeatedKey extends RuntimeException {
        private static final long serialVersionUID = 1L;
        final String key;
        final int line;

        RepeatedKey(String key, int line) {
            super("repeated key \"" + key + "\"");
            this.key = key;
            this.line = line;
        }
    }

    /**
     * Refuse {@code path} unless it is a regular file (symbolic links followed), naming it and what
     * it is instead; nothing is opened.
     */
    static void requireRegularFile(Path path) {
        BasicFileAttributes attributes;
        try {
            attributes = Files.readAttributes(path, BasicFileAttributes.class);
        } catch (NoSuchFileException e) {
            throw new VerifyException(path + ": no such file");
        } catch (FileSystemException e) {
            if (Files.isSymbolicLink(path) && String.valueOf(e.getReason()).contains("symbolic links")) {
                throw new VerifyException(path + ": a loop of symbolic links");
            }
            throw new VerifyException(path + ": cannot read: " + (e.getReason() != null ? e.getReason() : e.getMessage()));
        } catch (IOException e) {
            throw new VerifyException(path + ": cannot read: " + e.getMessage());
        }
        if (!attributes.isRegularFile()) {
            throw new VerifyException(path + ": not a regular file (" + kind(path, attributes) + ")");
        }
    }

    /** What a path that is not a regular file is, in a few words. */
    private static String kind(Path path, BasicFileAttributes attributes) {
        if (attributes.isDirectory()) {
            return "a folder";
        }
        try {
            int type = (Integer) Files.getAttribute(path, "unix:mode") & TYPE;
            switch (type) {
                case FIFO:
                    return "a named pipe";
                case SOCKET:
                    return "a socket";
                case CHARACTER_DEVICE:
                case BLOCK_DEVICE:
                    return "a device";
                default:
                    break;
            }
        } catch (IOException | UnsupportedOperationException | IllegalArgumentException | ClassCastException e) {
            // a file system without unix attributes: the general words below
        }
        return "a named pipe, a device or a socket";
    }

    /** Whether something (a file, a folder, a pipe, a dangling link) is at {@code path}. */
    static boolean present(Path path) {
        return Files.exists(path, LinkOption.NOFOLLOW_LINKS);
    }

    /** The text of a regular file, refused by name (and by line, for bytes that are not UTF-8). */
    static String read(Path path) {
        requireRegularFile(path);
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(path);
        } catch (NoSuchFileException e) {
            throw new VerifyException(path + ": no such file");
        } catch (IOException e) {
            throw new VerifyException(path + ": cannot read: " + e.getMessage());
        }
        return utf8(bytes, path.toString());
    }

    /** {@code bytes} as UTF-8; a byte that is not is named by {@code name}, line and column. */
    static String utf8(byte[] bytes, String name) {
        CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        try {
            return decoder.decode(ByteBuffer.wrap(bytes)).toString();
        } catch (CharacterCodingException e) {
            int at = firstBadByte(bytes);
            int line = 1;
            for (int i = 0; i < at; i++) {
                line += bytes[i] == '\n' ? 1 : 0;
            }
            throw new VerifyException(name + ":" + line + ": not UTF-8 text (byte " + at + ")");
        }
    }

    /** The offset of the first byte that does not decode. */
    private static int firstBadByte(byte[] bytes) {
        CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes);
        java.nio.CharBuffer out = java.nio.CharBuffer.allocate(bytes.length + 1);
        java.nio.charset.CoderResult r = decoder.decode(in, out, true);
        return r.isError() ? in.position() : Math.max(0, bytes.length - 1);
    }

    /**
     * One JSON document; a repeated key is a {@link RepeatedKey} at its line (counted from
     * {@code firstLine}), anything else that does not parse a {@link VerifyException} naming
     * {@code name} (and the line, for a document of several lines).
     */
    static JsonNode parse(String text, String name, int firstLine) {
        try {
            return JSON.readTree(text);
        } catch (JacksonException e) {
            String message = e.getOriginalMessage();
            Matcher m = DUPLICATE.matcher(message == null ? "" : message);
            int line = e.getLocation() != null && e.getLocation().getLineNr() > 0 ? e.getLocation().getLineNr() : 1;
            if (m.find()) {
                throw new RepeatedKey(m.group(1), firstLine + line - 1);
            }
            String where = firstLine > 1 || text.indexOf('\n') < 0 ? ":" + firstLine : ":" + line;
            throw new VerifyException(name + where + ": not valid JSON (" + message + ")");
        }
    }

    /**
     * The id of the vector of a family file (one JSON document with {@code vectors}) that spans
     * {@code line}, or null: where a repeated key is, read by a parser that lets it pass.
     */
    static String vectorAt(String text, int line) {
        try (JsonParser p = LENIENT.createParser(text)) {
            int depth = 0;
            boolean inVectors = false;
            String id = null;
            int start = 0;
            for (JsonToken t = p.nextToken(); t != null; t = p.nextToken()) {
                if (t == JsonToken.START_OBJECT || t == JsonToken.START_ARRAY) {
                    depth++;
                    if (inVectors && depth == 3 && t == JsonToken.START_OBJECT) {
                        start = p.currentLocation().getLineNr();
                        id = null;
                    }
                } else if (t == JsonToken.END_OBJECT || t == JsonToken.END_ARRAY) {
                    if (inVectors && depth == 3 && t == JsonToken.END_OBJECT && start <= line
                            && line <= p.currentLocation().getLineNr()) {
                        return id;
                    }
                    depth--;
                    inVectors &= depth >= 2;
                } else if (t == JsonToken.PROPERTY_NAME && depth == 1) {
                    inVectors = "vectors".equals(p.currentName());
                } else if (t == JsonToken.VALUE_STRING && inVectors && depth == 3 && "id".equals(p.currentName())) {
                    id = p.getString();
                }
            }
        } catch (JacksonException e) {
            return null;
        }
        return null;
    }

    /** The id of a vector on one line of a JSON-lines file, read by a parser that lets a repeated key pass. */
    static String idOf(String line) {
        try {
            JsonNode node = LENIENT.readTree(line);
            return node != null && node.path("id").isString() ? node.get("id").stringValue() : null;
        } catch (JacksonException e) {
            return null;
        }
    }
}
