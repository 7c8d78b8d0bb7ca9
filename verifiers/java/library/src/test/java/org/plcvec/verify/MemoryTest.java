package org.plcvec.verify;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Map;

import org.junit.jupiter.api.Test;

class MemoryTest {
    @Test
    void devicesOfDifferentTypesWithTheSameNumberAreDistinct() {
        Memory m = new Memory(DeviceSizes.UNSTATED);
        m.setWord("D100", 7);
        m.setBit("SM100", true);
        assertEquals(7, m.word("D100"));
        assertTrue(m.bit("SM100"));
        assertEquals(0, m.word("D101"));
        assertEquals(Address.of("D102").key(), Address.of("D100").key() + 2);
        assertEquals(Map.of("D100", 7, "SM100", true), m.toMap());
    }

    @Test
    void wordsKeepTheirLow16BitsAndMultiWordOperandsReadOnward() {
        Memory m = new Memory(DeviceSizes.UNSTATED);
        m.setWord(Address.of("D10"), 2, -1);          // "a 16-bit signed binary -1 is 65535"
        assertEquals(65535, m.word(Address.of("D10"), 2));
        assertEquals(65535, m.word("D12"));
        assertEquals(Values.word(0x10000 + 5), 5);
    }

    @Test
    void deviceSizesBoundMultiWordOperands() {
        // {"D": 8000} means D0 to D7999.
        DeviceSizes sizes = new DeviceSizes(Map.of("D", 8000));
        assertTrue(sizes.inRange(Address.of("D7997"), 3));
        assertFalse(sizes.inRange(Address.of("D7998"), 3));
        assertFalse(sizes.inRange(Address.of("D8000"), 1));
        assertTrue(sizes.inRange(Address.of("R99999"), 3));     // a size the vector does not state: assumed to exist
    }

    @Test
    void aDeviceNamedOnlyByALaterSetIsNotInTheImageUntilWritten() {
        // A vector whose step 1 sets D5, which initial.devices does not list.
        Memory m = new Memory(DeviceSizes.UNSTATED, new Address[] {Address.of("D1"), Address.of("D5")},
                new int[] {3, Values.ABSENT});
        assertEquals(Map.of("D1", 3), m.snapshot().toMap());
        assertEquals(0, m.word("D5"));
        m.setWord("D5", 9);
        assertEquals(Map.of("D1", 3, "D5", 9), m.snapshot().toMap());
    }

    @Test
    void namedDevicesAreTheirOwnType() {
        Address er = Address.of("P_ER");
        assertEquals("P_ER", er.kind());
        assertEquals(-1, er.number());
        assertTrue(Address.of("P_EQ").key() != er.key());
    }
}
