//! undercut_depth on boxes whose answers are worked out by hand: a slab
//! floating above another (the sweep fills the 3 mm gap between them, and the
//! top of the lower slab ends 2 mm inside the filled block: its distance to
//! the block's bottom), the same with the upper slab a 1 mm wide wall (the
//! fill is a 1 mm wide strip: 0.5 mm from its middle to its sides), no gap
//! across the slabs, none when the upper slab is another part or another
//! part lies in the gap, and the reach capping the depth. Measured on the
//! input the shell holds: a gap S_low smoothed away is still found, the same
//! with the input stored inside out. A part holds its shell ω deep under a
//! surface with no own surface below it: a gap over it buries that deep.
#include <gtest/gtest.h>

#include <cmath>

#include "shell_shapes.h"
#include "surface/nearest_outer_triangles.h"
#include "surface/undercut_depth.h"

namespace {

using fabvdb::Mesh;
using fabvdb::surface::Shell;
using fabvdb::surface::undercut_depth;
using fabvdb::test::make_box;
using fabvdb::test::merged;

constexpr double spacing = 0.3;  // lines 0.05 mm off the boxes' 10 mm sides
constexpr double far = 100;      // a reach past every depth here

//! Lower slab [0,10]²×[0,2] and the given upper box; triangles of the lower
//! slab come first (make_box gives 12).
Shell slabs(const Mesh& upper) { return fabvdb::test::shell_of(merged(make_box({0, 0, 0}, {10, 10, 2}), upper), 0.5); }

std::vector<int> parts(const Shell& shell, int lower, int upper, int rest = 2) {
    std::vector<int> part(shell.triangle_count(), rest);
    for (size_t t = 0; t < shell.triangle_count(); ++t) part[t] = t < 12 ? lower : t < 24 ? upper : rest;
    return part;
}

}  // namespace

TEST(UndercutDepth, FilledGapBetweenSlabsBuriesTheLowerTopTwoDeep) {
    const Shell shell = slabs(make_box({0, 0, 5}, {10, 10, 7}));
    const auto result = undercut_depth(shell, parts(shell, 0, 0), 0, {0, 0, 1}, spacing, far);
    // Filled block [0,10]²×[0,7]: z = 2 is 2 above its bottom (and 5 from its
    // sides at the middle), z = 5 is 2 below its top.
    EXPECT_NEAR(result.depth, 2.0, 1e-9);
    EXPECT_TRUE(std::abs(result.at[2] - 2.0) < 1e-9 || std::abs(result.at[2] - 5.0) < 1e-9) << result.at[2];
    // Downwards the same gap, the same depth.
    EXPECT_NEAR(undercut_depth(shell, parts(shell, 0, 0), 0, {0, 0, -1}, spacing, far).depth, 2.0, 1e-9);
}

TEST(UndercutDepth, NarrowWallAboveIsBuriedOnlyHalfItsWidth) {
    // The gap is 3 deep along z but the fill is a strip y ∈ [4.5, 5.5].
    const Shell shell = slabs(make_box({0, 4.5, 5}, {10, 5.5, 15}));
    const double depth = undercut_depth(shell, parts(shell, 0, 0), 0, {0, 0, 1}, spacing, far).depth;
    EXPECT_GT(depth, 0.5 - spacing);
    EXPECT_LT(depth, 0.5 + spacing);
}

TEST(UndercutDepth, PartHoldsItsShellUnderALowestCrossingThatLeavesIt) {
    // The lower slab's bottom belongs to part 1, so part 0's lowest crossing
    // on each line leaves it at z = 2; part 0 still holds ω = 3 under it. The
    // fill [-1, 5.5] buries z = 2 by 3 (to the shell's inner side), not by 0.
    const double omega = 3;
    const Shell shell =
        fabvdb::test::shell_of(merged(make_box({0, 0, 0}, {10, 10, 2}), make_box({0, 0, 5}, {10, 10, 5.5})), omega);
    std::vector<int> part(shell.triangle_count(), 0);
    for (size_t t = 0; t < shell.triangle_count(); ++t) {
        bool bottom = true;
        for (uint32_t v : shell.outer.triangles[t]) bottom = bottom && shell.outer.vertices[v][2] == 0;
        if (bottom) part[t] = 1;
    }
    EXPECT_NEAR(undercut_depth(shell, part, 0, {0, 0, 1}, spacing, far).depth, omega, 1e-9);
    // Turned over, the same part's highest crossing enters it: the same depth.
    EXPECT_NEAR(undercut_depth(shell, part, 0, {0, 0, -1}, spacing, far).depth, omega, 1e-9);
}

TEST(UndercutDepth, NoGapAcrossTheSlabs) {
    const Shell shell = slabs(make_box({0, 0, 5}, {10, 10, 7}));
    EXPECT_EQ(undercut_depth(shell, parts(shell, 0, 0), 0, {1, 0, 0}, spacing, far).depth, 0.0);
}

TEST(UndercutDepth, AnotherPartAboveOrBetweenMakesNoGap) {
    const Shell two = slabs(make_box({0, 0, 5}, {10, 10, 7}));
    EXPECT_EQ(undercut_depth(two, parts(two, 0, 1), 0, {0, 0, 1}, spacing, far).depth, 0.0);
    EXPECT_EQ(undercut_depth(two, parts(two, 0, 1), 1, {0, 0, 1}, spacing, far).depth, 0.0);
    // Slabs of part 0 with a slab of part 1 in the gap: the lines cross it.
    const Shell three =
        fabvdb::test::shell_of(merged(merged(make_box({0, 0, 0}, {10, 10, 2}), make_box({0, 0, 5}, {10, 10, 7})),
                                      make_box({0, 0, 3}, {10, 10, 4})),
                               0.5);
    EXPECT_EQ(undercut_depth(three, parts(three, 0, 0, 1), 0, {0, 0, 1}, spacing, far).depth, 0.0);
}

TEST(UndercutDepth, ReachCapsTheDepth) {
    const Shell shell = slabs(make_box({0, 0, 5}, {10, 10, 7}));
    EXPECT_NEAR(undercut_depth(shell, parts(shell, 0, 0), 0, {0, 0, 1}, spacing, 1.0).depth, 1.0, 1e-9);
}

TEST(UndercutDepth, MeasuredOnTheInputWhereSLowSmoothedTheGapAway) {
    // S_low a solid block; the input it was made from two slabs with a 3 mm gap.
    Shell shell = fabvdb::test::shell_of(make_box({0, 0, 0}, {10, 10, 7}), 0.5);
    const std::vector<int> one_part(shell.triangle_count(), 0);
    EXPECT_EQ(undercut_depth(shell, one_part, 0, {0, 0, 1}, spacing, far).depth, 0.0);
    for (bool inside_out : {false, true}) {
        shell.input = merged(make_box({0, 0, 0}, {10, 10, 2}), make_box({0, 0, 5}, {10, 10, 7}));
        if (inside_out)
            for (auto& t : shell.input.triangles) std::swap(t[1], t[2]);
        shell.input_nearest = fabvdb::surface::nearest_outer_triangles(shell.input, shell.outer);
        EXPECT_NEAR(undercut_depth(shell, one_part, 0, {0, 0, 1}, spacing, far).depth, 2.0, 1e-9) << inside_out;
        EXPECT_EQ(undercut_depth(shell, one_part, 0, {1, 0, 0}, spacing, far).depth, 0.0) << inside_out;
    }
}
