package org.plcvec.verify;

import java.util.concurrent.ConcurrentHashMap;

/**
 * A device address, split once into its device type and number: {@code D100} is ({@code D}, 100);
 * a named device such as Omron's {@code P_EQ} has no number.
 *
 * <p>Addresses are interned, and each has a {@link #key()} that is unique per address and such
 * that the address {@code n} points further is {@code key() + n}: a multi-word operand is read
 * without building strings.
 */
public final class Address {
    private static final ConcurrentHashMap<String, Address> BY_NAME = new ConcurrentHashMap<>();
    private static final ConcurrentHashMap<String, Integer> KINDS = new ConcurrentHashMap<>();
    private static final java.util.concurrent.atomic.AtomicInteger NEXT_KIND = new java.util.concurrent.atomic.AtomicInteger();
    /** Named devices get numbers from here, above any real device number. */
    private static final int NAMED = Integer.MAX_VALUE;

    private final String name;
    private final String kind;
    private final int number;      // -1 for a named device
    private final long key;

    private Address(String name, String kind, int number, long key) {
        this.name = name;
        this.kind = kind;
        this.number = number;
        this.key = key;
    }

    /**
     * The address named {@code name} ({@code D100}, {@code SM709}, {@code P_ER}).
     *
     * @param name the device as the vectors spell it
     * @return its address (one object per name)
     */
    public static Address of(String name) {
        Address a = BY_NAME.get(name);
        return a != null ? a : BY_NAME.computeIfAbsent(name, Address::parse);
    }

    private static Address parse(String name) {
        int split = name.length();
        while (split > 0 && Character.isDigit(name.charAt(split - 1))) {
            split--;
        }
        boolean numbered = split > 0 && split < name.length() && name.chars().limit(split).allMatch(c -> c >= 'A' && c <= 'Z')
                && name.length() - split <= 9;
        if (!numbered) {
            // A named device is a type of its own with a single point.
            return new Address(name, name, -1, kindKey(name) | NAMED);
        }
        String kind = name.substring(0, split);
        int number = Integer.parseInt(name.substring(split));
        return new Address(name, kind, number, kindKey(kind) | number);
    }

    private static long kindKey(String kind) {
        int id = KINDS.computeIfAbsent(kind, k -> NEXT_KIND.incrementAndGet());
        return ((long) id) << 32;
    }

    /**
     * The address {@code offset} points further ({@code D100}.plus(2) is {@code D102}).
     *
     * @param offset how many points further
     * @return that address
     * @throws IllegalArgumentException for a named device, which has no next point
     */
    public Address plus(int offset) {
        if (number < 0) {
            throw new IllegalArgumentException(name + " is not a numbered device");
        }
        return offset == 0 ? this : of(kind + (number + offset));
    }

    /**
     * The device as the vectors spell it.
     *
     * @return {@code D100}, {@code SM709}, {@code P_ER}
     */
    public String name() {
        return name;
    }

    /**
     * The device type: {@code D}, {@code SM}, or the whole name of a named device.
     *
     * @return the type
     */
    public String kind() {
        return kind;
    }

    /**
     * The device number, or -1 for a named device.
     *
     * @return the number
     */
    public int number() {
        return number;
    }

    /**
     * A key unique per address, one addition away from the next point.
     *
     * @return the key; {@code plus(n).key() == key() + n}
     */
    public long key() {
        return key;
    }

    @Override
    public String toString() {
        return name;
    }
}
