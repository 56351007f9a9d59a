// Rounding to float coordinates: a box with a slit a micrometre high cut
// into it by an exact boolean (the kind of sliver the mold booleans leave
// where two solids graze within float precision: a kitten mold piece had
// one) crosses itself when its vertices go to their nearest floats, and
// comes back valid from round_to_float; so does a box with two vertices
// closer than a float step, by moving one or by collapsing their edge. Checked with the test support's own
// CGAL self-intersection test, edge pairing and degeneracy count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.h"
#include "support/ray_cast.h"
#include "support/defect_shapes.h"
#include "support/shapes.h"
#include "surface/float_rounding.h"
#include "surface/mesh_boolean.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;

bool all_floats(const Mesh& mesh) { return fabvdb::test::stored_as_float(mesh).vertices == mesh.vertices; }

// Box [100, 110]³ with a slit `thickness` high cut into it from the x = 100
// face, 5 mm deep, rising by 1 in 1000 along x: its faces are a micrometre
// apart where `thickness` is 1e-6, under a float step (7.6e-6 at 105 mm).
Mesh slit_box(double thickness) {
    const Mesh block = fabvdb::test::make_box({100, 100, 100}, {110, 110, 110});
    Mesh slit = fabvdb::test::make_box({98, 98, 105}, {105, 112, 105 + thickness});
    for (Vec3& p : slit.vertices) p[2] += 1e-3 * (p[0] - 100);
    fabvdb::Progress progress;
    return fabvdb::surface::mesh_boolean(block, "block", {{fabvdb::surface::BooleanOperation::subtract, &slit, "slit"}},
                                        progress);
}

void expect_valid_float_solid(const Mesh& source, const Mesh& rounded, double max_move) {
    EXPECT_TRUE(all_floats(rounded));
    EXPECT_TRUE(fabvdb::test::closed_two_manifold(rounded));
    EXPECT_FALSE(fabvdb::test::self_intersects(rounded));
    EXPECT_EQ(fabvdb::test::degenerate_triangle_count(rounded), 0u);
    EXPECT_NEAR(fabvdb::test::mesh_volume(rounded), fabvdb::test::mesh_volume(source),
                1e-6 * fabvdb::test::mesh_volume(source));
    // Every vertex kept lies within max_move of a vertex of the source.
    for (const Vec3& p : rounded.vertices) {
        double nearest = HUGE_VAL;
        for (const Vec3& q : source.vertices) nearest = std::min(nearest, std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]));
        EXPECT_LE(nearest, max_move);
    }
}

// A float step at 110 mm.
const double ulp = std::nextafter(110.0f, 200.0f) - 110.0f;

TEST(FloatRounding, MicrometreSlitIsRoundedWithoutCrossings) {
    const Mesh slit = slit_box(1e-6);
    ASSERT_TRUE(fabvdb::test::closed_two_manifold(slit));
    ASSERT_FALSE(fabvdb::test::self_intersects(slit));
    // The defect this guards against: at the nearest floats the slit's
    // faces meet.
    const Mesh naive = fabvdb::test::stored_as_float(slit);
    EXPECT_TRUE(fabvdb::test::self_intersects(naive) || fabvdb::test::degenerate_triangle_count(naive) > 0);

    const Mesh rounded = fabvdb::surface::round_to_float(slit, "the slit box");
    EXPECT_EQ(rounded.triangles.size(), slit.triangles.size());
    expect_valid_float_solid(slit, rounded, 10 * ulp);
}

TEST(FloatRounding, CloseVerticesMergedByRoundingAreCollapsed) {
    const Mesh box = fabvdb::test::make_box_with_close_pair();
    ASSERT_TRUE(fabvdb::test::closed_two_manifold(box));
    ASSERT_FALSE(fabvdb::test::self_intersects(box));
    ASSERT_GT(fabvdb::test::degenerate_triangle_count(fabvdb::test::stored_as_float(box)), 0u);
    // Moving either vertex a float step apart also separates them; without
    // that search the edge between them goes.
    expect_valid_float_solid(box, fabvdb::surface::round_to_float(box, "the box"), 10 * ulp);
    fabvdb::surface::FloatRoundingOptions options;
    options.search_ulps = 0;
    const Mesh collapsed = fabvdb::surface::round_to_float(box, "the box", options);
    EXPECT_EQ(collapsed.triangles.size(), box.triangles.size() - 2);
    expect_valid_float_solid(box, collapsed, 4 * ulp);
}

TEST(FloatRounding, CleanMeshOnlyGoesToNearestFloats) {
    const Mesh sphere = fabvdb::test::make_sphere({1.1, 2.2, 3.3}, 20.0, 4);
    const Mesh rounded = fabvdb::surface::round_to_float(sphere, "the sphere");
    const Mesh naive = fabvdb::test::stored_as_float(sphere);
    EXPECT_EQ(rounded.vertices, naive.vertices);
    EXPECT_EQ(rounded.triangles, naive.triangles);
}

TEST(FloatRounding, BadOptionsAreRefused) {
    const Mesh box = fabvdb::test::make_box({0, 0, 0}, {1, 1, 1});
    for (const auto& [search, rounds] : {std::pair{-1, 4}, std::pair{17, 4}, std::pair{2, 0}}) {
        fabvdb::surface::FloatRoundingOptions options;
        options.search_ulps = search;
        options.max_rounds = rounds;
        try {
            fabvdb::surface::round_to_float(box, "box", options);
            FAIL() << "expected invalid argument";
        } catch (const fabvdb::Error& e) {
            EXPECT_EQ(e.status(), FABVDB_ERR_INVALID_ARGUMENT);
        }
    }
}

}  // namespace
