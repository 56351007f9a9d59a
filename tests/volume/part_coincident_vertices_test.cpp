// Parting coincident vertices: two tetrahedra whose apexes share a position
// (distinct indices) get their apexes moved apart, each into its own
// tetrahedron, everything else untouched; a mesh without such vertices is
// left as it is.
#include <gtest/gtest.h>

#include "support/shapes.h"
#include "volume/part_coincident_vertices.h"

namespace {

using fabvdb::Mesh;

// Apex at the origin, base at z = side (side > 0: above, < 0: below), outward.
void add_tetrahedron(Mesh& mesh, double side) {
    const uint32_t base = uint32_t(mesh.vertices.size());
    mesh.vertices.push_back({0, 0, 0});
    mesh.vertices.push_back({1, 0, side});
    mesh.vertices.push_back({-0.5, 0.8, side});
    mesh.vertices.push_back({-0.5, -0.8, side});
    const uint32_t a = base, b = base + 1, c = base + 2, d = base + 3;
    if (side > 0)
        mesh.triangles.insert(mesh.triangles.end(), {{a, c, b}, {a, d, c}, {a, b, d}, {b, c, d}});
    else
        mesh.triangles.insert(mesh.triangles.end(), {{a, b, c}, {a, c, d}, {a, d, b}, {b, d, c}});
}

TEST(PartCoincidentVertices, TouchingApexesMoveIntoTheirOwnSolids) {
    Mesh mesh;
    add_tetrahedron(mesh, -1.0);
    add_tetrahedron(mesh, 1.0);
    const Mesh before = mesh;
    EXPECT_EQ(fabvdb::volume::part_coincident_vertices(mesh), 2u);
    EXPECT_NE(mesh.vertices[0], mesh.vertices[4]);
    EXPECT_LT(mesh.vertices[0][2], 0.0);
    EXPECT_GT(mesh.vertices[4][2], 0.0);
    EXPECT_NEAR(mesh.vertices[0][2], -0.01, 1e-12);  // a hundredth of the way to its ring's centre
    for (size_t v : {1, 2, 3, 5, 6, 7}) EXPECT_EQ(mesh.vertices[v], before.vertices[v]);
    EXPECT_EQ(mesh.triangles, before.triangles);
    EXPECT_GT(fabvdb::test::mesh_volume(mesh), 0.0);
}

TEST(PartCoincidentVertices, DistinctPositionsAreLeftAlone) {
    Mesh box = fabvdb::test::make_box({0, 0, 0}, {1, 2, 3});
    const Mesh before = box;
    EXPECT_EQ(fabvdb::volume::part_coincident_vertices(box), 0u);
    EXPECT_EQ(box.vertices, before.vertices);
}

}  // namespace
