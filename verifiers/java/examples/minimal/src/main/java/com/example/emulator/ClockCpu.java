package com.example.emulator;

/**
 * Stands for your emulator: a CPU with its own word and bit memory, here able to execute the FX5
 * clock addition TADD / TADDP (MELSEC iQ-F programming manual). Nothing in it knows plcvec.
 */
public final class ClockCpu {
    /** What the CPU reads and writes; an emulator has its own, plcvec's Memory is adapted to it. */
    public interface Devices {
        int word(String device, int offset);

        void setWord(String device, int offset, int value);

        void setBit(String device, boolean on);

        /** Whether {@code count} points from {@code device} exist in this CPU. */
        boolean exists(String device, int count);
    }

    private final Devices devices;
    private boolean previousEn;

    public ClockCpu(Devices devices) {
        this.devices = devices;
    }

    /** One scan of TADD (every scan while EN is on) or TADDP (on the rising edge of EN). */
    public void tadd(boolean pulse, boolean en, String s1, String s2, String d) {
        boolean run = pulse ? en && !previousEn : en;
        previousEn = en;
        if (!run) {
            return;
        }
        if (!devices.exists(s1, 3) || !devices.exists(s2, 3) || !devices.exists(d, 3)) {
            error(0x2820);
            return;
        }
        int[] a = hms(s1);
        int[] b = hms(s2);
        if (a == null || b == null) {
            error(0x3405);
            return;
        }
        int total = (a[0] + b[0]) * 3600 + (a[1] + b[1]) * 60 + a[2] + b[2];
        int day = 24 * 3600;
        int result = total % day;
        devices.setWord(d, 0, result / 3600);
        devices.setWord(d, 1, result / 60 % 60);
        devices.setWord(d, 2, result % 60);
        devices.setBit("SM700", total >= day);
        devices.setBit("SM8022", total >= day);
        devices.setBit("SM8020", result == 0);
    }

    /** Hour, minute, second as 16-bit signed words, or null when one is out of range. */
    private int[] hms(String device) {
        int[] v = new int[3];
        int[] max = {23, 59, 59};
        for (int i = 0; i < 3; i++) {
            v[i] = (short) devices.word(device, i);
            if (v[i] < 0 || v[i] > max[i]) {
                return null;
            }
        }
        return v;
    }

    private void error(int code) {
        devices.setWord("SD0", 0, code);
        devices.setWord("SD8067", 0, code);
    }
}
