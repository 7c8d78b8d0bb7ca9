package org.plcvec.verify;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The device image of one vector run: what an emulator's memory looks like to the verifier.
 *
 * <p>It starts as the vector's {@code initial.devices}. A device the vector does not list reads
 * as 0 (or off) and, once written, is recorded, so that a write outside the vector is reported.
 * Words are stored as their raw 16 bits; bits as bits. Lookups go by {@link Address#key()} over a
 * handful of slots, which is faster than hashing strings for the dozen devices a vector holds.
 */
public final class Memory {
    private final DeviceSizes sizes;
    private long[] keys;
    private Address[] addresses;
    private int[] values;
    private int size;

    /**
     * An empty image.
     *
     * @param sizes the device sizes ({@code assumes.device_sizes})
     */
    public Memory(DeviceSizes sizes) {
        this(sizes, new Address[0], new int[0]);
    }

    Memory(DeviceSizes sizes, Address[] slots, int[] initial) {
        this.sizes = sizes;
        int capacity = Math.max(8, slots.length + 4);
        this.keys = new long[capacity];
        this.addresses = new Address[capacity];
        this.values = new int[capacity];
        for (int i = 0; i < slots.length; i++) {
            keys[i] = slots[i].key();
            addresses[i] = slots[i];
        }
        this.size = slots.length;
        System.arraycopy(initial, 0, values, 0, initial.length);
    }

    /** Back to {@code initial} over the first slots; anything recorded past them is dropped. */
    void reset(int listed, int[] initial) {
        size = listed;
        System.arraycopy(initial, 0, values, 0, listed);
    }

    private int slot(long key) {
        long[] k = keys;
        for (int i = 0, n = size; i < n; i++) {
            if (k[i] == key) {
                return i;
            }
        }
        return -1;
    }

    private int slotForWrite(Address address) {
        int i = slot(address.key());
        if (i >= 0) {
            return i;
        }
        if (size == keys.length) {
            int capacity = size * 2;
            keys = Arrays.copyOf(keys, capacity);
            addresses = Arrays.copyOf(addresses, capacity);
            values = Arrays.copyOf(values, capacity);
        }
        keys[size] = address.key();
        addresses[size] = address;
        values[size] = Values.ABSENT;
        return size++;
    }

    /**
     * The encoded value ({@link Values}) of a device.
     *
     * @param address the device
     * @return its value, {@link Values#ABSENT} if it holds nothing
     */
    public int raw(Address address) {
        int i = slot(address.key());
        return i < 0 ? Values.ABSENT : values[i];
    }

    /**
     * Store an encoded value ({@link Values}) as it is.
     *
     * @param address the device
     * @param value the encoded value
     */
    public void setRaw(Address address, int value) {
        values[slotForWrite(address)] = value;
    }

    /**
     * A word: its raw 16 bits (a bit device reads as 0 or 1; an unlisted device as 0).
     *
     * @param address the device
     * @return the word, 0..65535
     */
    public int word(Address address) {
        int i = slot(address.key());
        if (i < 0) {
            return 0;
        }
        int v = values[i];
        return v >= 0 ? v & 0xFFFF : 0;
    }

    /**
     * The word {@code offset} points past {@code base} ({@code word(D100, 2)} is D102).
     *
     * @param base the first word
     * @param offset how many points further
     * @return the word, 0..65535
     */
    public int word(Address base, int offset) {
        int i = slot(base.key() + offset);
        if (i < 0) {
            return 0;
        }
        int v = values[i];
        return v >= 0 ? v & 0xFFFF : 0;
    }

    /**
     * A word, by the device's name.
     *
     * @param device the device ({@code D100})
     * @return the word, 0..65535
     */
    public int word(String device) {
        return word(Address.of(device));
    }

    /**
     * A bit (a word device reads as on when non-zero; an unlisted device as off).
     *
     * @param address the device
     * @return whether it is on
     */
    public boolean bit(Address address) {
        int i = slot(address.key());
        if (i < 0) {
            return false;
        }
        int v = values[i];
        return v == Values.TRUE || (v > 0 && v <= 0xFFFF);
    }

    /**
     * A bit, by the device's name.
     *
     * @param device the device ({@code SM709})
     * @return whether it is on
     */
    public boolean bit(String device) {
        return bit(Address.of(device));
    }

    /**
     * Write a word (the low 16 bits of {@code value}).
     *
     * @param address the device
     * @param value the value, whose low 16 bits are written
     */
    public void setWord(Address address, int value) {
        values[slotForWrite(address)] = value & 0xFFFF;
    }

    /**
     * Write the word {@code offset} points past {@code base}.
     *
     * @param base the first word
     * @param offset how many points further
     * @param value the value, whose low 16 bits are written
     */
    public void setWord(Address base, int offset, int value) {
        setWord(offset == 0 ? base : base.plus(offset), value);
    }

    /**
     * Write a word, by the device's name.
     *
     * @param device the device ({@code D300})
     * @param value the value, whose low 16 bits are written
     */
    public void setWord(String device, int value) {
        setWord(Address.of(device), value);
    }

    /**
     * Write a bit.
     *
     * @param address the device
     * @param on its new state
     */
    public void setBit(Address address, boolean on) {
        values[slotForWrite(address)] = on ? Values.TRUE : Values.FALSE;
    }

    /**
     * Write a bit, by the device's name.
     *
     * @param device the device ({@code SM709})
     * @param on its new state
     */
    public void setBit(String device, boolean on) {
        setBit(Address.of(device), on);
    }

    /**
     * Whether {@code count} points from {@code base} all exist in the device
     * ({@code assumes.device_sizes}). A device type whose size the vector does not state is
     * taken to exist.
     *
     * @param base the first point
     * @param count how many points from it
     * @return true when all exist
     */
    public boolean inRange(Address base, int count) {
        return sizes.inRange(base, count);
    }

    /**
     * The device sizes the vector assumes.
     *
     * @return the sizes
     */
    public DeviceSizes sizes() {
        return sizes;
    }

    /**
     * The number of devices in the image (listed ones first, then any written outside).
     *
     * @return the number of slots
     */
    public int size() {
        return size;
    }

    /**
     * The address in slot {@code i}.
     *
     * @param i the slot, 0 to size() - 1
     * @return the device
     */
    public Address address(int i) {
        return addresses[i];
    }

    /**
     * The encoded value in slot {@code i}.
     *
     * @param i the slot, 0 to size() - 1
     * @return the value ({@link Values})
     */
    public int valueAt(int i) {
        return values[i];
    }

    /**
     * The image as JSON-ready values (words as Integer, bits as Boolean), in slot order.
     *
     * @return device name to value
     */
    public Map<String, Object> toMap() {
        Map<String, Object> out = new LinkedHashMap<>();
        for (int i = 0; i < size; i++) {
            if (values[i] != Values.ABSENT) {
                out.put(addresses[i].name(), Values.decode(values[i]));
            }
        }
        return out;
    }

    /**
     * A copy of the image as it is now.
     *
     * @return the devices that hold a value
     */
    public DeviceImage snapshot() {
        int n = 0;
        for (int i = 0; i < size; i++) {
            n += values[i] != Values.ABSENT ? 1 : 0;
        }
        if (n == size) {
            return new DeviceImage(Arrays.copyOf(addresses, size), Arrays.copyOf(values, size), null);
        }
        // Devices the vector names for later (a step's `set`) hold nothing yet: not in the image.
        Address[] a = new Address[n];
        int[] v = new int[n];
        for (int i = 0, j = 0; i < size; i++) {
            if (values[i] != Values.ABSENT) {
                a[j] = addresses[i];
                v[j++] = values[i];
            }
        }
        return new DeviceImage(a, v, null);
    }

    @Override
    public String toString() {
        return toMap().toString();
    }
}
