package org.plcvec.verify;

/** An instruction operand: a device ({@code {"device": "D100"}}) or a K/H constant ({@code {"constant": 7}}). */
public final class Operand {
    private final Address device;
    private final long constant;

    private Operand(Address device, long constant) {
        this.device = device;
        this.constant = constant;
    }

    /**
     * A device operand ({@code {"device": "D100"}}).
     *
     * @param name the device
     * @return the operand
     */
    public static Operand device(String name) {
        return new Operand(Address.of(name), 0);
    }

    /**
     * A K/H constant operand ({@code {"constant": 7}}).
     *
     * @param value the constant
     * @return the operand
     */
    public static Operand constant(long value) {
        return new Operand(null, value);
    }

    /**
     * Whether the operand is a constant rather than a device.
     *
     * @return true for a constant
     */
    public boolean isConstant() {
        return device == null;
    }

    /**
     * The device; a multi-word operand occupies it and the words after it, in the manual's order.
     *
     * @return the device
     * @throws IllegalStateException for a constant
     */
    public Address device() {
        if (device == null) {
            throw new IllegalStateException("the operand is the constant " + constant + ", not a device");
        }
        return device;
    }

    /**
     * The constant.
     *
     * @return its value
     * @throws IllegalStateException for a device
     */
    public long constant() {
        if (device != null) {
            throw new IllegalStateException("the operand is the device " + device + ", not a constant");
        }
        return constant;
    }

    /**
     * A one-word operand's value: the constant's low 16 bits, or the word in the device.
     *
     * @param memory where the device is read
     * @return the word, 0..65535
     */
    public int word(Memory memory) {
        return device == null ? (int) (constant & 0xFFFF) : memory.word(device);
    }

    @Override
    public String toString() {
        return device == null ? "K" + constant : device.name();
    }
}
