//! snap_to_offset with the box [−10, 10]³ as the outer surface and cavities
//! whose vertices each have one nearest face, so the offset point is worked
//! out by hand: an octahedron with corners 6 mm from the centre (4 mm deep)
//! goes to the 2 mm offset at ±8 (exact), stays (at least 2 mm), or goes to
//! ±5 (at least 5 mm); shifted off centre, its deep and shallow corners all
//! reach the 3 mm offset. A thin slab cavity whose faces would meet on the
//! offset plane (its side triangles collapse) has moves undone until no
//! triangle turns or collapses. Cancellation throws.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>

#include "core/error.h"
#include "support/octahedron.h"
#include "support/shapes.h"
#include "volume/snap_to_offset.h"
#include "volume/solid_distance.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;
using fabvdb::volume::OffsetSnap;
using fabvdb::volume::SnapStats;

const Mesh outer = fabvdb::test::make_box({-10, -10, -10}, {10, 10, 10});

const openvdb::Int32Grid& closest_triangles() {
    static const fabvdb::volume::SolidDistance distance = [] {
        openvdb::initialize();
        fabvdb::Progress progress;
        return fabvdb::volume::solid_distance(outer, 0.5, 8.0, progress);
    }();
    return *distance.closest_triangle;
}

SnapStats snap(Mesh& cavity, double wall, OffsetSnap mode) {
    fabvdb::Progress progress;
    return fabvdb::volume::snap_to_offset(cavity, outer, closest_triangles(), wall, mode, progress);
}

void expect_vertices(const Mesh& mesh, const std::vector<Vec3>& expected) {
    ASSERT_EQ(mesh.vertices.size(), expected.size());
    for (size_t v = 0; v < expected.size(); ++v)
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(mesh.vertices[v][k], expected[v][k], 1e-9) << "vertex " << v;
}

}  // namespace

TEST(SnapToOffset, ExactModeMovesEveryCornerToTheWall) {
    Mesh cavity = fabvdb::test::make_octahedron({0, 0, 0}, 6, 6);
    const SnapStats stats = snap(cavity, 2.0, OffsetSnap::exact);
    expect_vertices(cavity, fabvdb::test::make_octahedron({0, 0, 0}, 8, 8).vertices);
    EXPECT_EQ(stats.moved, 6u);
    EXPECT_EQ(stats.kept_back, 0u);
    EXPECT_NEAR(stats.min_depth, 2.0, 1e-9);
}

TEST(SnapToOffset, AtLeastModeMovesOnlyShallowCorners) {
    Mesh deep_enough = fabvdb::test::make_octahedron({0, 0, 0}, 6, 6);
    const SnapStats kept = snap(deep_enough, 2.0, OffsetSnap::at_least);
    expect_vertices(deep_enough, fabvdb::test::make_octahedron({0, 0, 0}, 6, 6).vertices);
    EXPECT_EQ(kept.moved, 0u);
    EXPECT_NEAR(kept.min_depth, 4.0, 1e-9);

    Mesh shallow = fabvdb::test::make_octahedron({0, 0, 0}, 6, 6);
    const SnapStats deepened = snap(shallow, 5.0, OffsetSnap::at_least);
    expect_vertices(shallow, fabvdb::test::make_octahedron({0, 0, 0}, 5, 5).vertices);
    EXPECT_EQ(deepened.moved, 6u);
    EXPECT_NEAR(deepened.min_depth, 5.0, 1e-9);
}

TEST(SnapToOffset, DeepAndShallowCornersBothReachTheWall) {
    // Centred at x = 2: corner (8, 0, 0) is 2 deep, (−4, 0, 0) is 6 deep, the
    // others 4 deep below the faces y, z = ±10.
    Mesh cavity = fabvdb::test::make_octahedron({2, 0, 0}, 6, 6);
    const SnapStats stats = snap(cavity, 3.0, OffsetSnap::exact);
    expect_vertices(cavity, {{7, 0, 0}, {2, 7, 0}, {-7, 0, 0}, {2, -7, 0}, {2, 0, 7}, {2, 0, -7}});
    EXPECT_EQ(stats.moved, 6u);
    EXPECT_NEAR(stats.min_depth, 3.0, 1e-9);
}

TEST(SnapToOffset, CollapsingSlabKeepsItsOrientation) {
    // A 0.5 mm slab cavity 1.5 to 2 mm under the top face: on the 3 mm offset
    // both its faces would lie in z = 7, its side triangles flat, so moves are
    // undone until no triangle turns; a vertex ends either where it was or on
    // the offset, and its depth is 10 − z (the top face is nearest).
    const Mesh slab = fabvdb::test::make_box({-2, -2, 8}, {2, 2, 8.5});
    Mesh cavity = slab;
    const SnapStats stats = snap(cavity, 3.0, OffsetSnap::exact);
    size_t moved = 0;
    double min_depth = 1e300;
    for (size_t v = 0; v < slab.vertices.size(); ++v) {
        const Vec3 &was = slab.vertices[v], &now = cavity.vertices[v];
        EXPECT_EQ(now[0], was[0]);
        EXPECT_EQ(now[1], was[1]);
        if (now[2] != was[2]) {
            ++moved;
            EXPECT_NEAR(now[2], 7.0, 1e-9) << "vertex " << v;
        }
        min_depth = std::min(min_depth, 10.0 - now[2]);
    }
    for (size_t t = 0; t < slab.triangles.size(); ++t) {
        const Vec3 n0 = fabvdb::triangle_normal(slab, slab.triangles[t]);
        const Vec3 n1 = fabvdb::triangle_normal(cavity, cavity.triangles[t]);
        EXPECT_GT(n0[0] * n1[0] + n0[1] * n1[1] + n0[2] * n1[2], 0.0) << "triangle " << t << " turned or collapsed";
    }
    EXPECT_LT(moved, 8u);
    EXPECT_EQ(stats.moved, moved);
    EXPECT_EQ(stats.moved + stats.kept_back, 8u);
    EXPECT_NEAR(stats.min_depth, min_depth, 1e-9);
}

TEST(SnapToOffset, CancelledRunThrowsCancelled) {
    Mesh cavity = fabvdb::test::make_octahedron({0, 0, 0}, 6, 6);
    std::atomic<bool> cancel{true};
    fabvdb::Progress cancelled(nullptr, nullptr, &cancel);
    try {
        fabvdb::volume::snap_to_offset(cavity, outer, closest_triangles(), 2.0, OffsetSnap::exact, cancelled);
        FAIL() << "no exception";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}
