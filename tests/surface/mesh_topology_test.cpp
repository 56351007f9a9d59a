// Components and the topology summary against counts known by
// hand: a box (8 vertices, 18 edges, genus 0), a torus grid (genus 1), boxes
// with holes (boundary edges, loops and their vertices), a fin (a non-manifold edge), two
// boxes pinched at one vertex, a flipped triangle (inconsistent edges), the
// 6-vertex projective plane (closed, odd Euler characteristic: no genus),
// unused vertices, repeated indices and the empty mesh.
#include "surface/mesh_topology.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "support/shapes.h"

namespace fabvdb::surface {
namespace {

using test::make_box;
using test::merged;

TEST(MeshTopology, RepeatedIndexUsesOneEdgeTwice) {
    // The edge table's side of this is in tests/volume/edge_table_test.
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}};
    mesh.triangles = {{0, 0, 1}};
    EXPECT_EQ(summarize_topology(mesh).boundary_edges, 0u);
}

TEST(MeshTopology, ComponentsJoinAtSharedVerticesInFirstTriangleOrder) {
    // Triangles 0 and 2 meet at vertex 2 only (a bow tie); triangle 1 is apart.
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {5, 5, 0}, {6, 5, 0}, {5, 6, 0}, {2, 1, 0}, {2, 2, 0}};
    mesh.triangles = {{0, 1, 2}, {3, 4, 5}, {2, 6, 7}};
    size_t count = 0;
    EXPECT_EQ(triangle_components(mesh, count), (std::vector<uint32_t>{0, 1, 0}));
    EXPECT_EQ(count, 2u);
    // Two boxes, the second listed first.
    const Mesh boxes = merged(make_box({5, 0, 0}, {6, 1, 1}), make_box({0, 0, 0}, {1, 1, 1}));
    const std::vector<uint32_t> component = triangle_components(boxes, count);
    EXPECT_EQ(count, 2u);
    for (size_t t = 0; t < 24; ++t) EXPECT_EQ(component[t], t < 12 ? 0u : 1u);
}

TEST(MeshTopology, ClosedBoxAndTorus) {
    const TopologySummary box = summarize_topology(make_box({0, 0, 0}, {1, 1, 1}));
    EXPECT_EQ(box.referenced_vertices, 8u);
    EXPECT_EQ(box.unreferenced_vertices, 0u);
    EXPECT_EQ(box.edges, 18u);
    EXPECT_EQ(box.boundary_edges, 0u);
    EXPECT_EQ(box.boundary_loops, 0u);
    EXPECT_EQ(box.non_manifold_edges, 0u);
    EXPECT_EQ(box.non_manifold_vertices, 0u);
    EXPECT_EQ(box.inconsistent_edges, 0u);
    EXPECT_EQ(box.components, 1u);
    EXPECT_EQ(box.component_closed, std::vector<bool>{true});
    EXPECT_TRUE(box.closed);
    ASSERT_TRUE(box.genus.has_value());
    EXPECT_EQ(*box.genus, 0);
    // An 8 × 6 torus grid: V = 48, E = 144, F = 96, χ = 0, genus 1.
    const TopologySummary torus = summarize_topology(test::make_torus({0, 0, 0}, 3.0, 1.0, 8, 6));
    EXPECT_EQ(torus.edges, 144u);
    EXPECT_TRUE(torus.closed);
    ASSERT_TRUE(torus.genus.has_value());
    EXPECT_EQ(*torus.genus, 1);
    // Genera add up over components: box + torus + torus.
    const Mesh three = merged(merged(make_box({20, 0, 0}, {21, 1, 1}), test::make_torus({0, 0, 0}, 3.0, 1.0, 8, 6)),
                              test::make_torus({0, 10, 0}, 3.0, 1.0, 8, 6));
    const TopologySummary sum = summarize_topology(three);
    EXPECT_EQ(sum.components, 3u);
    ASSERT_TRUE(sum.genus.has_value());
    EXPECT_EQ(*sum.genus, 2);
}

TEST(MeshTopology, HolesAreBoundaryLoops) {
    // One triangle removed: its 3 edges are boundary, one loop.
    Mesh one = make_box({0, 0, 0}, {1, 1, 1});
    one.triangles.erase(one.triangles.begin());
    TopologySummary s = summarize_topology(one);
    EXPECT_EQ(s.edges, 18u);
    EXPECT_EQ(s.boundary_edges, 3u);
    EXPECT_EQ(s.boundary_loops, 1u);
    EXPECT_FALSE(s.closed);
    EXPECT_EQ(s.component_closed, std::vector<bool>{false});
    EXPECT_FALSE(s.genus.has_value());
    // A whole face removed: its diagonal goes, the square's 4 edges are boundary.
    Mesh face = make_box({0, 0, 0}, {1, 1, 1});
    face.triangles.erase(face.triangles.begin(), face.triangles.begin() + 2);
    s = summarize_topology(face);
    EXPECT_EQ(s.edges, 17u);
    EXPECT_EQ(s.boundary_edges, 4u);
    EXPECT_EQ(s.boundary_loops, 1u);
    // Bottom and top triangles removed: two loops (no shared vertex? the
    // bottom's (0, 2, 3) and the top's (4, 5, 7) share none).
    Mesh two = make_box({0, 0, 0}, {1, 1, 1});
    two.triangles.erase(two.triangles.begin() + 2);
    two.triangles.erase(two.triangles.begin());
    s = summarize_topology(two);
    EXPECT_EQ(s.boundary_edges, 6u);
    EXPECT_EQ(s.boundary_loops, 2u);
    // A holed box beside a closed one: only the first component is open.
    s = summarize_topology(merged(one, make_box({3, 0, 0}, {4, 1, 1})));
    EXPECT_EQ(s.component_closed, (std::vector<bool>{false, true}));
    EXPECT_FALSE(s.closed);
}

TEST(MeshTopology, BoundaryLoopsListTheirVertices) {
    const Mesh box = make_box({0, 0, 0}, {1, 1, 1});
    const auto sorted = [](Triangle t) {
        std::sort(t.begin(), t.end());
        return std::vector<uint32_t>(t.begin(), t.end());
    };
    // One triangle removed: its three corners, ascending.
    Mesh one = box;
    one.triangles.erase(one.triangles.begin());
    EXPECT_EQ(boundary_loops(one, build_edge_table(one)), std::vector<std::vector<uint32_t>>{sorted(box.triangles[0])});
    // Two triangles removed that share no vertex: two loops, by least vertex.
    Mesh two = box;
    two.triangles.erase(two.triangles.begin() + 2);
    two.triangles.erase(two.triangles.begin());
    auto expected = std::vector<std::vector<uint32_t>>{sorted(box.triangles[0]), sorted(box.triangles[2])};
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(boundary_loops(two, build_edge_table(two)), expected);
    // A closed box has none.
    EXPECT_TRUE(boundary_loops(box, build_edge_table(box)).empty());
}

TEST(MeshTopology, FinIsANonManifoldEdge) {
    Mesh fin;
    fin.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}};
    fin.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    const TopologySummary s = summarize_topology(fin);
    EXPECT_EQ(s.edges, 7u);
    EXPECT_EQ(s.non_manifold_edges, 1u);
    EXPECT_EQ(s.boundary_edges, 6u);
    EXPECT_EQ(s.inconsistent_edges, 0u);  // only edges of exactly two uses count
    EXPECT_FALSE(s.closed);
    EXPECT_EQ(s.components, 1u);
}

TEST(MeshTopology, PinchedVertexIsNonManifold) {
    // Two boxes sharing one vertex index: closed, every edge used twice, but
    // the shared vertex has two fans; no genus is given.
    const Mesh a = make_box({0, 0, 0}, {1, 1, 1});
    Mesh pinched = merged(a, make_box({1, 1, 1}, {2, 2, 2}));
    for (auto& t : pinched.triangles)
        for (auto& v : t)
            if (v == 8) v = 7;  // the second box's low corner is the first's high one
    pinched.vertices.erase(pinched.vertices.begin() + 8);
    for (auto& t : pinched.triangles)
        for (auto& v : t)
            if (v > 8) --v;
    const TopologySummary s = summarize_topology(pinched);
    EXPECT_EQ(s.referenced_vertices, 15u);
    EXPECT_EQ(s.edges, 36u);
    EXPECT_EQ(s.boundary_edges, 0u);
    EXPECT_EQ(s.non_manifold_edges, 0u);
    EXPECT_EQ(s.non_manifold_vertices, 1u);
    EXPECT_EQ(s.components, 1u);
    EXPECT_TRUE(s.closed);
    EXPECT_FALSE(s.genus.has_value());
}

TEST(MeshTopology, FlippedTriangleMakesThreeInconsistentEdges) {
    Mesh box = make_box({0, 0, 0}, {1, 1, 1});
    std::swap(box.triangles[4][1], box.triangles[4][2]);
    const TopologySummary s = summarize_topology(box);
    EXPECT_EQ(s.inconsistent_edges, 3u);
    EXPECT_TRUE(s.closed);  // closed counts uses, not their directions
    EXPECT_EQ(summarize_topology(test::flipped(make_box({0, 0, 0}, {1, 1, 1}))).inconsistent_edges, 0u);
}

TEST(MeshTopology, ProjectivePlaneHasNoGenus) {
    // The 6-vertex real projective plane: 10 triangles, 15 edges each used
    // twice, every vertex link a 5-cycle; χ = 6 − 15 + 10 = 1 is odd.
    Mesh plane;
    for (int i = 0; i < 6; ++i) plane.vertices.push_back({double(i), double(i * i), 0.0});
    plane.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {0, 5, 1},
                       {1, 2, 4}, {2, 3, 5}, {3, 4, 1}, {4, 5, 2}, {5, 1, 3}};
    const TopologySummary s = summarize_topology(plane);
    EXPECT_EQ(s.edges, 15u);
    EXPECT_EQ(s.boundary_edges, 0u);
    EXPECT_EQ(s.non_manifold_edges, 0u);
    EXPECT_EQ(s.non_manifold_vertices, 0u);
    EXPECT_TRUE(s.closed);
    EXPECT_FALSE(s.genus.has_value());
}

TEST(MeshTopology, UnusedVerticesAndEmptyMesh) {
    Mesh box = make_box({0, 0, 0}, {1, 1, 1});
    box.vertices.push_back({9, 9, 9});
    box.vertices.push_back({8, 8, 8});
    const TopologySummary s = summarize_topology(box);
    EXPECT_EQ(s.referenced_vertices, 8u);
    EXPECT_EQ(s.unreferenced_vertices, 2u);
    ASSERT_TRUE(s.genus.has_value());
    EXPECT_EQ(*s.genus, 0);  // unused vertices do not enter χ

    Mesh empty;
    empty.vertices = {{0, 0, 0}};
    const TopologySummary e = summarize_topology(empty);
    EXPECT_EQ(e.edges, 0u);
    EXPECT_EQ(e.components, 0u);
    EXPECT_EQ(e.unreferenced_vertices, 1u);
    EXPECT_FALSE(e.closed);
    EXPECT_FALSE(e.genus.has_value());
}

}  // namespace
}  // namespace fabvdb::surface
