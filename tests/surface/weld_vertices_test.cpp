// Welding exactly coincident vertices: each vertex maps to the lowest index at
// its position (checked against an all-pairs search), -0.0 equals 0.0, close
// is not equal, and the welded mesh keeps first-appearance order, unused
// vertices, every triangle (degenerate ones too) and the volume.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "support/shapes.h"
#include "surface/weld_vertices.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Triangle;
using fabvdb::Vec3;

// The lowest index at the same position, by comparing every pair.
std::vector<uint32_t> first_at_same_position(const Mesh& mesh) {
    std::vector<uint32_t> map(mesh.vertices.size());
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        map[v] = uint32_t(v);
        for (size_t w = 0; w < v; ++w) {
            const Vec3 &a = mesh.vertices[v], &b = mesh.vertices[w];
            if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) {
                map[v] = uint32_t(w);
                break;
            }
        }
    }
    return map;
}

TEST(WeldVertices, TwoBoxesSharingAFace) {
    // Boxes side by side along x: the second's four x = 1 corners are the first's.
    const Mesh mesh = fabvdb::test::merged(fabvdb::test::make_box({0, 0, 0}, {1, 1, 1}),
                                           fabvdb::test::make_box({1, 0, 0}, {2, 1, 1}));
    const std::vector<uint32_t> map = fabvdb::surface::coincident_vertex_map(mesh);
    EXPECT_EQ(map, first_at_same_position(mesh));
    int moved = 0;
    for (size_t v = 0; v < map.size(); ++v) moved += map[v] != v;
    EXPECT_EQ(moved, 4);

    const Mesh welded = fabvdb::surface::weld_coincident_vertices(mesh);
    EXPECT_EQ(welded.vertices.size(), 12u);
    ASSERT_EQ(welded.triangles.size(), mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(welded.vertices[welded.triangles[t][k]], mesh.vertices[mesh.triangles[t][k]]);
    EXPECT_NEAR(fabvdb::test::mesh_volume(welded), 2.0, 1e-12);
}

TEST(WeldVertices, FirstAppearanceOrderAndUnusedVerticesKept) {
    Mesh mesh;
    mesh.vertices = {{5, 5, 5}, {1, 0, 0}, {0, 0, 0}, {1, 0, 0}, {9, 9, 9}, {0, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{2, 1, 6}, {5, 3, 6}, {1, 3, 5}};
    EXPECT_EQ(fabvdb::surface::coincident_vertex_map(mesh), (std::vector<uint32_t>{0, 1, 2, 1, 4, 2, 6}));
    const Mesh original = mesh;
    const Mesh welded = fabvdb::surface::weld_coincident_vertices(mesh);
    EXPECT_EQ(mesh.vertices, original.vertices);  // input untouched
    EXPECT_EQ(mesh.triangles, original.triangles);
    EXPECT_EQ(welded.vertices, (std::vector<Vec3>{{5, 5, 5}, {1, 0, 0}, {0, 0, 0}, {9, 9, 9}, {0, 1, 0}}));
    // The second triangle lands on the first; the third collapses to an edge: both stay.
    EXPECT_EQ(welded.triangles, (std::vector<Triangle>{{2, 1, 4}, {2, 1, 4}, {1, 1, 2}}));
}

TEST(WeldVertices, NegativeZeroEqualsZeroButCloseIsNotEqual) {
    Mesh mesh;
    mesh.vertices = {{0.0, 1.0, 0.0}, {-0.0, 1.0, -0.0}, {0.0, std::nextafter(1.0, 2.0), 0.0}, {1e-300, 1.0, 0.0}};
    EXPECT_EQ(fabvdb::surface::coincident_vertex_map(mesh), (std::vector<uint32_t>{0, 0, 2, 3}));
    EXPECT_EQ(fabvdb::surface::weld_coincident_vertices(mesh).vertices.size(), 3u);
}

TEST(WeldVertices, ManyCoincidentVerticesMatchAnAllPairsSearch) {
    // A grid of points on a coarse lattice, many repeated in scrambled order.
    Mesh mesh;
    for (int i = 0; i < 300; ++i) {
        const int k = (i * 37) % 53;
        mesh.vertices.push_back({double(k % 3), double((k / 3) % 3) * 0.5, double(k % 2) - 1.0});
    }
    for (uint32_t i = 0; i + 2 < 300; i += 3) mesh.triangles.push_back({i, i + 1, i + 2});
    const std::vector<uint32_t> expected = first_at_same_position(mesh);
    EXPECT_EQ(fabvdb::surface::coincident_vertex_map(mesh), expected);
    size_t distinct = 0;
    for (size_t v = 0; v < expected.size(); ++v) distinct += expected[v] == v;
    const Mesh welded = fabvdb::surface::weld_coincident_vertices(mesh);
    EXPECT_EQ(welded.vertices.size(), distinct);
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(welded.vertices[welded.triangles[t][k]], mesh.vertices[mesh.triangles[t][k]]);
}

TEST(WeldVertices, EmptyMesh) {
    EXPECT_TRUE(fabvdb::surface::coincident_vertex_map(Mesh{}).empty());
    const Mesh welded = fabvdb::surface::weld_coincident_vertices(Mesh{});
    EXPECT_TRUE(welded.vertices.empty());
    EXPECT_TRUE(welded.triangles.empty());
}

}  // namespace
