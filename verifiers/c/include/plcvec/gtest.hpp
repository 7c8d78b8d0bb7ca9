// plcvec under GoogleTest: one test per vector, and a gate that a filter or a skip cannot turn
// green. Header-only; include it in the test program of your emulator (C++17, GoogleTest 1.10+).
//
//   class Conformance : public ::testing::TestWithParam<const plcvec_vector *> {};
//   TEST_P(Conformance, Vector) { plcvec::gtest::check(judge(), GetParam()); }
//   INSTANTIATE_TEST_SUITE_P(Hour, Conformance, ::testing::ValuesIn(plcvec::gtest::vectors("fc6a-hour-meter")),
//                            plcvec::gtest::test_name);
//   int main(int argc, char **argv) {
//       ::testing::InitGoogleTest(&argc, argv);
//       return plcvec::gtest::run_all_tests();
//   }
//
// vectors() selects as plcvec_main does, from the PLCVEC_* variables. check() judges one vector:
// a failure is a test failure with the field-level text, a skip is a skipped test, a vector listed
// in PLCVEC_KNOWN_FAILURES (or its old name, PLCVEC_EXPECTATIONS) that fails is skipped as a known
// failure and one that passes fails as stale; PLCVEC_WRITE_EXPECTATIONS writes the run's failures
// as a known-failures file. run_all_tests() is RUN_ALL_TESTS() followed by what GoogleTest does not
// print or check: the end of the run in the words of every plcvec runner (the roll-up by reading,
// with the known failures another reading explains; the skips by reason; the summary), exit 5 when
// no vector was judged (a --gtest_filter that matches nothing, an empty selection) or none passed
// (an implementation that skips everything, a list of known failures alone), 1 on a failure or a
// stale known failure.
#ifndef PLCVEC_GTEST_HPP
#define PLCVEC_GTEST_HPP

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "plcvec/plcvec.h"

namespace plcvec::gtest {

namespace detail {
struct Run {
    size_t judged = 0;
    plcvec_report *report = nullptr;        // every verdict, for the end of the run
    std::vector<const char *> failing;      // for PLCVEC_WRITE_EXPECTATIONS: failures and known failures
    std::vector<plcvec_known_failure> known_failures;
    plcvec_known_failure *loaded = nullptr;  // the file's entries, which known_failures points into
    size_t n_loaded = 0;
    bool known_loaded = false;
    std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
    ~Run() {
        plcvec_report_free(report);
        plcvec_known_free(loaded, n_loaded);
    }
};
inline Run &run() {
    static Run r;
    return r;
}
// A mistake in the set-up (a variable, the known-failures file) ends the program with a message
// and the status plcvec_main gives it, 2, before any test runs.
[[noreturn]] inline void usage_error(const std::string &message) {
    std::fprintf(stderr, "plcvec: %s\n", message.c_str());
    std::fflush(nullptr);
    std::_Exit(PLCVEC_EXIT_USAGE);
}
inline const std::vector<plcvec_known_failure> &known_failures() {
    Run &r = run();
    if (!r.known_loaded) {
        r.known_loaded = true;
        if (const char *path = plcvec_setting("PLCVEC_KNOWN_FAILURES")) {
            char err[1024];
            if (plcvec_known_load(path, &r.loaded, &r.n_loaded, err, sizeof err) != 0)
                usage_error(err);
            r.known_failures.assign(r.loaded, r.loaded + r.n_loaded);   // freed with the run, at exit
        }
    }
    return r.known_failures;
}
}  // namespace detail

// The vectors of `family` (nullptr: every family) that the PLCVEC_* variables select.
inline std::vector<const plcvec_vector *> vectors(const char *family = nullptr) {
    const plcvec_vector **list = nullptr;
    char err[1024];
    long n = plcvec_select_from_environment(family, &list, err, sizeof err);
    if (n < 0)
        detail::usage_error(err);
    std::vector<const plcvec_vector *> out(list, list + n);
    std::free(list);
    return out;
}

// GoogleTest names allow letters, digits and '_' alone: plcvec_test_name spells the id so. The
// id itself is the first line of every failure, and recorded as the test's `plcvec_id` property.
inline std::string test_name(const ::testing::TestParamInfo<const plcvec_vector *> &info) {
    std::string name(plcvec_test_name(info.param, nullptr, 0), '\0');
    plcvec_test_name(info.param, name.data(), name.size() + 1);
    return name;
}

// The verdict as text, without a terminating NUL in the string.
inline std::string describe(const plcvec_verdict *vd) {
    std::string text(plcvec_format_verdict(nullptr, 0, vd), '\0');
    plcvec_format_verdict(text.data(), text.size() + 1, vd);
    return text;
}

// Judge one vector inside a TEST_P.
inline void check(plcvec_judge *judge, const plcvec_vector *v) {
    ASSERT_NE(judge, nullptr) << "no judge (plcvec_judge_new refused the implementation)";
    ::testing::Test::RecordProperty("plcvec_id", v->id);
    plcvec_verdict vd = *plcvec_judge_vector(judge, v);
    const auto &known = detail::known_failures();
    plcvec_known_apply(&vd, known.data(), known.size());
    detail::Run &r = detail::run();
    r.judged++;
    if (!r.report)
        r.report = plcvec_report_new(judge);
    if (!r.report || plcvec_report_add(r.report, &vd) != 0)
        detail::usage_error("out of memory");
    switch (vd.status) {
    case PLCVEC_PASS:
        return;
    case PLCVEC_SKIP:
        GTEST_SKIP() << v->id << ": " << vd.message;
    case PLCVEC_XFAIL:
        r.failing.push_back(v->id);
        GTEST_SKIP() << v->id << ": " << vd.message;
    default:
        if (vd.status != PLCVEC_STALE)
            r.failing.push_back(v->id);
        ADD_FAILURE() << describe(&vd);
    }
}

// RUN_ALL_TESTS(), then the end of the run and what makes a run of nothing a failure. Use it as
// main's return value.
inline int run_all_tests() {
    int rc = RUN_ALL_TESTS();
    detail::Run &r = detail::run();
    const auto &known = detail::known_failures();
    // PLCVEC_WRITE_EXPECTATIONS: this run's failures as a known-failures file, as plcvec verify writes it.
    if (const char *path = plcvec_setting("PLCVEC_WRITE_EXPECTATIONS")) {
        char err[1024];
        if (plcvec_known_write(path, r.failing.data(), r.failing.size(), "not yet triaged", err, sizeof err) != 0) {
            std::printf("plcvec: %s\n", err);
            return PLCVEC_EXIT_USAGE;
        }
        std::printf("plcvec: %zu known failures written to %s\n", r.failing.size(), path);
    }
    // No vector judged: GoogleTest may fail the run itself (a parameterized suite with no values),
    // which is the same fact; either way nothing was tested.
    if (r.judged == 0) {
        int stale = 0;
        for (const plcvec_known_failure &k : known)
            stale += !plcvec_find(k.id);
        std::printf("NOT PASSED (exit 5): no vector selected: the test filter or the selection matched none (an empty "
                    "run never passes). Select vectors with PLCVEC_ID (an id or glob, comma-separated) rather than "
                    "--gtest_filter, whose names are not the ids\n");
        return stale ? PLCVEC_EXIT_FAILED : PLCVEC_EXIT_NOTHING_TESTED;
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - r.started).count();
    int end = plcvec_report_end(r.report, stdout, known.data(), known.size(), seconds);
    // A test of the program's own that failed fails the run too.
    return rc != 0 && end != PLCVEC_EXIT_USAGE ? PLCVEC_EXIT_FAILED : end;
}

}  // namespace plcvec::gtest

#endif
