//! drainability_model against hand-worked cases, on the model that
//! plan_drain_holes builds for a hollow sphere (cavity radius 12.5 mm) with
//! the operator turning it only to "as printed" (gravity −z):
//! - As printed, a hole at the bottom leaves the powder under the crater's
//!   cone rising at θ_r from the rim of its mouth: the share of the sphere
//!   under that cone, integrated here on a fine grid, about 4.5%.
//! - No hole keeps everything; adding a hole never keeps more; a hole at the
//!   top drains nothing as printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cavity_shapes.h"
#include "model_fixture.h"
#include "powder/drain_plan.h"

namespace {

using fabvdb::Vec3;
using fabvdb::powder::DrainabilityModel;
using fabvdb::powder::DrainHole;

constexpr double kRepose = 35.0 * M_PI / 180.0;
constexpr double kCavity = 12.5;

//! The model of a hollow sphere (radius 15, wall 2.5, voxel 0.5).
template <class Check>
void with_sphere_model(Check check) {
    fabvdb::test::with_drainability_model(fabvdb::test::hollow_sphere({0, 0, 0}, 15.0, 2.5, 0.5), 40000, check);
}

//! The candidate whose centre is lowest (or highest) along z.
const DrainHole& extreme(const std::vector<DrainHole>& candidates, bool lowest) {
    return *std::min_element(candidates.begin(), candidates.end(), [&](const DrainHole& a, const DrainHole& b) {
        return lowest ? a.center[2] < b.center[2] : a.center[2] > b.center[2];
    });
}

//! Share of a sphere of radius `r` (centre at the origin) under the cone of
//! slope θ_r rising from the rim (radius `mouth`) around `apex`, gravity −z.
double share_under_cone(double r, const Vec3& apex, double mouth) {
    const int n = 240;
    const double h = 2 * r / n, slope = std::tan(kRepose);
    double under = 0, all = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                const double x = -r + (i + 0.5) * h, y = -r + (j + 0.5) * h, z = -r + (k + 0.5) * h;
                if (x * x + y * y + z * z > r * r) continue;
                ++all;
                const double across = std::hypot(x - apex[0], y - apex[1]);
                const double rise = z - apex[2];
                const bool stays = across <= mouth ? rise < -mouth : rise < slope * (across - mouth);
                under += stays;
            }
    return under / all;
}

}  // namespace

TEST(DrainabilityModel, BottomHoleKeepsTheCraterRimAsPrinted) {
    with_sphere_model([](const DrainabilityModel& model, const std::vector<DrainHole>& candidates) {
        const DrainHole& bottom = extreme(candidates, true);
        ASSERT_LT(bottom.center[2], -kCavity + 0.5);
        ASSERT_TRUE(model.absorbing(bottom, {0, 0, -1}));
        const DrainabilityModel::Drain drained = model.drain(std::vector<DrainHole>{bottom});
        const double kept = 1.0 - drained.drained_first_volume / model.total_volume();
        const double expected = share_under_cone(kCavity, bottom.center, 0.5 * bottom.diameter);
        EXPECT_GT(expected, 0.03);
        EXPECT_LT(expected, 0.07);
        EXPECT_NEAR(kept, expected, 0.015);
    });
}

TEST(DrainabilityModel, MoreHolesNeverKeepMore) {
    with_sphere_model([](const DrainabilityModel& model, const std::vector<DrainHole>& candidates) {
        EXPECT_NEAR(model.evaluate(std::vector<DrainHole>{}).residual_fraction(), 1.0, 1e-9);
        const DrainHole& bottom = extreme(candidates, true);
        const DrainHole& top = extreme(candidates, false);
        ASSERT_GT(top.center[2], kCavity - 0.5);
        // As printed nothing reaches a hole at the top.
        EXPECT_EQ(model.drain(std::vector<DrainHole>{top}).drained_first_volume, 0.0);
        EXPECT_FALSE(model.absorbing(top, {0, 0, -1}));
        const double one = model.evaluate(std::vector<DrainHole>{bottom}).residual_fraction();
        const double two = model.evaluate(std::vector<DrainHole>{bottom, top}).residual_fraction();
        EXPECT_LT(one, 0.1);
        EXPECT_LE(two, one + 1e-12);
        const std::vector<DrainHole> bottom_only{bottom};
        EXPECT_NEAR(model.predicted_residual(model.drain(bottom_only)), model.evaluate(bottom_only).residual_volume,
                    1e-9 * model.total_volume());
        // The per-patch powder adds up to the cavity's at the start and to
        // the residual at the end.
        const auto evaluation = model.evaluate(std::vector<DrainHole>{bottom});
        double initial = 0.0, left = 0.0;
        for (double v : evaluation.initial_per_patch) initial += v;
        for (double v : evaluation.left_per_patch) left += v;
        EXPECT_NEAR(initial, model.total_volume(), 1e-9 * model.total_volume());
        EXPECT_NEAR(left, evaluation.residual_volume, 1e-9 * model.total_volume());
    });
}
