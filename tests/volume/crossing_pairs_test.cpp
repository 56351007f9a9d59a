// crossing_pairs on hand-built cases whose answer is known by construction:
// single pairs of triangles with no, one, two or three shared vertices
// (piercing, touching, folded, flat, duplicated), a unit box pierced by a
// large triangle at half height (exactly its 8 side triangles cross it), and
// the candidate filter on that box. The comparison with CGAL's own
// self-intersection test on random meshes is in mesh_predicates_test.cpp.
#include "volume/crossing_pairs.h"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "support/pair_checks.h"
#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

using Pairs = std::vector<std::pair<uint32_t, uint32_t>>;

// The unit box plus a triangle in the plane z = 0.5 whose shadow holds the
// box's (x + y <= 3 around [0, 1]²): it cuts every side triangle of the box
// (each has corners at z = 0 and z = 1) and misses the top and bottom.
Mesh box_with_blade() {
    Mesh mesh = test::make_box({0, 0, 0}, {1, 1, 1});
    const uint32_t first = uint32_t(mesh.vertices.size());
    mesh.vertices.push_back({-3, -3, 0.5});
    mesh.vertices.push_back({6, -3, 0.5});
    mesh.vertices.push_back({-3, 6, 0.5});
    mesh.triangles.push_back({first, first + 1, first + 2});
    return mesh;
}

TEST(CrossingPairs, FewerThanTwoTrianglesHaveNone) {
    EXPECT_TRUE(crossing_pairs(Mesh{}).empty());
    EXPECT_TRUE(crossing_pairs(test::loose_triangles({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}})).empty());
}

TEST(CrossingPairs, SeparateTrianglesCrossWhenTheyMeetOrTouch) {
    const std::array<Vec3, 3> flat = {{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}};
    // Piercing: a vertical triangle through the flat one's interior.
    EXPECT_EQ(crossing_pairs(test::loose_triangles({flat, {{{0.5, 0.5, -1}, {0.5, 0.5, 1}, {0.6, 0.4, 1}}}})), (Pairs{{0, 1}}));
    // Parallel, 0.1 above: apart, though their boxes nearly meet.
    EXPECT_TRUE(crossing_pairs(test::loose_triangles({flat, {{{0, 0, 0.1}, {2, 0, 0.1}, {0, 2, 0.1}}}})).empty());
    // A corner resting on the flat one's interior: closed sets touch.
    EXPECT_EQ(crossing_pairs(test::loose_triangles({flat, {{{0.5, 0.5, 0}, {0.5, 0.5, 1}, {1, 0.5, 1}}}})), (Pairs{{0, 1}}));
    // The same corner lifted by 1e-9: apart.
    EXPECT_TRUE(crossing_pairs(test::loose_triangles({flat, {{{0.5, 0.5, 1e-9}, {0.5, 0.5, 1}, {1, 0.5, 1}}}})).empty());
    // Coplanar, overlapping.
    EXPECT_EQ(crossing_pairs(test::loose_triangles({flat, {{{0.5, 0.5, 0}, {3, 0.5, 0}, {0.5, 3, 0}}}})), (Pairs{{0, 1}}));
    // Coplanar across the hypotenuse x + y = 2, boxes overlapping: apart.
    EXPECT_TRUE(crossing_pairs(test::loose_triangles({flat, {{{2, 0.1, 0}, {2, 2, 0}, {0.1, 2, 0}}}})).empty());
    // An unwelded seam: the same edge in both, by position only, touches.
    EXPECT_EQ(crossing_pairs(test::loose_triangles({flat, {{{2, 0, 0}, {2, 2, 0}, {0, 2, 0}}}})), (Pairs{{0, 1}}));
}

TEST(CrossingPairs, SharedVertexCrossesOnlyAwayFromIt) {
    // Two triangles at vertex 0 (a fan of two, so tested exactly).
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, -1}, {0.2, 0.2, 1}};
    mesh.triangles = {{0, 1, 2}, {0, 3, 4}};
    // The edge (1,1,-1)-(0.2,0.2,1) passes z = 0 at (0.6, 0.6), inside the flat one.
    EXPECT_EQ(crossing_pairs(mesh), (Pairs{{0, 1}}));
    // Both ends above the plane: they meet at vertex 0 only.
    mesh.vertices[3] = {1, 1, 0.5};
    EXPECT_TRUE(crossing_pairs(mesh).empty());
    // Coplanar with the second inside the first's angle: they overlap.
    mesh.vertices[3] = {1, 0.2, 0};
    mesh.vertices[4] = {0.2, 1, 0};
    EXPECT_EQ(crossing_pairs(mesh), (Pairs{{0, 1}}));
    // Coplanar, in the opposite quadrant: only vertex 0 is common.
    mesh.vertices[3] = {-1, -0.2, 0};
    mesh.vertices[4] = {-0.2, -1, 0};
    EXPECT_TRUE(crossing_pairs(mesh).empty());
}

TEST(CrossingPairs, SharedEdgeCrossesOnlyWhenFoldedFlat) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}};
    // A flat strip: the second on the other side of edge 0-1.
    mesh.triangles = {{0, 1, 2}, {1, 0, 3}};
    EXPECT_TRUE(crossing_pairs(mesh).empty());
    // Bent along the edge: still only the edge in common.
    mesh.vertices[3] = {0.5, -1, 0.7};
    EXPECT_TRUE(crossing_pairs(mesh).empty());
    // Folded flat onto the first: coplanar on the same side.
    mesh.vertices[3] = {0.3, 0.5, 0};
    EXPECT_EQ(crossing_pairs(mesh), (Pairs{{0, 1}}));
    // Inconsistently oriented (both run 0 -> 1) but on opposite sides: no crossing.
    mesh.vertices[3] = {0.5, -1, 0};
    mesh.triangles = {{0, 1, 2}, {0, 1, 3}};
    EXPECT_TRUE(crossing_pairs(mesh).empty());
}

TEST(CrossingPairs, DuplicatesCrossInEitherOrientation) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {1, 2, 0}};
    EXPECT_EQ(crossing_pairs(mesh), (Pairs{{0, 1}}));
    mesh.triangles = {{0, 1, 2}, {0, 2, 1}};
    EXPECT_EQ(crossing_pairs(mesh), (Pairs{{0, 1}}));
    // A closed box with one triangle listed twice: that pair alone.
    Mesh box = test::make_box({0, 0, 0}, {1, 1, 1});
    box.triangles.push_back(box.triangles[5]);
    EXPECT_EQ(crossing_pairs(box), (Pairs{{5, 12}}));
}

TEST(CrossingPairs, BoxCutAtHalfHeightCrossesItsSideTriangles) {
    EXPECT_TRUE(crossing_pairs(test::make_box({0, 0, 0}, {1, 1, 1})).empty());
    const Mesh mesh = box_with_blade();
    // make_box: triangles 0-1 bottom, 2-3 top, 4-11 the four sides.
    Pairs expected;
    for (uint32_t t = 4; t < 12; ++t) expected.push_back({t, 12});
    EXPECT_EQ(crossing_pairs(mesh), expected);
    // Moved above the box, the blade crosses nothing.
    Mesh above = mesh;
    for (uint32_t v = 8; v < 11; ++v) above.vertices[v][2] = 1.5;
    EXPECT_TRUE(crossing_pairs(above).empty());
}

TEST(CrossingPairs, CandidatesKeepOnlyTheirPairs) {
    const Mesh mesh = box_with_blade();
    std::vector<char> candidates(mesh.triangles.size(), 0);
    // No candidate: nothing is tested.
    EXPECT_TRUE(crossing_pairs(mesh, candidates).empty());
    // The blade: all its pairs.
    candidates[12] = 1;
    Pairs all;
    for (uint32_t t = 4; t < 12; ++t) all.push_back({t, 12});
    EXPECT_EQ(crossing_pairs(mesh, candidates), all);
    // One side triangle, then one side and the (uncut) top: that side's pair alone.
    candidates[12] = 0;
    candidates[7] = 1;
    EXPECT_EQ(crossing_pairs(mesh, candidates), (Pairs{{7, 12}}));
    candidates[2] = 1;
    EXPECT_EQ(crossing_pairs(mesh, candidates), (Pairs{{7, 12}}));
    // Two sides: two pairs, sorted.
    candidates[10] = 1;
    EXPECT_EQ(crossing_pairs(mesh, candidates), (Pairs{{7, 12}, {10, 12}}));
}

TEST(CrossingPairs, SortedAndRepeatableOnManyCrossings) {
    // Two spheres of different sizes overlapping: many crossings, each listed
    // once as (i, j), i < j, with i on the first sphere and j on the second
    // (each sphere alone is clean), in the same order on every run.
    const Mesh a = test::make_sphere({0, 0, 0}, 1.0, 3);
    const Mesh mesh = test::merged(a, test::make_sphere({0.9, 0.2, 0.1}, 0.6, 4));
    const Pairs pairs = crossing_pairs(mesh);
    ASSERT_GT(pairs.size(), 50u);
    test::expect_sorted_pairs_across(pairs, uint32_t(a.triangles.size()));
    EXPECT_EQ(crossing_pairs(mesh), pairs);
}

}  // namespace
}  // namespace fabvdb::volume
