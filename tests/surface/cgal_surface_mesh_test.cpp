// Mesh <-> CGAL Surface_mesh: a box goes there and back with its vertices
// and triangles in order; triangles that are not a 2-manifold (an edge of
// three triangles) do not convert.
#include <gtest/gtest.h>

#include "support/shapes.h"
#include "surface/cgal_surface_mesh.h"

namespace {

using fabvdb::Mesh;

TEST(CgalSurfaceMesh, RoundTripKeepsVerticesAndTriangles) {
    const Mesh box = fabvdb::test::make_box({-1, 2, 3}, {4, 5, 6.5});
    const auto surface = fabvdb::surface::to_cgal_surface_mesh(box);
    ASSERT_TRUE(surface);
    EXPECT_EQ(surface->number_of_vertices(), box.vertices.size());
    EXPECT_EQ(surface->number_of_faces(), box.triangles.size());
    const auto back = fabvdb::surface::from_cgal_surface_mesh(*surface);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->vertices, box.vertices);
    EXPECT_EQ(back->triangles, box.triangles);
}

TEST(CgalSurfaceMesh, NonManifoldEdgeDoesNotConvert) {
    Mesh fan;
    fan.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    fan.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    EXPECT_FALSE(fabvdb::surface::to_cgal_surface_mesh(fan));
}

}  // namespace
