// cut_along_crossings on a hand-worked crossing: a vertical triangle through
// the interior of a flat one meets it along the segment from (1, 1, 0) to
// (1.5, 0.75, 0), exactly representable, which becomes the cut. The pieces
// cover each crossing triangle (same area, same plane), the untouched
// triangle stays first, every cut edge runs along that segment, and a corner
// lying exactly in the other's plane gives nothing.
#include "volume/cut_along_crossings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

namespace fabvdb::volume {
namespace {

double area(const Mesh& mesh, const Triangle& t) {
    const Vec3 n = triangle_normal(mesh, t);
    return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

// Triangle 0 far away and untouched; 1 in z = 0; 2 vertical, through 1.
Mesh flat_and_vertical() {
    Mesh mesh;
    mesh.vertices = {{10, 10, 10}, {11, 10, 10}, {10, 11, 10},  // untouched
                     {0, 0, 0},    {4, 0, 0},    {0, 4, 0},     // flat
                     {1, 1, -1},   {1, 1, 1},    {2, 0.5, 1}};  // vertical (x + 2y = 3)
    mesh.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
    return mesh;
}

TEST(CutAlongCrossings, APiercingTriangleIsCutAlongTheSegment) {
    const Mesh mesh = flat_and_vertical();
    const std::optional<CutSurface> cut = cut_along_crossings(mesh, {{1, 2}});
    ASSERT_TRUE(cut.has_value());
    // The input's vertices first, unchanged; then the cut points, which are
    // the segment's two ends (a copy for each side).
    ASSERT_EQ(cut->mesh.vertices.size(), mesh.vertices.size() + 4);
    EXPECT_TRUE(std::equal(mesh.vertices.begin(), mesh.vertices.end(), cut->mesh.vertices.begin()));
    const std::set<Vec3> ends = {{1, 1, 0}, {1.5, 0.75, 0}};
    for (size_t v = mesh.vertices.size(); v < cut->mesh.vertices.size(); ++v)
        EXPECT_TRUE(ends.count(cut->mesh.vertices[v])) << v;
    // The untouched triangle first; the pieces of each crossing triangle lie
    // in its plane and add up to its area.
    ASSERT_EQ(cut->first_piece, 1u);
    EXPECT_EQ(cut->mesh.triangles[0], mesh.triangles[0]);
    double flat_area = 0.0, vertical_area = 0.0;
    size_t flat_pieces = 0, vertical_pieces = 0;
    for (size_t t = cut->first_piece; t < cut->mesh.triangles.size(); ++t) {
        const Triangle& piece = cut->mesh.triangles[t];
        bool flat = true, vertical = true;
        for (uint32_t v : piece) {
            const Vec3& p = cut->mesh.vertices[v];
            flat = flat && p[2] == 0.0;
            vertical = vertical && p[0] + 2 * p[1] == 3.0;
        }
        ASSERT_NE(flat, vertical) << "piece " << t;
        (flat ? flat_area : vertical_area) += area(cut->mesh, piece);
        ++(flat ? flat_pieces : vertical_pieces);
    }
    // A triangle with 2 points inside is cut into 2 × 2 + 1 triangles; one
    // cut across by a segment into a triangle and a quadrilateral, 3.
    EXPECT_EQ(flat_pieces, 5u);
    EXPECT_EQ(vertical_pieces, 3u);
    EXPECT_NEAR(flat_area, area(mesh, mesh.triangles[1]), 1e-12);
    EXPECT_NEAR(vertical_area, area(mesh, mesh.triangles[2]), 1e-12);
    // Every cut edge joins the segment's two ends: one edge in each triangle,
    // inside the flat one (two pieces along it), on the side of the vertical
    // one's part below (one piece along it above, one below).
    size_t cut_edges = 0;
    for (const Triangle& piece : cut->mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = piece[k], b = piece[(k + 1) % 3];
            if (!cut->along_cut(a, b)) continue;
            ++cut_edges;
            EXPECT_EQ((std::set<Vec3>{cut->mesh.vertices[a], cut->mesh.vertices[b]}), ends);
        }
    EXPECT_EQ(cut_edges, 4u);
}

TEST(CutAlongCrossings, SameResultEveryRun) {
    const Mesh mesh = flat_and_vertical();
    const std::optional<CutSurface> first = cut_along_crossings(mesh, {{1, 2}});
    ASSERT_TRUE(first.has_value());
    for (int run = 0; run < 4; ++run) {
        const std::optional<CutSurface> again = cut_along_crossings(mesh, {{1, 2}});
        ASSERT_TRUE(again.has_value());
        EXPECT_EQ(again->mesh.vertices, first->mesh.vertices);
        EXPECT_EQ(again->mesh.triangles, first->mesh.triangles);
        EXPECT_EQ(again->cut_edges, first->cut_edges);
    }
}

TEST(CutAlongCrossings, ACornerInTheOtherPlaneGivesNothing) {
    // The vertical triangle's lowest corner moved onto z = 0 (inside the
    // flat one): the autorefinement is not trusted there.
    Mesh mesh = flat_and_vertical();
    mesh.vertices[6] = {1, 1, 0};
    EXPECT_FALSE(cut_along_crossings(mesh, {{1, 2}}).has_value());
    EXPECT_FALSE(cut_along_crossings(mesh, {{2, 1}}).has_value());
}

}  // namespace
}  // namespace fabvdb::volume
