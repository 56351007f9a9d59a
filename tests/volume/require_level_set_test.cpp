// The level-set precondition: a level set with cubic voxels passes (at any
// voxel size, in a rotated frame, empty or not); a fog volume, an unknown grid class or
// non-cubic voxels is Error(INVALID_ARGUMENT) naming what was checked.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>

#include "core/error.h"
#include "volume/require_level_set.h"

namespace {

using fabvdb::volume::require_level_set;

void expect_rejected(const openvdb::FloatGrid& grid, const char* what) {
    try {
        require_level_set(grid, what);
        ADD_FAILURE() << "accepted";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_INVALID_ARGUMENT);
        EXPECT_EQ(std::string(error.what()), std::string(what) + " is not a level set with uniform voxels");
    }
}

TEST(RequireLevelSet, LevelSetsPass) {
    openvdb::initialize();
    const auto sphere = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(2.0f, openvdb::Vec3f(0, 0, 0), 0.25f);
    ASSERT_EQ(sphere->getGridClass(), openvdb::GRID_LEVEL_SET);
    EXPECT_NO_THROW(require_level_set(*sphere, "the part"));
    const auto coarse = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(10.0f, openvdb::Vec3f(1, 2, 3), 1.5f);
    EXPECT_NO_THROW(require_level_set(*coarse, "the part"));
    // An empty level set is still a level set.
    const auto empty = openvdb::createLevelSet<openvdb::FloatGrid>(0.1);
    EXPECT_NO_THROW(require_level_set(*empty, "a keep-out solid"));
}

TEST(RequireLevelSet, OtherGridClassesAreRejected) {
    openvdb::initialize();
    auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(2.0f, openvdb::Vec3f(0, 0, 0), 0.25f);
    grid->setGridClass(openvdb::GRID_FOG_VOLUME);
    expect_rejected(*grid, "the part");
    grid->setGridClass(openvdb::GRID_UNKNOWN);
    expect_rejected(*grid, "a keep-out solid");
    grid->setGridClass(openvdb::GRID_STAGGERED);
    expect_rejected(*grid, "x");
    // A plain new grid has no class.
    expect_rejected(*openvdb::FloatGrid::create(), "the part");
}

TEST(RequireLevelSet, NonCubicVoxelsAreRejected) {
    openvdb::initialize();
    auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(2.0f, openvdb::Vec3f(0, 0, 0), 0.25f);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(
        openvdb::math::Mat4d(0.25, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.25, 0.0, 0.0, 0.0, 0.0, 1.0)));
    ASSERT_EQ(grid->getGridClass(), openvdb::GRID_LEVEL_SET);
    expect_rejected(*grid, "the part");
    // Cubic voxels at another size and offset pass.
    auto moved = openvdb::math::Transform::createLinearTransform(0.7);
    moved->postTranslate(openvdb::Vec3d(3, -2, 1));
    grid->setTransform(moved);
    EXPECT_NO_THROW(require_level_set(*grid, "the part"));
}

// Cubic voxels of 2.5 µm in a frame rotated by 0.4 rad (a sweep's aligned
// grid for a part a millimetre across): OpenVDB's own test calls them
// non-uniform; they are cubic.
TEST(RequireLevelSet, TinyVoxelsInARotatedFramePass) {
    openvdb::initialize();
    auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(0.1f, openvdb::Vec3f(0, 0, 0), 2.5e-3f);
    const double c = std::cos(0.4), s = std::sin(0.4), v = 2.5e-3;
    grid->setTransform(openvdb::math::Transform::createLinearTransform(
        openvdb::math::Mat4d(v * c, v * s, 0.0, 0.0, -v * s, v * c, 0.0, 0.0, 0.0, 0.0, v, 0.0, 0.0, 0.0, 0.0, 1.0)));
    ASSERT_FALSE(grid->hasUniformVoxels());
    EXPECT_NO_THROW(require_level_set(*grid, "the part"));
    // The same frame stretched by 1% along one axis is not cubic.
    grid->setTransform(openvdb::math::Transform::createLinearTransform(openvdb::math::Mat4d(
        v * c, v * s, 0.0, 0.0, -v * s, v * c, 0.0, 0.0, 0.0, 0.0, 1.01 * v, 0.0, 0.0, 0.0, 0.0, 1.0)));
    expect_rejected(*grid, "the part");
}

}  // namespace
