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

    public int size() {
        return addresses.length;
    }

    public Address address(int i) {
        return addresses[i];
    }

    /** The encoded value ({@link Values}) of entry {@code i}. */
    public int value(int i) {
        return values[i];
    }

    /** The value as reported, for messages: a word, a bit, or whatever else was reported. */
    public String show(int i) {
        if (values[i] == Values.OTHER) {
            Object o = others[i];
            return o instanceof String ? "\"" + o + "\"" : String.valueOf(o)
                    + (o == null ? "" : " (" + o.getClass().getSimpleName() + ")");
        }
        return Values.show(values[i]);
    }

    /** JSON-ready: words as Integer, bits as Boolean. */
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
