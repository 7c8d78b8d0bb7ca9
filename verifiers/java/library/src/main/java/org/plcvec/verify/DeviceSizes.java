package org.plcvec.verify;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/** The number of points of each device type ({@code assumes.device_sizes}: D 8000 is D0..D7999). */
public final class DeviceSizes {
    /** No size stated: every device is taken to exist. */
    public static final DeviceSizes UNSTATED = new DeviceSizes(Map.of());

    private final Map<String, Integer> sizes;
    // The same by device type id (the high half of Address.key()): checked on every execution.
    private final long[] kinds;
    private final int[] points;

    /**
     * Sizes by device type.
     *
     * @param sizes device type to its number of points ({@code D} to 8000)
     */
    public DeviceSizes(Map<String, Integer> sizes) {
        this.sizes = Collections.unmodifiableMap(new LinkedHashMap<>(sizes));
        this.kinds = new long[sizes.size()];
        this.points = new int[sizes.size()];
        int i = 0;
        for (Map.Entry<String, Integer> e : this.sizes.entrySet()) {
            kinds[i] = Address.of(e.getKey() + "0").key() >>> 32;
            points[i++] = e.getValue();
        }
    }

    /**
     * The number of points of a device type.
     *
     * @param kind the device type ({@code D})
     * @return its points, or -1 when the vector does not state it
     */
    public int of(String kind) {
        Integer n = sizes.get(kind);
        return n == null ? -1 : n;
    }

    /**
     * Whether {@code count} points from {@code base} all exist; an unstated type is taken to exist.
     *
     * @param base the first point
     * @param count how many points from it
     * @return true when the last of them is within its type's size
     */
    public boolean inRange(Address base, int count) {
        long kind = base.key() >>> 32;
        for (int i = 0; i < kinds.length; i++) {
            if (kinds[i] == kind) {
                return base.number() >= 0 && (long) base.number() + count <= points[i];
            }
        }
        return true;
    }

    /**
     * The sizes as the vector states them.
     *
     * @return device type to its number of points
     */
    public Map<String, Integer> asMap() {
        return sizes;
    }

    @Override
    public String toString() {
        return sizes.toString();
    }
}
