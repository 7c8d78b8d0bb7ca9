// The reference under the README's GoogleTest pattern (plcvec/gtest.hpp), for the row of the
// table of faults in which GoogleTest's own filter matches no test, and with
// PLCVEC_HOSTILE=skips-everything for an implementation that skips every vector: neither run may
// be green. PLCVEC_HOSTILE=follows-alternative follows PLCVEC_HOSTILE_CHOICE (ID=alternative)
// undeclared, so that the end of a GoogleTest run shows the known failures another reading explains.
#include "plcvec/gtest.hpp"

#include <cstdlib>
#include <cstring>
#include <string>

#include "reference.h"

namespace {

int skip(void *, const plcvec_vector *, plcvec_out *out) { return plcvec_out_skip(out, "skips every vector"); }

plcvec_judge *judge() {
    static plcvec_reference ref;
    static plcvec_impl impl;
    static plcvec_judge *j = [] {
        plcvec_reference_init(&ref);
        impl = plcvec_reference_impl(&ref);
        const char *hostile = std::getenv("PLCVEC_HOSTILE");
        if (hostile && std::string(hostile) == "skips-everything")
            impl.run = skip;            // the README's pattern must not turn this green
        const char *choice = std::getenv("PLCVEC_HOSTILE_CHOICE");
        if (hostile && std::string(hostile) == "follows-alternative" && choice && std::strchr(choice, '=')) {
            std::string id(choice, std::strchr(choice, '='));
            if (plcvec_reference_choose(&ref, id.c_str(), std::strchr(choice, '=') + 1) != 0)
                std::fprintf(stderr, "hostile: PLCVEC_HOSTILE_CHOICE=%s: ID=alternative of the suite\n", choice);
            impl.choices = nullptr, impl.n_choices = 0;
        }
        char err[256];
        plcvec_judge *made = plcvec_judge_new(&impl, err, sizeof err);
        if (!made)
            std::fprintf(stderr, "plcvec: %s\n", err);
        return made;
    }();
    return j;
}

class Reference : public ::testing::TestWithParam<const plcvec_vector *> {};

TEST_P(Reference, Vector) { plcvec::gtest::check(judge(), GetParam()); }

INSTANTIATE_TEST_SUITE_P(Plcvec, Reference, ::testing::ValuesIn(plcvec::gtest::vectors()), plcvec::gtest::test_name);

}  // namespace

int main(int argc, char **argv) {
    ::testing::InitGoogleTest(&argc, argv);
    return plcvec::gtest::run_all_tests();
}
