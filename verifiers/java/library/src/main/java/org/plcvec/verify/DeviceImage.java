package org.plcvec.verify;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The devices after one step, as a contract-level {@link Implementation} reports them: every
 * device the vector lists (scratch may be left out) plus any other device the step wrote.
 */
public final class DeviceImage {
    private final Address[] addresses;
    private final int[] values;
    private final Object[] others;   // the reported object where a value is Values.OTHER, else null

    DeviceImage(Address[] addresses, int[] values, Object[] others) {
        this.addresses = addresses;
        this.values = values;
        this.others = others;
    }

    /**
     * From a map of device name to value: {@code Boolean} for a bit, an integer 0..65535 for a word.
     * Anything else is kept, and reported as a wrong value.
     *
     * @param devices what an implementation reports after a step
     * @return the image
     */
    public static DeviceImage of(Map<String, ?> devices) {
        Address[] a = new Address[devices.size()];
        int[] v = new int[devices.size()];
        Object[] others = null;
        int i = 0;
        for (Map.Entry<String, ?> e : devices.entrySet()) {
            a[i] = Address.of(e.getKey());
            v[i] = Values.encode(e.getValue());
            if (v[i] == Values.OTHER) {
                if (others == null) {
                    others = new Object[a.length];
                }
                others[i] = e.getValue();
            }
            i++;
        }
        return new DeviceImage(a, v, others);
    }

    /**
     * The number of devices reported.
     *
     * @return the size
     */
    public int size() {
        return addresses.length;
    }

    /**
     * The device of entry {@code i}.
     *
     * @param i the entry, 0 to size() - 1
     * @return its address
     */
    public Address address(int i) {
        return addresses[i];
    }

    /**
     * The encoded value ({@link Values}) of entry {@code i}.
     *
     * @param i the entry, 0 to size() - 1
     * @return the value, {@link Values#OTHER} for one that is neither a word nor a bit
     */
    public int value(int i) {
        return values[i];
    }

    /**
     * The value as reported, for messages, as TEXT.md shows values: a word or a bit as itself, an
     * integer outside the word range as its digits, a floating-point number in Java's shortest
     * round-trip form ({@code NaN}, {@code Infinity} and {@code -Infinity} for those that are not
     * finite), a string, {@code null}, a list or a map as compact JSON.
     *
     * @param i the entry
     * @return the value as a report shows it
     */
    public String show(int i) {
        return values[i] == Values.OTHER ? Values.showReported(others[i]) : Values.show(values[i]);
    }

    /**
     * JSON-ready: words as Integer, bits as Boolean.
     *
     * @return device name to value, in report order
     */
    public Map<String, Object> toMap() {
        Map<String, Object> out = new LinkedHashMap<>();
        for (int i = 0; i < addresses.length; i++) {
            out.put(addresses[i].name(), values[i] == Values.OTHER ? others[i] : Values.decode(values[i]));
        }
        return out;
    }

    @Override
    public String toString() {
        return toMap().toString();
    }
}
