// The volume inside a level set: a sphere of radius r measures 4/3·π·r³ (to
// the voxel's resolution), the same in a rotated frame of voxels so small
// that OpenVDB's own measure refuses that frame, and an empty grid is 0.
#include <gtest/gtest.h>

#include <cmath>

#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>

#include "volume/level_set_volume.h"

namespace {

using fabvdb::volume::level_set_volume;

TEST(LevelSetVolume, ASphereMeasuresFourThirdsPiRCubed) {
    openvdb::initialize();
    const double r = 2.0;
    const auto sphere = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(float(r), openvdb::Vec3f(1, 2, 3), 0.05f);
    EXPECT_NEAR(level_set_volume(*sphere), 4.0 / 3.0 * M_PI * r * r * r, 0.01 * 4.0 / 3.0 * M_PI * r * r * r);
}

TEST(LevelSetVolume, TinyVoxelsInARotatedFrameMeasureTheSame) {
    openvdb::initialize();
    // A sphere of 0.1 mm radius in voxels of 2.5 µm, its frame rotated by
    // 0.4 rad about z: a frame OpenVDB's own measure refuses as non-uniform.
    const double r = 0.1, v = 2.5e-3, c = std::cos(0.4), s = std::sin(0.4);
    auto sphere = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(float(r), openvdb::Vec3f(0, 0, 0), float(v));
    sphere->setTransform(openvdb::math::Transform::createLinearTransform(
        openvdb::math::Mat4d(v * c, v * s, 0.0, 0.0, -v * s, v * c, 0.0, 0.0, 0.0, 0.0, v, 0.0, 0.0, 0.0, 0.0, 1.0)));
    ASSERT_FALSE(sphere->hasUniformVoxels());
    EXPECT_NEAR(level_set_volume(*sphere), 4.0 / 3.0 * M_PI * r * r * r, 0.01 * 4.0 / 3.0 * M_PI * r * r * r);
}

TEST(LevelSetVolume, AnEmptyGridIsZero) {
    openvdb::initialize();
    EXPECT_EQ(level_set_volume(*openvdb::createLevelSet<openvdb::FloatGrid>(0.1)), 0.0);
}

}  // namespace
