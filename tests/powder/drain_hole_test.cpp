//! spaced_from on hand-placed holes: a candidate exactly the minimum
//! distance from a hole is spaced, one a hair closer is not; every hole
//! counts, not only the nearest in the list; no holes, always spaced.
#include <gtest/gtest.h>

#include <vector>

#include "powder/drain_hole.h"

namespace {

using fabvdb::Vec3;
using fabvdb::powder::DrainHole;
using fabvdb::powder::spaced_from;

DrainHole at(const Vec3& center) {
    DrainHole hole;
    hole.center = center;
    return hole;
}

}  // namespace

TEST(DrainHole, SpacedFromEveryHoleByCentreDistance) {
    const std::vector<DrainHole> holes{at({0, 0, 0}), at({10, 0, 0})};
    EXPECT_TRUE(spaced_from(at({5, 0, 0}), holes, 5.0));
    EXPECT_FALSE(spaced_from(at({5, 0, 0}), holes, 5.01));
    // 3-4-5 from the first hole, far from the second.
    EXPECT_TRUE(spaced_from(at({3, 4, 0}), holes, 5.0));
    EXPECT_FALSE(spaced_from(at({3, 4, 0}), holes, 5.5));
    // Near the second hole only.
    EXPECT_FALSE(spaced_from(at({10, 0, 1}), holes, 2.0));
    EXPECT_TRUE(spaced_from(at({0, 0, 0}), {}, 100.0));
}
