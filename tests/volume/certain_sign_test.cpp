// certain_sign at and around its threshold: a sign only when x² exceeds
// 1e-24 × the bound, which scales with the bound, and never for 0.
#include "volume/certain_sign.h"

#include <gtest/gtest.h>

namespace fabvdb::volume {
namespace {

TEST(CertainSign, SignBeyondTheBound) {
    EXPECT_EQ(certain_sign(1.0, 1.0), 1);
    EXPECT_EQ(certain_sign(-1.0, 1.0), -1);
    EXPECT_EQ(certain_sign(2e-12, 1.0), 1);    // x² = 4e-24 > 1e-24
    EXPECT_EQ(certain_sign(-2e-12, 1.0), -1);
}

TEST(CertainSign, UnsureWithinTheBound) {
    EXPECT_EQ(certain_sign(0.0, 1.0), 0);
    EXPECT_EQ(certain_sign(0.0, 0.0), 0);
    EXPECT_EQ(certain_sign(5e-13, 1.0), 0);    // x² = 2.5e-25
    EXPECT_EQ(certain_sign(-5e-13, 1.0), 0);
}

TEST(CertainSign, TheBoundScalesWithTheTerms) {
    // The same x is certain against small terms and not against large ones.
    EXPECT_EQ(certain_sign(1e-6, 1.0), 1);
    EXPECT_EQ(certain_sign(1e-6, 1e11), 1);   // x² = 1e-12 > 1e-24 × 1e11
    EXPECT_EQ(certain_sign(-1e-6, 1e13), 0);  // x² = 1e-12 < 1e-24 × 1e13
}

}  // namespace
}  // namespace fabvdb::volume
