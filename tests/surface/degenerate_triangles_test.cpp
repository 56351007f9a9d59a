// Degenerate triangles: a repeated index, coincident corners and exactly
// collinear corners are found (ascending), with no tolerance: corners off
// the line by one unit in the last place are not degenerate.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "support/shapes.h"
#include "surface/degenerate_triangles.h"

namespace {

using fabvdb::Mesh;
using fabvdb::surface::is_degenerate_triangle;

TEST(DegenerateTriangles, RepeatedIndexIsDegenerateWhateverThePositions) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_FALSE(is_degenerate_triangle(mesh, {0, 1, 2}));
    EXPECT_TRUE(is_degenerate_triangle(mesh, {0, 0, 2}));
    EXPECT_TRUE(is_degenerate_triangle(mesh, {0, 1, 1}));
    EXPECT_TRUE(is_degenerate_triangle(mesh, {2, 1, 2}));
    EXPECT_TRUE(is_degenerate_triangle(mesh, {1, 1, 1}));
}

TEST(DegenerateTriangles, CoincidentAndCollinearCorners) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 2, 3}, {3, 6, 9}, {1, 2, 3}, {-2, -4, -6}, {1e16, 0, 0}, {1e16 + 2, 1, 0},
                     {1e16 + 4, 2, 0}};
    EXPECT_TRUE(is_degenerate_triangle(mesh, {0, 1, 2}));  // on one line through the origin
    EXPECT_TRUE(is_degenerate_triangle(mesh, {4, 0, 2}));  // the middle corner need not be in the middle
    EXPECT_TRUE(is_degenerate_triangle(mesh, {1, 3, 0}));  // two corners at one point
    EXPECT_TRUE(is_degenerate_triangle(mesh, {5, 6, 7}));  // collinear far out, where doubles are 2 apart
}

TEST(DegenerateTriangles, NoTolerance) {
    Mesh mesh;
    // 0.1 * 3 is 0.30000000000000004 in doubles: just off the diagonal.
    const double off = 0.1 * 3;
    ASSERT_NE(off, 0.3);
    mesh.vertices = {{0, 0, 0}, {1, 1, 1}, {off, 0.3, 0.3}, {2, 1e-300, 0}, {1, 0, 0}, {1e16, 0, 0},
                     {1e16 + 2, 1, 0}, {1e16 + 6, 2, 0}};
    EXPECT_FALSE(is_degenerate_triangle(mesh, {0, 1, 2}));
    EXPECT_FALSE(is_degenerate_triangle(mesh, {0, 4, 3}));
    EXPECT_FALSE(is_degenerate_triangle(mesh, {5, 6, 7}));
}

TEST(DegenerateTriangles, ListsTheDegenerateOnesAscending) {
    Mesh mesh = fabvdb::test::make_box({0, 0, 0}, {1, 1, 1});
    EXPECT_TRUE(fabvdb::surface::degenerate_triangles(mesh).empty());
    // Box vertices: 0 = (0,0,0), 1 = (1,0,0), 3 = (1,1,0), 7 = (1,1,1).
    mesh.triangles.insert(mesh.triangles.begin() + 4, {0, 3, 3});  // now triangle 4
    mesh.vertices.push_back({0.5, 0.5, 0.5});                        // vertex 8, on the 0-7 diagonal
    mesh.triangles.push_back({7, 8, 0});                             // triangle 13
    mesh.triangles.push_back({0, 1, 8});                             // triangle 14: fine
    mesh.triangles.insert(mesh.triangles.begin(), {1, 1, 1});        // triangle 0; the others move up one
    EXPECT_EQ(fabvdb::surface::degenerate_triangles(mesh), (std::vector<uint32_t>{0, 5, 14}));
}

TEST(DegenerateTriangles, EmptyMeshHasNone) {
    EXPECT_TRUE(fabvdb::surface::degenerate_triangles(Mesh{}).empty());
}

}  // namespace
