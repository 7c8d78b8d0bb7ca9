package org.plcvec.verify;

/** An instruction operand: a device ({@code {"device": "D100"}}) or a K/H constant ({@code {"constant": 7}}). */
public final class Operand {
    private final Address device;
    private final long constant;

    private Operand(Address device, long constant) {
        this.device = device;
        this.constant = constant;
    }

    public static Operand device(String name) {
        return new Operand(Address.of(name), 0);
    }

    public static Operand constant(long value) {
        return new Operand(null, value);
    }

    public boolean isConstant() {
        return device == null;
    }

    /** The device; a multi-word operand occupies it and the words after it, in the manual's order. */
    public Address device() {
        if (device == null) {
            throw new IllegalStateException("the operand is the constant " + constant + ", not a device");
        }
        return device;
    }

    public long constant() {
        if (device != null) {
            throw new IllegalStateException("the operand is the device " + device + ", not a constant");
        }
        return constant;
    }

    /** A one-word operand's value: the constant's low 16 bits, or the word in the device. */
    public int word(Memory memory) {
        return device == null ? (int) (constant & 0xFFFF) : memory.word(device);
    }

    @Override
    public String toString() {
        return device == null ? "K" + constant : device.name();
    }
}
