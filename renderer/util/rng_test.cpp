#include "util/rng.h"

#include <gtest/gtest.h>

namespace wavelit::util {
namespace {

// Reference values of the minimal PCG32 (pcg32-demo with seed 42, stream 54).
TEST(Pcg32, MatchesReferenceSequence) {
    Pcg32 rng(42u, 54u);
    const uint32_t expected[] = {0xa15c02b7, 0x7b47f409, 0xba1d3330, 0x83d2f293, 0xbfa4784b, 0xcbed606e};
    for (uint32_t e : expected) EXPECT_EQ(rng.nextUint(), e);
}

TEST(Pcg32, FloatsStayInHalfOpenUnitInterval) {
    Pcg32 rng(1);
    double sum = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        float f = rng.nextFloat();
        ASSERT_GE(f, 0.0f);
        ASSERT_LT(f, 1.0f);
        sum += f;
    }
    // Mean of U(0,1): 0.5 with standard error 1/sqrt(12 n) = 6.5e-4; allow 4 sigma.
    EXPECT_NEAR(sum / n, 0.5, 4 * 6.5e-4);
}

} // namespace
} // namespace wavelit::util
