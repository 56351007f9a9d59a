// baseline_holes on hand-placed candidates whose answer is read off their
// heights: the lowest of each cavity first, as many as the cavity asks for,
// skipping those closer than the spacing to any hole already taken (exactly
// the spacing is allowed); "low" is along any gravity, whatever its length;
// cavities with no quota or unknown ids get nothing; no candidates, no holes.
#include <gtest/gtest.h>

#include <vector>

#include "powder/baseline_holes.h"

namespace {

using fabvdb::Vec3;
using fabvdb::powder::baseline_holes;
using fabvdb::powder::DrainHole;

DrainHole at(const Vec3& center, uint32_t cavity = 0) {
    DrainHole hole;
    hole.center = center;
    hole.cavity = cavity;
    return hole;
}

}  // namespace

TEST(BaselineHoles, TakesTheLowestCandidatesLowestFirst) {
    const std::vector<DrainHole> candidates{at({0, 0, 5}), at({10, 0, 1}), at({20, 0, 3}), at({30, 0, 0}),
                                            at({40, 0, 4})};
    EXPECT_EQ(baseline_holes(candidates, {2}, {0, 0, -1}, 1.0), (std::vector<size_t>{3, 1}));
    EXPECT_EQ(baseline_holes(candidates, {1}, {0, 0, -1}, 1.0), (std::vector<size_t>{3}));
    // More holes asked for than there are candidates: all of them, in height order.
    EXPECT_EQ(baseline_holes(candidates, {9}, {0, 0, -1}, 1.0), (std::vector<size_t>{3, 1, 2, 4, 0}));
}

TEST(BaselineHoles, SkipsCandidatesTooCloseToAHoleTaken) {
    // Index 1 is 0.5 above and 1 across from the lowest (distance √1.25 < 3);
    // index 2 is 2 above and 2 across (√8 < 3); index 3 is 5 away.
    const std::vector<DrainHole> candidates{at({0, 0, 0}), at({1, 0, 0.5}), at({2, 0, 2}), at({0, 3, 4}),
                                            at({0, -10, 6})};
    EXPECT_EQ(baseline_holes(candidates, {3}, {0, 0, -1}, 3.0), (std::vector<size_t>{0, 3, 4}));
    // Index 3 is exactly 5 from index 0: "at least the spacing" keeps it.
    EXPECT_EQ(baseline_holes(candidates, {2}, {0, 0, -1}, 5.0), (std::vector<size_t>{0, 3}));
    // Just over 5 it goes, and the next spaced one (index 4, √(100 + 36) away) comes in.
    EXPECT_EQ(baseline_holes(candidates, {2}, {0, 0, -1}, 5.001), (std::vector<size_t>{0, 4}));
    // No spacing: simply the lowest.
    EXPECT_EQ(baseline_holes(candidates, {3}, {0, 0, -1}, 0.0), (std::vector<size_t>{0, 1, 2}));
}

TEST(BaselineHoles, EachCavityGetsItsOwnCount) {
    // Cavity 0 asks for one hole, cavity 1 for two, cavity 2 for none.
    const std::vector<DrainHole> candidates{at({0, 0, 2}, 0),   at({0, 0, 1}, 0),  at({50, 0, 7}, 1),
                                            at({60, 0, -3}, 1), at({70, 0, 9}, 1), at({-50, 0, -9}, 2)};
    // Lowest first across cavities: 3 (z −3), 1 (z 1), 2 (z 7).
    EXPECT_EQ(baseline_holes(candidates, {1, 2, 0}, {0, 0, -1}, 1.0), (std::vector<size_t>{3, 1, 2}));
    // A cavity id with no entry in per_cavity gets nothing either.
    EXPECT_EQ(baseline_holes(candidates, {1, 2}, {0, 0, -1}, 1.0), (std::vector<size_t>{3, 1, 2}));
    EXPECT_EQ(baseline_holes(candidates, {}, {0, 0, -1}, 1.0), std::vector<size_t>{});
}

TEST(BaselineHoles, SpacingCountsHolesOfEveryCavity) {
    // Two cavities side by side: the lowest hole of cavity 1 is 2 mm from the
    // hole taken in cavity 0, so cavity 1 gets its next lowest.
    const std::vector<DrainHole> candidates{at({0, 0, 0}, 0), at({2, 0, 0.5}, 1), at({12, 0, 1}, 1)};
    EXPECT_EQ(baseline_holes(candidates, {1, 1}, {0, 0, -1}, 4.0), (std::vector<size_t>{0, 2}));
}

TEST(BaselineHoles, LowIsAlongGravity) {
    const std::vector<DrainHole> candidates{at({-10, 0, 1}), at({0, 0, -10}), at({10, 0, 0}), at({-1, 10, 10})};
    EXPECT_EQ(baseline_holes(candidates, {4}, {0, 0, -1}, 1.0), (std::vector<size_t>{1, 2, 0, 3}));
    // Gravity +x: the lowest point is the one furthest along +x.
    EXPECT_EQ(baseline_holes(candidates, {2}, {1, 0, 0}, 1.0), (std::vector<size_t>{2, 1}));
    // Gravity +z (upside down): the highest z first.
    EXPECT_EQ(baseline_holes(candidates, {2}, {0, 0, 1}, 1.0), (std::vector<size_t>{3, 0}));
    // Only the direction counts, not the length.
    EXPECT_EQ(baseline_holes(candidates, {4}, {0, 0, -9.81}, 1.0), baseline_holes(candidates, {4}, {0, 0, -1}, 1.0));
    // Gravity along the diagonal (1, 1, 1)/√3: heights −(x + y + z)/√3 are
    // 9, 10, −10 and −19 (times 1/√3): index 3, then 2.
    EXPECT_EQ(baseline_holes(candidates, {2}, {1, 1, 1}, 1.0), (std::vector<size_t>{3, 2}));
}

TEST(BaselineHoles, NoCandidatesNoHoles) {
    EXPECT_TRUE(baseline_holes({}, {3, 3}, {0, 0, -1}, 1.0).empty());
}
