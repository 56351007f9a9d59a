// Detail restoration: a fine sphere (the full-resolution input) decomposed as
// two coarse hemispherical shells (the low-resolution parts) gets its outer
// surface back: each restored part's outer surface lies on the fine sphere,
// the parts do not overlap, and together they fill the input's shell of
// thickness ω. Measured on extracted meshes by the test support.
#include <gtest/gtest.h>

#include <cmath>

#include <openvdb/tools/MeshToVolume.h>

#include "core/error.h"
#include "support/mold_shapes.h"
#include "support/ray_cast.h"
#include "support/shapes.h"
#include "volume/detail_restoration.h"
#include "volume/extract_mesh.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;

TEST(DetailRestoration, CoarseHemispheresGetTheFineSphereBack) {
    openvdb::initialize();
    const double radius = 15.0, omega = 3.0, voxel = 0.4;
    const Mesh fine = fabvdb::test::make_sphere({0, 0, 0}, radius, 4);
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    for (const Vec3& p : fine.vertices) points.emplace_back(float(p[0] / voxel), float(p[1] / voxel), float(p[2] / voxel));
    for (const auto& t : fine.triangles) triangles.emplace_back(t[0], t[1], t[2]);
    auto transform = openvdb::math::Transform::createLinearTransform(voxel);
    openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3s, openvdb::Vec3I> adapter(points, triangles);
    auto input = openvdb::tools::meshToVolume<openvdb::FloatGrid>(adapter, *transform, 10.0f, 10.0f);
    input->setGridClass(openvdb::GRID_LEVEL_SET);

    // Coarse parts: 8 segments around, 3 rings: the outer surface sits up to
    // ~1 mm inside the fine sphere.
    const Mesh upper = fabvdb::test::make_dome_shell(radius, radius - omega, 3, 8);
    Mesh lower = upper;
    for (Vec3& p : lower.vertices) p[2] = -p[2];
    lower = fabvdb::test::flipped(lower);

    fabvdb::Progress progress;
    fabvdb::volume::DetailRestorationOptions options;
    options.shell_thickness = omega;
    options.reach = 2.0;
    const auto restored = fabvdb::volume::restore_part_details(*input, {upper, lower}, options, progress);
    ASSERT_EQ(restored.size(), 2u);

    std::vector<Mesh> parts;
    for (const auto& grid : restored) parts.push_back(fabvdb::volume::extract_mesh(*grid, 0.0, progress));
    const double shell_volume = 4.0 / 3.0 * M_PI * (std::pow(radius, 3) - std::pow(radius - omega, 3));
    double total = 0;
    for (size_t i = 0; i < parts.size(); ++i) {
        ASSERT_TRUE(fabvdb::test::closed_two_manifold(parts[i])) << i;
        total += fabvdb::test::mesh_volume(parts[i]);
        // Its outer surface is the fine sphere: the farthest vertex from the
        // centre is on it, none beyond.
        double farthest = 0;
        for (const Vec3& p : parts[i].vertices) farthest = std::max(farthest, std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
        EXPECT_NEAR(farthest, radius, voxel) << i;
        // Just under the fine sphere in the middle of a coarse facet (which
        // lies ~1 mm further in) is inside the restored part.
        fabvdb::test::LineCaster caster(parts[i], {0.013, 0.007, 1.0});
        const double r = radius - 0.5 * voxel, elevation = M_PI / 4, azimuth = M_PI / 8;
        const double z = (i == 0 ? 1 : -1) * r * std::sin(elevation);
        EXPECT_TRUE(caster.inside({r * std::cos(elevation) * std::cos(azimuth), r * std::cos(elevation) * std::sin(azimuth), z}))
            << i;
    }
    EXPECT_NEAR(total, shell_volume, 0.03 * shell_volume);
    const double common = fabvdb::test::sampled_common_volume({&parts[0], &parts[1]}, {-16, -16, -16}, {16, 16, 16}, 64);
    EXPECT_LT(common, 0.005 * shell_volume);
}

TEST(DetailRestoration, RefusesAPartAboutAVoxelThin) {
    openvdb::initialize();
    // A 40 x 40 x 0.6 mm plate at a 0.4 mm voxel, as two parts 0.3 mm thick
    // (under a voxel) one above the other: restored, each would keep almost
    // nothing. As one part 0.6 mm thick it is restored.
    const double voxel = 0.4;
    const Mesh plate = fabvdb::test::make_box({-20, -20, -0.3}, {20, 20, 0.3});
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    for (const Vec3& p : plate.vertices) points.emplace_back(float(p[0] / voxel), float(p[1] / voxel), float(p[2] / voxel));
    for (const auto& t : plate.triangles) triangles.emplace_back(t[0], t[1], t[2]);
    auto transform = openvdb::math::Transform::createLinearTransform(voxel);
    openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3s, openvdb::Vec3I> adapter(points, triangles);
    auto input = openvdb::tools::meshToVolume<openvdb::FloatGrid>(adapter, *transform, 6.0f, 6.0f);
    input->setGridClass(openvdb::GRID_LEVEL_SET);

    fabvdb::Progress progress;
    fabvdb::volume::DetailRestorationOptions options;
    options.shell_thickness = 1.0;
    options.reach = 1.0;
    options.input_name = "plate.stl";
    const Mesh lower = fabvdb::test::make_box({-20, -20, -0.3}, {20, 20, 0.0});
    const Mesh upper = fabvdb::test::make_box({-20, -20, 0.0}, {20, 20, 0.3});
    try {
        fabvdb::volume::restore_part_details(*input, {lower, upper}, options, progress);
        ADD_FAILURE() << "two sub-voxel parts were restored";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT);
        EXPECT_NE(std::string(e.what()).find("plate.stl: part 0"), std::string::npos) << e.what();
    }
    const auto whole = fabvdb::volume::restore_part_details(*input, {plate}, options, progress);
    ASSERT_EQ(whole.size(), 1u);
    const Mesh restored = fabvdb::volume::extract_mesh(*whole[0], 0.0, progress);
    EXPECT_NEAR(fabvdb::test::mesh_volume(restored), 40 * 40 * 0.6, 0.1 * 40 * 40 * 0.6);
}

TEST(DetailRestoration, RefusesBadOptions) {
    openvdb::FloatGrid input;
    input.setGridClass(openvdb::GRID_LEVEL_SET);
    fabvdb::Progress progress;
    fabvdb::volume::DetailRestorationOptions options;
    EXPECT_THROW(fabvdb::volume::restore_part_details(input, {}, options, progress), fabvdb::Error);
}

}  // namespace
