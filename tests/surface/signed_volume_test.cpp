// Signed volume per component: boxes and a tetrahedron give their volumes by
// hand (negative when inside out), interleaved components stay apart, a box
// far from the origin keeps its volume, and empty components give zero.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "support/shapes.h"
#include "surface/signed_volume.h"

namespace {

using fabvdb::Mesh;
using fabvdb::test::flipped;
using fabvdb::test::make_box;
using fabvdb::test::merged;

TEST(SignedVolume, OutwardAndInwardBoxes) {
    // 2 x 3 x 4 = 24 facing out, 1 x 1 x 1 = 1 facing in.
    const Mesh mesh = merged(make_box({0, 0, 0}, {2, 3, 4}), flipped(make_box({5, 5, 5}, {6, 6, 6})));
    std::vector<uint32_t> component(24, 0);
    for (size_t t = 12; t < 24; ++t) component[t] = 1;
    const std::vector<double> volumes = fabvdb::surface::component_signed_volumes(mesh, component, 2);
    ASSERT_EQ(volumes.size(), 2u);
    EXPECT_NEAR(volumes[0], 24.0, 1e-12);
    EXPECT_NEAR(volumes[1], -1.0, 1e-12);
}

TEST(SignedVolume, TetrahedronIsASixth) {
    Mesh tet;
    tet.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    tet.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};  // normals point away from the inside
    const auto volumes = fabvdb::surface::component_signed_volumes(tet, {0, 0, 0, 0}, 1);
    ASSERT_EQ(volumes.size(), 1u);
    EXPECT_NEAR(volumes[0], 1.0 / 6.0, 1e-15);
}

TEST(SignedVolume, InterleavedComponentsAndUnusedOnes) {
    // Triangles of a 1 x 2 x 3 box (component 2) and a 4 x 1 x 1 box
    // (component 0) alternate; component 1 has no triangle.
    const Mesh a = make_box({0, 0, 0}, {1, 2, 3});
    const Mesh b = make_box({10, 0, 0}, {14, 1, 1});
    Mesh mesh = merged(a, b);
    Mesh shuffled;
    shuffled.vertices = mesh.vertices;
    std::vector<uint32_t> component;
    for (size_t t = 0; t < 12; ++t) {
        shuffled.triangles.push_back(mesh.triangles[t]);
        component.push_back(2);
        shuffled.triangles.push_back(mesh.triangles[12 + t]);
        component.push_back(0);
    }
    const auto volumes = fabvdb::surface::component_signed_volumes(shuffled, component, 4);
    ASSERT_EQ(volumes.size(), 4u);
    EXPECT_NEAR(volumes[0], 4.0, 1e-12);
    EXPECT_EQ(volumes[1], 0.0);
    EXPECT_NEAR(volumes[2], 6.0, 1e-12);
    EXPECT_EQ(volumes[3], 0.0);
}

TEST(SignedVolume, FarFromTheOriginKeepsItsVolume) {
    // A 0.5 x 0.25 x 2 box a thousand kilometres out: products about the
    // origin would lose the volume to rounding.
    const double far = 1e9;
    const Mesh box = make_box({far, far, far}, {far + 0.5, far + 0.25, far + 2});
    const auto volumes = fabvdb::surface::component_signed_volumes(box, std::vector<uint32_t>(12, 0), 1);
    EXPECT_NEAR(volumes[0], 0.25, 1e-9);
}

TEST(SignedVolume, EmptyMesh) {
    EXPECT_TRUE(fabvdb::surface::component_signed_volumes(Mesh{}, {}, 0).empty());
    EXPECT_EQ(fabvdb::surface::component_signed_volumes(Mesh{}, {}, 2), (std::vector<double>{0.0, 0.0}));
}

TEST(SignedVolume, SphereMatchesTheHelpersVolume) {
    const Mesh sphere = fabvdb::test::make_sphere({1, -2, 3}, 2.0, 3);
    const auto volumes =
        fabvdb::surface::component_signed_volumes(sphere, std::vector<uint32_t>(sphere.triangles.size(), 0), 1);
    EXPECT_NEAR(volumes[0], fabvdb::test::mesh_volume(sphere), 1e-9);
    EXPECT_LT(volumes[0], 4.0 / 3.0 * M_PI * 8.0);
    EXPECT_GT(volumes[0], 0.95 * 4.0 / 3.0 * M_PI * 8.0);
}

}  // namespace
