// Small holes filled with faired patches: a sphere missing the triangles
// around two of its vertices gets them back as smooth patches close to the
// sphere, all its triangles kept, closed again; a hole larger than allowed,
// a mesh without holes, or one that is not an oriented 2-manifold (a flipped
// triangle, a fin) is left alone.
#include <gtest/gtest.h>

#include <cmath>

#include "support/ray_cast.h"
#include "support/shapes.h"
#include "surface/fill_small_holes.h"

namespace {

using fabvdb::Mesh;

// The sphere of radius 10 without the triangles around vertices 0 and 7.
Mesh sphere_with_two_holes() {
    const Mesh sphere = fabvdb::test::make_sphere({0, 0, 0}, 10.0, 3);
    Mesh holed;
    holed.vertices = sphere.vertices;
    for (const fabvdb::Triangle& t : sphere.triangles) {
        bool around = false;
        for (uint32_t v : t) around = around || v == 0 || v == 7;
        if (!around) holed.triangles.push_back(t);
    }
    return holed;
}

TEST(FillSmallHoles, SmallHolesGetFairPatches) {
    const Mesh holed = sphere_with_two_holes();
    ASSERT_FALSE(fabvdb::test::closed_two_manifold(holed));
    fabvdb::Progress progress;
    const auto filled = fabvdb::surface::fill_small_holes(holed, 5.0, progress);
    ASSERT_TRUE(filled);
    EXPECT_EQ(filled->holes, 2u);
    EXPECT_EQ(filled->mesh.triangles.size(), holed.triangles.size() + filled->added_triangles);
    EXPECT_TRUE(fabvdb::test::closed_two_manifold(filled->mesh));
    EXPECT_FALSE(fabvdb::test::self_intersects(filled->mesh));
    for (const fabvdb::Vec3& p : filled->mesh.vertices)
        EXPECT_NEAR(std::hypot(p[0], p[1], p[2]), 10.0, 0.3);
    EXPECT_NEAR(fabvdb::test::mesh_volume(filled->mesh),
                fabvdb::test::mesh_volume(fabvdb::test::make_sphere({0, 0, 0}, 10.0, 3)), 2.0);
}

TEST(FillSmallHoles, LargeHolesAndClosedMeshesAreLeftAlone) {
    fabvdb::Progress progress;
    EXPECT_FALSE(fabvdb::surface::fill_small_holes(sphere_with_two_holes(), 1.0, progress));
    EXPECT_FALSE(fabvdb::surface::fill_small_holes(fabvdb::test::make_sphere({0, 0, 0}, 10.0, 2), 5.0, progress));
}

TEST(FillSmallHoles, NoPatchOnAMeshThatIsNotAnOrientedManifold) {
    fabvdb::Progress progress;
    Mesh flipped = sphere_with_two_holes();
    std::swap(flipped.triangles[40][1], flipped.triangles[40][2]);
    EXPECT_FALSE(fabvdb::surface::fill_small_holes(flipped, 5.0, progress));
    Mesh fin = sphere_with_two_holes();
    const fabvdb::Triangle t = fin.triangles[40];
    fin.vertices.push_back({0, 0, 20});
    fin.triangles.push_back({t[0], t[1], uint32_t(fin.vertices.size() - 1)});
    EXPECT_FALSE(fabvdb::surface::fill_small_holes(fin, 5.0, progress));
}

}  // namespace
