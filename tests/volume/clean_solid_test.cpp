// The clean-solid test: closed oriented solids pass; crossing shells,
// wherever the crossing lies along the part (the self-intersection test runs
// in slabs), open or inconsistently oriented surfaces fail. The meshes are
// built by hand, so the expected answer is known without running any test.
#include "volume/clean_solid.h"

#include <gtest/gtest.h>

#include <atomic>

#include "core/error.h"
#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

TEST(CleanSolid, ClosedOrientedSolidsPass) {
    Progress progress;
    EXPECT_TRUE(check_solid(test::make_box({0, 0, 0}, {80, 10, 10}), progress).clean);
    EXPECT_TRUE(check_solid(test::make_torus({0, 0, 0}, 20, 6, 64, 32), progress).clean);
    // A solid with a void: the void's shell faces inward.
    EXPECT_TRUE(check_solid(test::merged(test::make_box({0, 0, 0}, {30, 30, 30}),
                                         test::flipped(test::make_box({5, 5, 5}, {25, 25, 25}))),
                            progress)
                    .clean);
    // Two separate solids.
    EXPECT_TRUE(check_solid(
                    test::merged(test::make_box({0, 0, 0}, {10, 10, 10}), test::make_box({20, 0, 0}, {30, 10, 10})),
                    progress)
                    .clean);
}

TEST(CleanSolid, CrossingShellsFailWhereverTheCrossingLies) {
    Progress progress;
    const Mesh bar = test::make_box({0, 0, 0}, {80, 10, 10});
    // A small cube through the bar's top face, moved along the whole bar
    // (slab boundaries at multiples of 10 mm included).
    for (double x = -1.0; x <= 79.0; x += 2.5) {
        const Mesh crossing = test::merged(bar, test::make_box({x, 4, 8}, {x + 2, 6, 12}));
        const SolidCheck check = check_solid(crossing, progress);
        EXPECT_FALSE(check.clean) << "cube at x = " << x;
        // Closed, oriented and manifold otherwise: the crossings come back.
        EXPECT_FALSE(check.crossings.empty()) << "cube at x = " << x;
    }
    // Touching along a face counts as crossing too.
    EXPECT_FALSE(check_solid(test::merged(bar, test::make_box({40, 0, 10}, {42, 10, 12})), progress).clean);
}

TEST(CleanSolid, OpenOrMisorientedSurfacesFail) {
    Progress progress;
    Mesh open = test::make_box({0, 0, 0}, {10, 10, 10});
    open.triangles.pop_back();
    const SolidCheck open_check = check_solid(open, progress);
    EXPECT_FALSE(open_check.clean);
    EXPECT_TRUE(open_check.crossings.empty());  // not closed: not tested for crossings
    Mesh misoriented = test::make_box({0, 0, 0}, {10, 10, 10});
    std::swap(misoriented.triangles[0][1], misoriented.triangles[0][2]);
    EXPECT_FALSE(check_solid(misoriented, progress).clean);
    // Inside out as a whole: encloses no volume, as one shell and as a void
    // with no solid around it.
    EXPECT_FALSE(check_solid(test::flipped(test::make_box({0, 0, 0}, {10, 10, 10})), progress).clean);
    EXPECT_FALSE(check_solid(test::merged(test::flipped(test::make_box({0, 0, 0}, {30, 30, 30})),
                                          test::make_box({5, 5, 5}, {25, 25, 25})),
                             progress)
                     .clean);
    // A void outside the solid: a positive total volume, but no volume bounded.
    EXPECT_FALSE(check_solid(test::merged(test::make_box({0, 0, 0}, {30, 30, 30}),
                                          test::flipped(test::make_box({40, 0, 0}, {45, 5, 5}))),
                             progress)
                     .clean);
}

TEST(CleanSolid, CancelledThrows) {
    std::atomic<bool> cancel{true};
    Progress progress(nullptr, nullptr, &cancel);
    try {
        check_solid(test::make_box({0, 0, 0}, {80, 10, 10}), progress);
        ADD_FAILURE() << "not cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
}  // namespace fabvdb::volume
