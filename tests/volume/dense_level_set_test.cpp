// A level set from a dense block: every sample under the background in
// magnitude is copied exactly as an active voxel (sign and value), samples at
// or beyond it become inactive ±background, the transform and level-set class
// are set, and a cancelled call throws CANCELLED.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstddef>

#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>

#include "core/error.h"
#include "core/progress.h"
#include "volume/dense_level_set.h"

namespace {

using openvdb::Coord;
using openvdb::CoordBBox;
using openvdb::tools::Dense;

//! Samples of a sphere's signed distance (radius `r` voxels about `c`, times `voxel`).
Dense<float> sphere_block(const CoordBBox& box, const openvdb::Vec3d& c, double r, double voxel) {
    Dense<float> block(box);
    for (int i = box.min().x(); i <= box.max().x(); ++i)
        for (int j = box.min().y(); j <= box.max().y(); ++j)
            for (int k = box.min().z(); k <= box.max().z(); ++k)
                block.setValue(Coord(i, j, k), float(((openvdb::Vec3d(i, j, k) - c).length() - r) * voxel));
    return block;
}

TEST(DenseLevelSet, NarrowBandSamplesAreCopiedAndTheRestIsOffAtTheBackground) {
    openvdb::initialize();
    const CoordBBox box(Coord(-10, -9, -8), Coord(10, 11, 9));
    const double voxel = 0.5;
    const float background = 1.5f;  // 3 voxels
    const Dense<float> block = sphere_block(box, {0.3, 0.6, -0.2}, 6.0, voxel);
    const auto transform = openvdb::math::Transform::createLinearTransform(voxel);
    transform->postTranslate(openvdb::Vec3d(1, 2, 3));
    fabvdb::Progress progress;
    const auto grid = fabvdb::volume::dense_level_set(block, *transform, background, progress);
    ASSERT_TRUE(grid);
    EXPECT_EQ(grid->getGridClass(), openvdb::GRID_LEVEL_SET);
    EXPECT_EQ(grid->background(), background);
    EXPECT_EQ(grid->transform(), *transform);
    size_t band = 0, inside = 0, outside = 0;
    auto accessor = grid->getConstAccessor();
    for (auto ijk = box.begin(); ijk; ++ijk) {
        const float sample = block.getValue(*ijk);
        const bool on = accessor.isValueOn(*ijk);
        const float value = accessor.getValue(*ijk);
        if (std::abs(sample) < background) {
            ++band;
            EXPECT_TRUE(on) << *ijk;
            EXPECT_EQ(value, sample) << *ijk;
        } else {
            EXPECT_FALSE(on) << *ijk;
            EXPECT_EQ(value, sample < 0 ? -background : background) << *ijk;
            ++(sample < 0 ? inside : outside);
        }
    }
    EXPECT_EQ(grid->activeVoxelCount(), openvdb::Index64(band));
    // The sphere is well inside the block: there are deep samples on both sides.
    EXPECT_GT(band, 1000u);
    EXPECT_GT(inside, 100u);
    EXPECT_GT(outside, 1000u);
    // Beyond the block: outside.
    EXPECT_EQ(accessor.getValue(Coord(40, 0, 0)), background);
    EXPECT_FALSE(accessor.isValueOn(Coord(40, 0, 0)));
}

TEST(DenseLevelSet, ExactlyTheBackgroundIsOffAndZeroIsOn) {
    openvdb::initialize();
    Dense<float> block(CoordBBox(Coord(0, 0, 0), Coord(1, 0, 0)));
    block.setValue(Coord(0, 0, 0), 2.0f);
    block.setValue(Coord(1, 0, 0), 0.0f);
    fabvdb::Progress progress;
    auto grid = fabvdb::volume::dense_level_set(block, openvdb::math::Transform(), 2.0f, progress);
    EXPECT_EQ(grid->activeVoxelCount(), 1u);
    EXPECT_TRUE(grid->tree().isValueOn(Coord(1, 0, 0)));
    EXPECT_EQ(grid->tree().getValue(Coord(1, 0, 0)), 0.0f);
    block.setValue(Coord(0, 0, 0), -2.0f);
    block.setValue(Coord(1, 0, 0), -1.999f);
    grid = fabvdb::volume::dense_level_set(block, openvdb::math::Transform(), 2.0f, progress);
    EXPECT_EQ(grid->activeVoxelCount(), 1u);
    EXPECT_FALSE(grid->tree().isValueOn(Coord(0, 0, 0)));
    EXPECT_EQ(grid->tree().getValue(Coord(0, 0, 0)), -2.0f);
    EXPECT_EQ(grid->tree().getValue(Coord(1, 0, 0)), -1.999f);
}

TEST(DenseLevelSet, ABlockAllFarFromTheSurfaceHasNoActiveVoxels) {
    openvdb::initialize();
    const CoordBBox box(Coord(0, 0, 0), Coord(15, 15, 15));
    Dense<float> block(box, -7.0f);  // all deep inside
    fabvdb::Progress progress;
    auto grid = fabvdb::volume::dense_level_set(block, openvdb::math::Transform(), 1.0f, progress);
    EXPECT_EQ(grid->activeVoxelCount(), 0u);
    for (auto ijk = box.begin(); ijk; ++ijk) ASSERT_EQ(grid->tree().getValue(*ijk), -1.0f) << *ijk;
    block.fill(123.0f);  // all far outside
    grid = fabvdb::volume::dense_level_set(block, openvdb::math::Transform(), 1.0f, progress);
    EXPECT_EQ(grid->activeVoxelCount(), 0u);
    EXPECT_EQ(grid->tree().getValue(Coord(7, 7, 7)), 1.0f);
    EXPECT_EQ(grid->getGridClass(), openvdb::GRID_LEVEL_SET);
}

TEST(DenseLevelSet, CancelledCallThrowsCancelled) {
    openvdb::initialize();
    const Dense<float> block = sphere_block(CoordBBox(Coord(-8), Coord(8)), {0, 0, 0}, 5.0, 1.0);
    std::atomic<bool> cancel{true};
    fabvdb::Progress progress(nullptr, nullptr, &cancel);
    try {
        fabvdb::volume::dense_level_set(block, openvdb::math::Transform(), 3.0f, progress);
        FAIL() << "not cancelled";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
