// Degenerate triangles taken out by CGAL's flips and collapses: a closed box
// with a zero-area cap comes back closed, with no degenerate triangle, the
// box's volume, and the triangles away from the cap as they were; a mesh
// without degenerate triangles, or not a 2-manifold, gives nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>

#include "support/defect_shapes.h"
#include "support/ray_cast.h"
#include "support/shapes.h"
#include "surface/collapse_degenerate_triangles.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;

std::set<std::array<Vec3, 3>> triangle_corners(const Mesh& mesh) {
    std::set<std::array<Vec3, 3>> out;
    for (const auto& t : mesh.triangles) {
        std::array<Vec3, 3> c{mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
        std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
        out.insert(c);
    }
    return out;
}

TEST(CollapseDegenerateTriangles, CapIsFlippedAwayAndTheBoxStaysClosed) {
    const Mesh capped = fabvdb::test::make_box_with_cap({0, 0, 0}, {10, 10, 10});
    ASSERT_EQ(fabvdb::test::degenerate_triangle_count(capped), 1u);
    fabvdb::Progress progress;
    const auto collapsed = fabvdb::surface::collapse_degenerate_triangles(capped, progress);
    ASSERT_TRUE(collapsed);
    EXPECT_EQ(collapsed->degenerate, 1u);
    const Mesh& out = collapsed->mesh;
    EXPECT_TRUE(fabvdb::test::closed_two_manifold(out));
    EXPECT_EQ(fabvdb::test::degenerate_triangle_count(out), 0u);
    EXPECT_FALSE(fabvdb::test::self_intersects(out));
    EXPECT_NEAR(fabvdb::test::mesh_volume(out), 1000.0, 1e-9);
    // The cap and the triangle across its long edge are the only ones that
    // may change: the other 12 come back as they were.
    const auto before = triangle_corners(capped), after = triangle_corners(out);
    size_t kept = 0;
    for (const auto& c : before) kept += after.count(c);
    EXPECT_GE(kept, 12u);
    EXPECT_LE(out.triangles.size(), capped.triangles.size());
}

TEST(CollapseDegenerateTriangles, NothingToDoGivesNothing) {
    fabvdb::Progress progress;
    EXPECT_FALSE(fabvdb::surface::collapse_degenerate_triangles(fabvdb::test::make_box({0, 0, 0}, {1, 1, 1}),
                                                                progress));
    // Two capped boxes sharing every vertex: each edge has four triangles.
    const Mesh capped = fabvdb::test::make_box_with_cap({0, 0, 0}, {10, 10, 10});
    Mesh doubled = capped;
    doubled.triangles.insert(doubled.triangles.end(), capped.triangles.begin(), capped.triangles.end());
    EXPECT_FALSE(fabvdb::surface::collapse_degenerate_triangles(doubled, progress));
}

}  // namespace
