package com.example.emulator;

import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicNode;
import org.junit.jupiter.api.TestFactory;
import org.plcvec.spec.Family;
import org.plcvec.verify.Address;
import org.plcvec.verify.Emulator;
import org.plcvec.verify.Memory;
import org.plcvec.verify.PlcvecTests;
import org.plcvec.verify.Selection;

/** Every plcvec vector of the FX5 clock addition, one JUnit test each, named by its id. */
class ClockConformanceTest {
    /** The glue: plcvec's memory for one vector, seen as the emulator's devices. */
    static final class Adapted implements ClockCpu.Devices {
        private final Memory memory;

        Adapted(Memory memory) {
            this.memory = memory;
        }

        @Override
        public int word(String device, int offset) {
            return memory.word(Address.of(device), offset);
        }

        @Override
        public void setWord(String device, int offset, int value) {
            memory.setWord(Address.of(device), offset, value);
        }

        @Override
        public void setBit(String device, boolean on) {
            memory.setBit(device, on);
        }

        @Override
        public boolean exists(String device, int count) {
            return memory.inRange(Address.of(device), count);
        }
    }

    /** A fresh CPU per vector; one scan per step. */
    static final Emulator EMULATOR = (vector, memory) -> {
        ClockCpu cpu = new ClockCpu(new Adapted(memory));
        boolean pulse = vector.instruction().equals("TADDP");
        String s1 = vector.operand("s1").device().name();
        String s2 = vector.operand("s2").device().name();
        String d = vector.operand("d").device().name();
        return step -> {
            cpu.tadd(pulse, step.en(), s1, s2, d);
            return null;     // TADD is not a contact: no result
        };
    };

    @TestFactory
    Stream<DynamicNode> plcvec() {
        return PlcvecTests.of(EMULATOR).selection(Selection.all().families(Family.FX5_TIME_ADD)).stream();
    }
}
