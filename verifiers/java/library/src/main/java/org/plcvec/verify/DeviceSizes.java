package org.plcvec.verify;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/** The number of points of each device type ({@code assumes.device_sizes}: D 8000 is D0..D7999). */
public final class DeviceSizes {
    public static final DeviceSizes UNSTATED = new DeviceSizes(Map.of());

    private final Map<String, Integer> sizes;

    public DeviceSizes(Map<String, Integer> sizes) {
        this.sizes = Collections.unmodifiableMap(new LinkedHashMap<>(sizes));
    }

    /** Points of device type {@code kind}, or -1 when the vector does not state it. */
    public int of(String kind) {
        Integer n = sizes.get(kind);
        return n == null ? -1 : n;
    }

    /** Whether {@code count} points from {@code base} all exist; an unstated type is taken to exist. */
    public boolean inRange(Address base, int count) {
        Integer n = sizes.get(base.kind());
        if (n == null) {
            return true;
        }
        long last = (long) base.number() + count;
        return base.number() >= 0 && last <= n;
    }

    public Map<String, Integer> asMap() {
        return sizes;
    }

    @Override
    public String toString() {
        return sizes.toString();
    }
}
