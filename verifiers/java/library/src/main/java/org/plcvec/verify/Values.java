package org.plcvec.verify;

/**
 * Device values as one {@code int} each, with their JSON type folded in.
 *
 * <p>A word is its raw 16 bits, 0..65535. A bit is {@link #FALSE} or {@link #TRUE}, outside the
 * word range, so a bit reported as the word 1 never equals {@code true} (CONTRACT.md: "a bit is
 * never 1") and one int comparison checks value and type together. {@link #ABSENT} marks a
 * device that is not in the image (not listed yet, or never written).
 */
public final class Values {
    /** The bit {@code false}. */
    public static final int FALSE = 0x1_0000;
    /** The bit {@code true}. */
    public static final int TRUE = 0x1_0001;
    /** Not in the device image. */
    public static final int ABSENT = -1;
    /** A value that is neither a word nor a bit (reported by a contract-level implementation). */
    public static final int OTHER = -2;

    private Values() {
    }

    /**
     * The encoded bit.
     *
     * @param on its state
     * @return {@link #TRUE} or {@link #FALSE}
     */
    public static int bit(boolean on) {
        return on ? TRUE : FALSE;
    }

    /**
     * A word from any integer: the low 16 bits, as the CPU stores it.
     *
     * @param value any integer
     * @return the word, 0..65535
     */
    public static int word(int value) {
        return value & 0xFFFF;
    }

    /**
     * Whether an encoded value is a bit.
     *
     * @param value an encoded value
     * @return true for {@link #TRUE} and {@link #FALSE}
     */
    public static boolean isBit(int value) {
        return value == TRUE || value == FALSE;
    }

    /**
     * Whether an encoded value is a word.
     *
     * @param value an encoded value
     * @return true for 0..65535
     */
    public static boolean isWord(int value) {
        return value >= 0 && value <= 0xFFFF;
    }

    /**
     * The encoded value of a JSON-ish Java value.
     *
     * @param value a Boolean, or an integer
     * @return the bit, the word 0..65535, or {@link #OTHER} for anything else
     */
    public static int encode(Object value) {
        if (value instanceof Boolean) {
            return bit((Boolean) value);
        }
        if (value instanceof Integer || value instanceof Long || value instanceof Short) {
            long v = ((Number) value).longValue();
            if (v >= 0 && v <= 0xFFFF) {
                return (int) v;
            }
        }
        return OTHER;
    }

    /**
     * The JSON value of an encoded one.
     *
     * @param value an encoded value
     * @return Boolean for a bit, Integer for a word, null when absent or other
     */
    public static Object decode(int value) {
        if (isBit(value)) {
            return value == TRUE;
        }
        return value == ABSENT || value == OTHER ? null : Integer.valueOf(value);
    }

    /**
     * As a report shows it.
     *
     * @param value an encoded value
     * @return {@code true}, {@code 13317}, ...
     */
    public static String show(int value) {
        if (value == TRUE) {
            return "true";
        }
        if (value == FALSE) {
            return "false";
        }
        return Integer.toString(value);
    }

    /** Compact JSON, as TEXT.md shows a reported list or map. */
    private static final tools.jackson.databind.json.JsonMapper SORTED = tools.jackson.databind.json.JsonMapper.builder()
            .build();

    /** The value with every map's keys sorted (a map may hold its keys in any order of its own). */
    private static Object keysSorted(Object value) {
        if (value instanceof java.util.Map<?, ?> map) {
            java.util.Map<String, Object> out = new java.util.TreeMap<>();
            map.forEach((k, v) -> out.put(String.valueOf(k), keysSorted(v)));
            return out;
        }
        if (value instanceof java.util.Collection<?> list) {
            return list.stream().map(Values::keysSorted).toList();
        }
        return value;
    }

    /**
     * A reported value that is neither a word nor a bit, as a report shows it (TEXT.md, "How values
     * are shown").
     *
     * @param value what the implementation reported
     * @return its digits, {@code NaN}, {@code 13.5}, {@code "13"}, {@code null}, {@code [1,2]}, ...
     */
    public static String showReported(Object value) {
        if (value instanceof Double || value instanceof Float) {
            double d = ((Number) value).doubleValue();
            return Double.isNaN(d) ? "NaN" : Double.isInfinite(d) ? (d > 0 ? "Infinity" : "-Infinity")
                    : value instanceof Float ? Float.toString((Float) value) : Double.toString(d);
        }
        if (value instanceof Number && !(value instanceof java.math.BigDecimal)) {
            return value.toString();
        }
        try {
            return SORTED.writeValueAsString(keysSorted(value));
        } catch (tools.jackson.core.JacksonException e) {
            return String.valueOf(value);
        }
    }
}
