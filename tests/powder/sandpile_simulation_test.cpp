// The reference sand-pile simulation on a hollow sphere: powder is conserved
// without holes in every turn; a hole at the bottom drains; no hole on top
// drains while the part stays upright; a shaft drains through an outlet in
// its side down to the angle of repose; cancellation.
#include <gtest/gtest.h>

#include <cmath>

#include "cavity_shapes.h"
#include "core/error.h"
#include "powder/sandpile_simulation.h"

namespace {

TEST(Sandpile, ClosedCavityKeepsAllItsPowderAndFillsTheCavity) {
    const auto part = fabvdb::test::hollow_sphere({0, 0, 0}, 12.0, 2.0, 0.5);
    fabvdb::powder::SandpileOptions options;
    options.routine = {{0, 0, -1}, {1, 0, 0}, {0.3, -0.5, 0.8}};
    fabvdb::Progress progress;
    const auto result = fabvdb::powder::simulate_sandpile(*part.shell, {}, options, progress);
    const double cavity = 4.0 / 3.0 * M_PI * 10.0 * 10.0 * 10.0;
    EXPECT_NEAR(result.initial_volume, cavity, 0.05 * cavity);
    ASSERT_EQ(result.residual_after_turn.size(), 3u);
    for (double left : result.residual_after_turn) EXPECT_DOUBLE_EQ(left, result.initial_volume);
}

TEST(Sandpile, BottomHoleDrainsTopHoleDoesNotWhileUpright) {
    const auto part = fabvdb::test::hollow_sphere({0, 0, 0}, 12.0, 2.0, 0.5);
    fabvdb::powder::SandpileOptions options;
    options.routine = {{0, 0, -1}};
    fabvdb::Progress progress;
    const auto bottom =
        fabvdb::powder::simulate_sandpile(*part.shell, {{{0, 0, -10}, {0, 0, -1}, 4.0, 6.0}}, options, progress);
    const auto top =
        fabvdb::powder::simulate_sandpile(*part.shell, {{{0, 0, 10}, {0, 0, 1}, 4.0, 6.0}}, options, progress);
    EXPECT_LT(bottom.residual_fraction(), 0.5);
    EXPECT_GT(top.residual_fraction(), 0.98);
    // Turned over, the top hole is at the bottom and drains too.
    options.routine = {{0, 0, -1}, {0, 0, 1}};
    const auto turned =
        fabvdb::powder::simulate_sandpile(*part.shell, {{{0, 0, 10}, {0, 0, 1}, 4.0, 6.0}}, options, progress);
    EXPECT_LT(turned.residual_fraction(), 0.5);
}

// A turn that moves nothing must not change what a later turn drains: the
// cavity is full and its only hole is on top while the part stands tilted,
// then the part is turned over and the hole drains. Voxelised in a tilted
// frame the full cavity holds a few more grains than cells in the upright
// one; those must wait for room, not stay inside for good.
TEST(Sandpile, GrainsWithoutACellAfterATurnWaitForRoom) {
    const auto part = fabvdb::test::hollow_sphere({0, 0, 0}, 12.0, 2.0, 0.5);
    const std::vector<fabvdb::powder::SandpileHole> top = {{{0, 0, 10}, {0, 0, 1}, 4.0, 6.0}};
    fabvdb::powder::SandpileOptions options;
    fabvdb::Progress progress;
    options.routine = {{0, 0, 1}};
    const auto direct = fabvdb::powder::simulate_sandpile(*part.shell, top, options, progress);
    options.routine = {{0.25, -0.35, -0.9}, {0, 0, 1}};
    const auto turned = fabvdb::powder::simulate_sandpile(*part.shell, top, options, progress);
    ASSERT_EQ(turned.residual_after_turn.size(), 2u);
    EXPECT_DOUBLE_EQ(turned.residual_after_turn[0], turned.initial_volume);  // the hole is on top
    EXPECT_LT(direct.residual_fraction(), 0.5);
    EXPECT_NEAR(turned.residual_volume, direct.residual_volume, 0.01 * direct.initial_volume);
}

// A shaft 6 x 6 x 24 mm, full, with an outlet at the foot of a side wall
// drilled 45° down: the column above the outlet must not stand on its face.
// What stays is what lies under the repose slope rising from the outlet's
// lip on the floor (|y| <= 1.41 mm where the tilted drill meets the floor):
// 78 mm³, 9.1% of the shaft by integration.
TEST(Sandpile, ShaftDrainsThroughASideOutletDownToTheRepose) {
    openvdb::initialize();
    const double voxel = 0.25;
    auto cavity = fabvdb::test::box({-3, -3, 0}, {3, 3, 24}, voxel);
    auto part = fabvdb::test::box({-5, -5, -2}, {5, 5, 26}, voxel);
    const auto shaft = fabvdb::test::finish(part, cavity);
    fabvdb::powder::SandpileOptions options;
    options.cell_size = 0.5;
    options.routine = {{0, 0, -1}};
    fabvdb::Progress progress;
    const double diagonal = std::sqrt(0.5);
    const auto result = fabvdb::powder::simulate_sandpile(
        *shaft.shell, {{{-3, 0, 2}, {-diagonal, 0, -diagonal}, 4.0, 8.0}}, options, progress);
    EXPECT_NEAR(result.initial_volume, 864.0, 0.05 * 864.0);
    EXPECT_NEAR(result.residual_fraction(), 0.091, 0.03);
}

TEST(Sandpile, CancelledSimulationThrowsCancelled) {
    const auto part = fabvdb::test::hollow_sphere({0, 0, 0}, 12.0, 2.0, 0.5);
    std::atomic<bool> cancel{true};
    fabvdb::Progress progress(nullptr, nullptr, &cancel);
    fabvdb::powder::SandpileOptions options;
    try {
        fabvdb::powder::simulate_sandpile(*part.shell, {}, options, progress);
        FAIL() << "a cancelled simulation returned";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
