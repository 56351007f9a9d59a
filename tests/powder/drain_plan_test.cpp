// Drain-hole planning on hollow parts from analytic level sets, checked by
// geometry the planner does not compute: where the holes are and which cavity
// they open into. Also cancellation.
#include <gtest/gtest.h>

#include <cmath>

#include "cavity_shapes.h"
#include "core/error.h"
#include "powder/drain_plan.h"

namespace {

using fabvdb::powder::DrainHole;

fabvdb::powder::DrainPlanOptions small_plan(int holes, double wall) {
    fabvdb::powder::DrainPlanOptions options;
    options.patch_count = 800;
    options.powder_samples = 20000;
    options.nominal_wall = wall;
    options.search.hole_count = holes;
    return options;
}

TEST(DrainPlan, HollowSphereHolesGoLowAndMoreHolesLeaveLess) {
    const auto part = fabvdb::test::hollow_sphere({0, 0, 0}, 15.0, 2.5, 0.5);
    double predicted[3] = {1, 1, 1};
    for (int k : {1, 2}) {
        fabvdb::Progress progress;
        const auto plan =
            fabvdb::powder::plan_drain_holes(*part.part, *part.cavity, *part.shell, small_plan(k, 2.5), progress);
        ASSERT_EQ(plan.holes.size(), size_t(k));
        predicted[k] = plan.evaluation.residual_fraction();
        // The first hole opens near the bottom of the cavity (radius 12.5) as printed.
        EXPECT_LT(plan.holes[0].center[2], -11.0);
        for (const DrainHole& hole : plan.holes) {
            const double r = std::sqrt(hole.center[0] * hole.center[0] + hole.center[1] * hole.center[1] +
                                       hole.center[2] * hole.center[2]);
            EXPECT_NEAR(r, 12.5, 0.5);  // on the cavity surface
            EXPECT_LT(hole.axis[2], 0.0);  // drilled outward, downward
        }
    }
    EXPECT_LT(predicted[2], predicted[1]);
    EXPECT_GT(predicted[1], 0.0);
}

TEST(DrainPlan, SeparateCavitiesEachGetHoles) {
    const auto part = fabvdb::test::two_hollow_spheres(10.0, 2.0, 0.5);
    fabvdb::Progress progress;
    const auto plan =
        fabvdb::powder::plan_drain_holes(*part.part, *part.cavity, *part.shell, small_plan(0, 2.0), progress);
    ASSERT_EQ(plan.patches.cavity_count, 2u);
    int near_first = 0, near_second = 0;
    for (const DrainHole& hole : plan.holes) {
        const double a = std::hypot(hole.center[0], std::hypot(hole.center[1], hole.center[2]));
        const double b = std::hypot(hole.center[0] - 25.0, std::hypot(hole.center[1], hole.center[2]));
        near_first += a < 9.0;
        near_second += b < 9.0;
    }
    EXPECT_GE(near_first, 2);
    EXPECT_GE(near_second, 2);
}

TEST(DrainPlan, CancelledPlanThrowsCancelled) {
    const auto part = fabvdb::test::hollow_sphere({0, 0, 0}, 15.0, 2.5, 0.5);
    std::atomic<bool> cancel{true};
    fabvdb::Progress progress(nullptr, nullptr, &cancel);
    try {
        fabvdb::powder::plan_drain_holes(*part.part, *part.cavity, *part.shell, small_plan(1, 2.5), progress);
        FAIL() << "a cancelled plan returned";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
