// A C++ emulator's GoogleTest suite over plcvec (plcvec/gtest.hpp): one test per vector, named
// after its id (spelled as GoogleTest names allow: '*HOUR__wrap*'); PLCVEC_ID and the other
// PLCVEC_* variables select vectors by their real ids. The emulator here is the IDEC FC6A HOUR instruction on a std::map memory,
// plugged in with the "execute on my memory" helper (plcvec_machine).
#include <cstdio>
#include <map>
#include <string>

#include "plcvec/gtest.hpp"

namespace {

// ---- the emulator ----

class HourMeter {
  public:
    void reset() {
        memory_.clear();
        fraction_ms_ = 0;
    }
    void write(const std::string &device, unsigned value) { memory_[device] = value; }
    unsigned read(const std::string &device) const {
        auto it = memory_.find(device);
        return it == memory_.end() ? 0 : it->second;
    }
    const std::map<std::string, unsigned> &memory() const { return memory_; }

    // One scan of HOUR D1, D2, S1 (D3 is our own work area: kept in fraction_ms_).
    void execute(const plcvec_vector *v, const plcvec_step *step) {
        if (step->input != 1)
            return;                                 // input off: D1 and D2 hold
        const plcvec_operand *d1 = plcvec_operand_named(v, "D1"), *d2 = plcvec_operand_named(v, "D2");
        const plcvec_operand *s1 = plcvec_operand_named(v, "S1");
        fraction_ms_ += step->elapsed_ms;
        long total = seconds(d1) + static_cast<long>(fraction_ms_ / 1000);
        fraction_ms_ %= 1000;
        total %= 65536L * 3600;                     // past 65535:59:59 back to 0:00:00
        put(d1, 0, total / 3600), put(d1, 1, total / 60 % 60), put(d1, 2, total % 60);
        long preset[3] = {s1->is_constant ? (s1->constant & 0xFFFF) : static_cast<long>(word(s1, 0)),
                          s1->is_constant ? 0 : static_cast<long>(word(s1, 1)),
                          s1->is_constant ? 0 : static_cast<long>(word(s1, 2))};
        if (preset[1] > 59 || preset[2] > 59) {     // invalid preset: error, output off, still measuring
            write("M8004", 1);
            write(plcvec_operand_device_name(d2), 0);
            return;
        }
        if (total >= preset[0] * 3600 + preset[1] * 60 + preset[2])
            write(plcvec_operand_device_name(d2), 1);
    }

  private:
    static std::string at(const plcvec_operand *op, int offset) {
        const plcvec_device_info &d = plcvec_devices[op->device];
        return d.kind + std::to_string(d.number + offset);
    }
    unsigned word(const plcvec_operand *op, int offset) const { return read(at(op, offset)); }
    void put(const plcvec_operand *op, int offset, long value) { write(at(op, offset), static_cast<unsigned>(value)); }
    long seconds(const plcvec_operand *d1) const { return word(d1, 0) * 3600L + word(d1, 1) * 60L + word(d1, 2); }

    std::map<std::string, unsigned> memory_;
    int64_t fraction_ms_ = 0;
};

// ---- plugging it into plcvec ----

HourMeter emulator;

plcvec_machine machine() {
    plcvec_machine m{};
    m.name = "gtest-hour-meter";
    m.supports = [](void *, plcvec_instruction i) { return i == PLCVEC_INSTR_HOUR ? 1 : 0; };
    m.reset = [](void *, const plcvec_vector *) { emulator.reset(); return 0; };
    m.write = [](void *, const char *device, plcvec_type, unsigned value) { emulator.write(device, value); };
    m.read = [](void *, const char *device) { return emulator.read(device); };
    m.execute = [](void *, const plcvec_vector *v, const plcvec_step *step) {
        emulator.execute(v, step);
        return static_cast<int>(PLCVEC_NONE);
    };
    m.written = [](void *, void (*seen)(void *, const char *, plcvec_type, unsigned), void *arg) {
        for (const auto &[device, value] : emulator.memory())
            seen(arg, device.c_str(), device[0] == 'M' ? PLCVEC_BIT : PLCVEC_WORD, value);
    };
    return m;
}

plcvec_judge *judge() {
    static const plcvec_machine m = machine();
    static const plcvec_impl impl = plcvec_machine_impl(&m);
    static plcvec_judge *j = [] {
        char err[256];
        plcvec_judge *made = plcvec_judge_new(&impl, err, sizeof err);
        if (!made)
            std::fprintf(stderr, "plcvec: %s\n", err);
        return made;
    }();
    return j;
}

class Conformance : public ::testing::TestWithParam<const plcvec_vector *> {};

TEST_P(Conformance, Vector) { plcvec::gtest::check(judge(), GetParam()); }

INSTANTIATE_TEST_SUITE_P(Hour, Conformance, ::testing::ValuesIn(plcvec::gtest::vectors("fc6a-hour-meter")),
                         plcvec::gtest::test_name);

}  // namespace

// RUN_ALL_TESTS() and the gate GoogleTest does not keep: a --gtest_filter that matches no vector,
// or a run in which every vector was skipped, exits 5, not 0.
int main(int argc, char **argv) {
    ::testing::InitGoogleTest(&argc, argv);
    return plcvec::gtest::run_all_tests();
}
