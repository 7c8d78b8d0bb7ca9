package org.plcvec.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.plcvec.spec.Instruction;
import org.plcvec.verify.Address;

/**
 * What keeps the reference's executions fast. HotSpot's optimizing compiler inlines a hot method
 * only up to FreqInlineSize (325 bytes of bytecode); a method one byte over it is called at every
 * execution instead of compiled into its caller. The comparisons' evaluate methods once grew past it
 * (333 and 359 bytes) and the judging loop slowed by about a tenth, so the methods every execution
 * runs are held under it here, measured in the compiled classes.
 */
class InlinableTest {
    /** HotSpot's FreqInlineSize (its default on every platform). */
    private static final int FREQ_INLINE_SIZE = 325;

    /** The methods one execution of a comparison or a TADD runs, by class and name (every overload). */
    private static final Map<Class<?>, List<String>> HOT = Map.of(
            Fx5Compare.class, List.of("<init>", "execute", "evaluate", "endedBeforeComparing", "read", "clock",
                    "outOfRange", "compare"),
            Cp1eTimeCompare.class, List.of("<init>", "execute", "evaluate", "allMasked", "executed", "reflectFlags",
                    "invalid"),
            Fx5TimeAdd.class, List.of("<init>", "execute", "add", "sum", "carries", "setFlags", "read", "valid"),
            Contact.class, List.of("result", "holds"),
            Reference.class, List.of("load"));

    @Test
    void everyMethodOfAnExecutionIsSmallEnoughToInline() throws IOException {
        for (Map.Entry<Class<?>, List<String>> e : HOT.entrySet()) {
            Map<String, Integer> sizes = codeSizes(e.getKey());
            for (String method : e.getValue()) {
                Integer size = sizes.get(method);
                assertNotNull(size, e.getKey().getSimpleName() + "." + method + ": no such method (renamed? update HOT)");
                assertTrue(size <= FREQ_INLINE_SIZE, e.getKey().getSimpleName() + "." + method + " is " + size
                        + " bytes of bytecode, past the " + FREQ_INLINE_SIZE + " up to which the JIT inlines a hot method:"
                        + " split it");
            }
        }
    }

    /** The table of flags by condition is the map the manual's names are written in, condition for condition. */
    @Test
    void theFlagOfEachConditionIsTheMapsOne() throws ReflectiveOperationException {
        java.lang.reflect.Field field = Cp1eTimeCompare.class.getDeclaredField("FLAG_OF");
        field.setAccessible(true);
        Address[] byOrdinal = (Address[]) field.get(null);
        assertEquals(Instruction.Condition.values().length, byOrdinal.length);
        assertEquals(Instruction.Condition.values().length, Cp1eTimeCompare.FLAGS.size());
        for (Instruction.Condition c : Instruction.Condition.values()) {
            assertEquals(Cp1eTimeCompare.FLAGS.get(c), byOrdinal[c.ordinal()], c.name());
        }
        assertEquals("P_LE", byOrdinal[Instruction.Condition.LE.ordinal()].name());
    }

    /**
     * The largest Code attribute among the methods of each name declared by {@code c}, read from its
     * class file (JVMS 4.1, 4.4, 4.7.3): the constant pool is walked for the names, the rest skipped.
     */
    static Map<String, Integer> codeSizes(Class<?> c) throws IOException {
        try (InputStream in = c.getResourceAsStream(c.getSimpleName() + ".class")) {
            assertNotNull(in, c + ": class file not found");
            DataInputStream data = new DataInputStream(new ByteArrayInputStream(in.readAllBytes()));
            data.readInt();            // magic
            data.readInt();            // minor and major version
            String[] utf8 = constantPool(data);
            data.skipBytes(6);         // access flags, this class, super class
            data.skipBytes(2 * data.readUnsignedShort());   // interfaces
            int fields = data.readUnsignedShort();
            for (int i = 0; i < fields; i++) {
                data.skipBytes(6);
                skipAttributes(data);
            }
            Map<String, Integer> sizes = new HashMap<>();
            int methods = data.readUnsignedShort();
            for (int i = 0; i < methods; i++) {
                data.skipBytes(2);
                String name = utf8[data.readUnsignedShort()];
                data.skipBytes(2);
                int attributes = data.readUnsignedShort();
                for (int a = 0; a < attributes; a++) {
                    String attribute = utf8[data.readUnsignedShort()];
                    int length = data.readInt();
                    if (attribute.equals("Code")) {
                        data.skipBytes(4);   // max_stack, max_locals
                        int code = data.readInt();
                        sizes.merge(name, code, Math::max);
                        data.skipBytes(length - 8);
                    } else {
                        data.skipBytes(length);
                    }
                }
            }
            return sizes;
        }
    }

    /** The constant pool's UTF-8 entries by index (null for the other kinds). */
    private static String[] constantPool(DataInputStream data) throws IOException {
        int count = data.readUnsignedShort();
        String[] utf8 = new String[count];
        for (int i = 1; i < count; i++) {
            int tag = data.readUnsignedByte();
            switch (tag) {
                case 1 -> utf8[i] = data.readUTF();
                case 7, 8, 16, 19, 20 -> data.skipBytes(2);   // Class, String, MethodType, Module, Package
                case 15 -> data.skipBytes(3);                 // MethodHandle
                case 3, 4, 9, 10, 11, 12, 17, 18 -> data.skipBytes(4);
                case 5, 6 -> {                                // Long, Double: two entries
                    data.skipBytes(8);
                    i++;
                }
                default -> throw new IOException("constant pool tag " + tag + " at entry " + i);
            }
        }
        return utf8;
    }

    private static void skipAttributes(DataInputStream data) throws IOException {
        int attributes = data.readUnsignedShort();
        for (int a = 0; a < attributes; a++) {
            data.skipBytes(2);
            data.skipBytes(data.readInt());
        }
    }
}
