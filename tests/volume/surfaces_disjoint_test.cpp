// The wall separation proof: nested surfaces pass, the triangles of touching
// or crossing ones are flagged, whichever way the grid sorts them (fine meshes,
// and large triangles on either side, which the grid leaves to the exact
// test). The meshes are built so that the answer is known.
#include "volume/surfaces_disjoint.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>

#include "core/error.h"
#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

// How many cavity triangles touch the outer surface; checks the flags' size.
size_t touching(const Mesh& outer, const Mesh& cavity) {
    Progress progress;
    const std::vector<char> flags = cavity_triangles_touching(outer, cavity, progress);
    EXPECT_EQ(flags.size(), cavity.triangles.size());
    return size_t(std::count(flags.begin(), flags.end(), 1));
}

TEST(SurfacesDisjoint, NestedSurfacesPass) {
    const Mesh ball = test::make_sphere({0, 0, 0}, 20, 5);
    EXPECT_EQ(touching(ball, test::make_sphere({0, 0, 0}, 17, 5)), 0u);
    // A fine cavity close under a box's large triangles, and a box cavity
    // (large triangles) in a fine ball.
    EXPECT_EQ(touching(test::make_box({-20, -20, -20}, {20, 20, 20}), test::make_sphere({0, 0, 0}, 19.9, 5)), 0u);
    EXPECT_EQ(touching(ball, test::make_box({-11, -11, -11}, {11, 11, 11})), 0u);
}

TEST(SurfacesDisjoint, TouchingOrCrossingTrianglesAreFlagged) {
    const Mesh ball = test::make_sphere({0, 0, 0}, 20, 5);
    // A small ball through the fine surface; the same through a box's face;
    // a box cavity whose corners poke through the ball.
    const Mesh poking = test::make_sphere({19, 0, 0}, 2, 3);
    EXPECT_GT(touching(ball, poking), 0u);
    EXPECT_LT(touching(ball, poking), poking.triangles.size());  // only those across the surface
    EXPECT_GT(touching(test::make_box({-20, -20, -20}, {20, 20, 20}), test::make_sphere({19, 3, 2}, 2, 3)), 0u);
    EXPECT_GT(touching(ball, test::make_box({-12, -12, -12}, {12, 12, 12})), 0u);
    // A box's large triangles among a fine ball's: the grid leaves them to
    // the exact test, which every cavity triangle meets.
    const Mesh ball_and_box = test::merged(ball, test::make_box({30, -10, -10}, {70, 10, 10}));
    EXPECT_GT(touching(ball_and_box, test::make_sphere({30, 1, 0.5}, 2, 3)), 0u);
    EXPECT_EQ(touching(ball_and_box, test::make_sphere({50, 1, 0.5}, 5, 3)), 0u);
    // Touching at a single point: a box corner on a box face.
    EXPECT_GT(touching(test::make_box({0, 0, 0}, {10, 10, 10}), test::make_box({2, 2, 2}, {10, 5, 5})), 0u);
}

TEST(SurfacesDisjoint, CancelledThrows) {
    std::atomic<bool> cancel{true};
    Progress progress(nullptr, nullptr, &cancel);
    try {
        cavity_triangles_touching(test::make_sphere({0, 0, 0}, 20, 3), test::make_sphere({0, 0, 0}, 17, 3),
                                  progress);
        ADD_FAILURE() << "not cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
}  // namespace fabvdb::volume
