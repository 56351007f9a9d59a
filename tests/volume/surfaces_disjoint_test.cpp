// The wall separation proof: nested surfaces pass, touching or crossing ones
// throw INTERNAL, whichever way the grid sorts their triangles (fine meshes,
// and large triangles on either side, which the grid leaves to the exact
// test). The meshes are built so that the answer is known.
#include "volume/surfaces_disjoint.h"

#include <gtest/gtest.h>

#include <atomic>

#include "core/error.h"
#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

fabvdb_status status_of(const Mesh& outer, const Mesh& cavity) {
    Progress progress;
    try {
        require_disjoint_surfaces(outer, cavity, "test", progress);
    } catch (const Error& e) {
        return e.status();
    }
    return FABVDB_OK;
}

TEST(SurfacesDisjoint, NestedSurfacesPass) {
    const Mesh ball = test::make_sphere({0, 0, 0}, 20, 5);
    EXPECT_EQ(status_of(ball, test::make_sphere({0, 0, 0}, 17, 5)), FABVDB_OK);
    // A fine cavity close under a box's large triangles, and a box cavity
    // (large triangles) in a fine ball.
    EXPECT_EQ(status_of(test::make_box({-20, -20, -20}, {20, 20, 20}), test::make_sphere({0, 0, 0}, 19.9, 5)),
              FABVDB_OK);
    EXPECT_EQ(status_of(ball, test::make_box({-11, -11, -11}, {11, 11, 11})), FABVDB_OK);
}

TEST(SurfacesDisjoint, TouchingOrCrossingSurfacesThrow) {
    const Mesh ball = test::make_sphere({0, 0, 0}, 20, 5);
    // A small ball through the fine surface; the same through a box's face;
    // a box cavity whose corners poke through the ball.
    EXPECT_EQ(status_of(ball, test::make_sphere({19, 0, 0}, 2, 3)), FABVDB_ERR_INTERNAL);
    EXPECT_EQ(status_of(test::make_box({-20, -20, -20}, {20, 20, 20}), test::make_sphere({19, 3, 2}, 2, 3)),
              FABVDB_ERR_INTERNAL);
    EXPECT_EQ(status_of(ball, test::make_box({-12, -12, -12}, {12, 12, 12})), FABVDB_ERR_INTERNAL);
    // A box's large triangles among a fine ball's: the grid leaves them to
    // the exact test, which every cavity triangle meets.
    const Mesh ball_and_box = test::merged(ball, test::make_box({30, -10, -10}, {70, 10, 10}));
    EXPECT_EQ(status_of(ball_and_box, test::make_sphere({30, 1, 0.5}, 2, 3)), FABVDB_ERR_INTERNAL);
    EXPECT_EQ(status_of(ball_and_box, test::make_sphere({50, 1, 0.5}, 5, 3)), FABVDB_OK);
    // Touching at a single point: a box corner on a box face.
    EXPECT_EQ(status_of(test::make_box({0, 0, 0}, {10, 10, 10}), test::make_box({2, 2, 2}, {10, 5, 5})),
              FABVDB_ERR_INTERNAL);
}

TEST(SurfacesDisjoint, CancelledThrows) {
    std::atomic<bool> cancel{true};
    Progress progress(nullptr, nullptr, &cancel);
    try {
        require_disjoint_surfaces(test::make_sphere({0, 0, 0}, 20, 3), test::make_sphere({0, 0, 0}, 17, 3), "test",
                                  progress);
        ADD_FAILURE() << "not cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
}  // namespace fabvdb::volume
