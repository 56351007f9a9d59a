// Dropping small solid pieces of a level set: of two balls the small one goes
// (its centre turns outside, the big one's stays inside), 0 only counts, the
// grid is replaced only when something goes, it may end up empty, an empty
// grid has no shell, and a cancelled call leaves the grid as it was.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include <openvdb/tools/Composite.h>
#include <openvdb/tools/LevelSetSphere.h>

#include "core/error.h"
#include "core/progress.h"
#include "volume/drop_small_shells.h"

namespace {

using fabvdb::volume::drop_small_shells;

constexpr double kVoxel = 0.25;

// Balls of radius 4 at the origin (268 mm³) and 1.5 at (12, 0, 0) (14.1 mm³).
openvdb::FloatGrid::Ptr two_balls() {
    openvdb::initialize();
    auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(4.0f, openvdb::Vec3f(0, 0, 0), float(kVoxel));
    auto small = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(1.5f, openvdb::Vec3f(12, 0, 0), float(kVoxel));
    openvdb::tools::csgUnion(*grid, *small);
    grid->setName("solid");
    return grid;
}

float value_at(const openvdb::FloatGrid& grid, const openvdb::Vec3d& world) {
    return grid.tree().getValue(openvdb::Coord::round(grid.transform().worldToIndex(world)));
}

TEST(DropSmallShells, SmallBallGoesBigBallStays) {
    openvdb::FloatGrid::Ptr grid = two_balls();
    const openvdb::FloatGrid::ConstPtr before = grid;
    ASSERT_LT(value_at(*grid, {12, 0, 0}), 0.0f);
    fabvdb::Progress progress;
    // Between the two balls' volumes (4/3 π r³: 268.1 and 14.1).
    const auto counts = drop_small_shells(grid, 100.0, progress);
    EXPECT_EQ(counts.kept, 1u);
    EXPECT_EQ(counts.dropped, 1u);
    ASSERT_TRUE(grid);
    EXPECT_NE(grid.get(), before.get());
    EXPECT_LT(value_at(*grid, {0, 0, 0}), 0.0f);
    EXPECT_LT(value_at(*grid, {3.5, 0, 0}), 0.0f);
    EXPECT_GT(value_at(*grid, {12, 0, 0}), 0.0f);
    EXPECT_GT(value_at(*grid, {12, 1, 0}), 0.0f);
    // Nothing of the small ball's band is left.
    for (auto it = grid->cbeginValueOn(); it; ++it)
        EXPECT_LT(grid->transform().indexToWorld(it.getCoord()).length(), 4.0 + 4 * kVoxel);
    EXPECT_EQ(grid->getGridClass(), openvdb::GRID_LEVEL_SET);
    EXPECT_EQ(grid->getName(), "solid");
    EXPECT_EQ(grid->background(), before->background());
    EXPECT_EQ(grid->transform(), before->transform());
    // The big ball's surface is still where it was: radius 4 along x.
    EXPECT_NEAR(value_at(*grid, {4, 0, 0}), 0.0f, kVoxel);
}

TEST(DropSmallShells, ThresholdBelowBothKeepsTheGrid) {
    openvdb::FloatGrid::Ptr grid = two_balls();
    const openvdb::FloatGrid::Ptr before = grid;
    const auto voxels = grid->activeVoxelCount();
    fabvdb::Progress progress;
    const auto counts = drop_small_shells(grid, 10.0, progress);
    EXPECT_EQ(counts.kept, 2u);
    EXPECT_EQ(counts.dropped, 0u);
    EXPECT_EQ(grid, before);  // not replaced
    EXPECT_EQ(grid->activeVoxelCount(), voxels);
}

TEST(DropSmallShells, ZeroOnlyCounts) {
    openvdb::FloatGrid::Ptr grid = two_balls();
    const openvdb::FloatGrid::Ptr before = grid;
    const auto voxels = grid->activeVoxelCount();
    fabvdb::Progress progress;
    const auto counts = drop_small_shells(grid, 0.0, progress);
    EXPECT_EQ(counts.kept, 2u);
    EXPECT_EQ(counts.dropped, 0u);
    EXPECT_EQ(grid, before);
    EXPECT_EQ(grid->activeVoxelCount(), voxels);
}

TEST(DropSmallShells, EverythingCanGo) {
    openvdb::FloatGrid::Ptr grid = two_balls();
    fabvdb::Progress progress;
    const auto counts = drop_small_shells(grid, 1000.0, progress);
    EXPECT_EQ(counts.kept, 0u);
    EXPECT_EQ(counts.dropped, 2u);
    ASSERT_TRUE(grid);
    EXPECT_EQ(grid->activeVoxelCount(), 0u);
    EXPECT_GT(value_at(*grid, {0, 0, 0}), 0.0f);
    EXPECT_GT(value_at(*grid, {12, 0, 0}), 0.0f);
    EXPECT_EQ(grid->getGridClass(), openvdb::GRID_LEVEL_SET);
}

TEST(DropSmallShells, AnEmptyGridHasNoShells) {
    openvdb::FloatGrid::Ptr grid = openvdb::createLevelSet<openvdb::FloatGrid>(0.5);
    fabvdb::Progress progress;
    const auto counts = drop_small_shells(grid, 1.0, progress);
    EXPECT_EQ(counts.kept, 0u);
    EXPECT_EQ(counts.dropped, 0u);
    EXPECT_EQ(grid->activeVoxelCount(), 0u);
}

TEST(DropSmallShells, CancelledCallLeavesTheGrid) {
    openvdb::FloatGrid::Ptr grid = two_balls();
    const openvdb::FloatGrid::Ptr before = grid;
    const auto voxels = grid->activeVoxelCount();
    std::atomic<bool> cancel{true};
    fabvdb::Progress progress(nullptr, nullptr, &cancel);
    try {
        drop_small_shells(grid, 100.0, progress);
        FAIL() << "not cancelled";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_CANCELLED);
    }
    EXPECT_EQ(grid, before);
    EXPECT_EQ(grid->activeVoxelCount(), voxels);
    EXPECT_LT(value_at(*grid, {12, 0, 0}), 0.0f);
}

TEST(DropSmallShells, CancelFromTheCallbackDuringTheWork) {
    // The callback cancels at its first report after the stage starts.
    openvdb::FloatGrid::Ptr grid = two_balls();
    const openvdb::FloatGrid::Ptr before = grid;
    int calls = 0;
    auto cancel_after_start = [](void* user, const char*, double fraction) {
        ++*static_cast<int*>(user);
        return fraction > 0.0 ? 1 : 0;
    };
    fabvdb::Progress progress(cancel_after_start, &calls, nullptr);
    try {
        drop_small_shells(grid, 100.0, progress);
        FAIL() << "not cancelled";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_CANCELLED);
    }
    EXPECT_GE(calls, 2);
    EXPECT_EQ(grid, before);
    EXPECT_LT(value_at(*grid, {12, 0, 0}), 0.0f);
}

}  // namespace
