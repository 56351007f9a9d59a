// The low-resolution surface: a level set of three balls, radius 10, 3 and
// 0.6 mm, remeshed to about 500 triangles (edge ≈ 2.6 mm): the two larger
// balls come back as closed outward shells (the small one coarse: its volume
// within 30%), the
// smallest (under (edge / 2)³) is dropped as a crumb. A ball with a void
// inside comes back as its outer surface alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <openvdb/tools/Composite.h>
#include <openvdb/tools/LevelSetSphere.h>

#include "volume/low_res_surface.h"
#include "volume/mesh_shells.h"

namespace {

TEST(LowResSurface, CrumbsAreDroppedAndBallsKept) {
    openvdb::initialize();
    const float voxel = 0.25f;
    auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(10.0f, openvdb::Vec3f(0, 0, 0), voxel);
    auto medium = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(3.0f, openvdb::Vec3f(20, 0, 0), voxel);
    auto crumb = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(0.6f, openvdb::Vec3f(0, 20, 0), voxel);
    openvdb::tools::csgUnion(*grid, *medium);
    openvdb::tools::csgUnion(*grid, *crumb);
    fabvdb::Progress progress;
    const fabvdb::Mesh surface = fabvdb::volume::low_res_surface(*grid, 500, progress);
    std::vector<fabvdb::volume::MeshShell> shells = fabvdb::volume::split_shells(surface);
    ASSERT_EQ(shells.size(), 2u);
    std::sort(shells.begin(), shells.end(), [](const auto& a, const auto& b) { return a.volume > b.volume; });
    EXPECT_NEAR(shells[0].volume, 4.0 / 3.0 * M_PI * 1000.0, 0.03 * 4.0 / 3.0 * M_PI * 1000.0);
    EXPECT_NEAR(shells[1].volume, 4.0 / 3.0 * M_PI * 27.0, 0.3 * 4.0 / 3.0 * M_PI * 27.0);
}

TEST(LowResSurface, VoidsAreFilled) {
    openvdb::initialize();
    const float voxel = 0.25f;
    auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(10.0f, openvdb::Vec3f(0, 0, 0), voxel);
    auto inner = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(5.0f, openvdb::Vec3f(1, 0, 0), voxel);
    openvdb::tools::csgDifference(*grid, *inner);
    fabvdb::Progress progress;
    const fabvdb::Mesh surface = fabvdb::volume::low_res_surface(*grid, 500, progress);
    const std::vector<fabvdb::volume::MeshShell> shells = fabvdb::volume::split_shells(surface);
    ASSERT_EQ(shells.size(), 1u);
    EXPECT_NEAR(shells[0].volume, 4.0 / 3.0 * M_PI * 1000.0, 0.03 * 4.0 / 3.0 * M_PI * 1000.0);
}

}  // namespace
