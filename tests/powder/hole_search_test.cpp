//! hole_search on the model of hollow spheres turned only to "as printed"
//! (gravity −z), where the answers are known by hand: one hole goes to the
//! bottom of the cavity (the lowest candidate, within the spacing of the
//! candidate groups); with two cavities and four holes each cavity gets its
//! minimum of two; no two holes are closer than the minimum spacing; the
//! result's evaluation is the model's own evaluation of the chosen holes;
//! in automatic mode the ceiling holds, and the last hole added never
//! predicts more than the set without it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cavity_shapes.h"
#include "model_fixture.h"
#include "powder/drain_plan.h"
#include "powder/hole_search.h"

namespace {

using fabvdb::powder::DrainabilityModel;
using fabvdb::powder::DrainHole;

double distance(const DrainHole& a, const DrainHole& b) {
    return std::sqrt(std::pow(a.center[0] - b.center[0], 2) + std::pow(a.center[1] - b.center[1], 2) +
                     std::pow(a.center[2] - b.center[2], 2));
}

void expect_spaced(const std::vector<DrainHole>& holes, double spacing) {
    for (size_t i = 0; i < holes.size(); ++i)
        for (size_t j = i + 1; j < holes.size(); ++j) EXPECT_GE(distance(holes[i], holes[j]), spacing - 1e-9);
}

}  // namespace

TEST(HoleSearch, OneHoleGoesToTheBottom) {
    fabvdb::test::with_drainability_model(fabvdb::test::hollow_sphere({0, 0, 0}, 15.0, 2.5, 0.5), 20000,
               [](const DrainabilityModel& model, const std::vector<DrainHole>& candidates) {
                   fabvdb::powder::HoleSearchOptions options;
                   options.hole_count = 1;
                   fabvdb::Progress progress;
                   const auto result =
                       fabvdb::powder::search_drain_holes(model, candidates, 1, {0, 0, -1}, options, progress);
                   ASSERT_EQ(result.holes.size(), 1u);
                   const double lowest =
                       std::min_element(candidates.begin(), candidates.end(), [](const DrainHole& a, const DrainHole& b) {
                           return a.center[2] < b.center[2];
                       })->center[2];
                   // The swaps move a hole within half the spacing; the bottom is
                   // flat enough there that it lands within 1 mm of the lowest height.
                   EXPECT_LT(result.holes[0].center[2], lowest + 1.0);
                   EXPECT_LT(result.holes[0].axis[2], -0.9);
                   EXPECT_NEAR(result.evaluation.residual_volume, model.evaluate(result.holes).residual_volume,
                               1e-9 * model.total_volume());
               });
}

TEST(HoleSearch, EachCavityGetsItsMinimum) {
    fabvdb::test::with_drainability_model(fabvdb::test::two_hollow_spheres(12.0, 2.5, 0.5), 20000,
               [](const DrainabilityModel& model, const std::vector<DrainHole>& candidates) {
                   fabvdb::powder::HoleSearchOptions options;
                   options.hole_count = 4;
                   options.min_center_distance = 8.0;
                   fabvdb::Progress progress;
                   const auto result =
                       fabvdb::powder::search_drain_holes(model, candidates, 2, {0, 0, -1}, options, progress);
                   ASSERT_EQ(result.holes.size(), 4u);
                   int per_sphere[2] = {0, 0};
                   int sphere_of_cavity[2] = {-1, -1};
                   for (const DrainHole& hole : result.holes) {
                       ASSERT_LT(hole.cavity, 2u);
                       // The sphere (centres x = 0 and x = 30) the hole opens into,
                       // on its cavity surface (radius 9.5), the same for one cavity id.
                       const int sphere = hole.center[0] < 15.0 ? 0 : 1;
                       const double r = std::sqrt(std::pow(hole.center[0] - 30.0 * sphere, 2) +
                                                  std::pow(hole.center[1], 2) + std::pow(hole.center[2], 2));
                       EXPECT_NEAR(r, 9.5, 0.6);
                       if (sphere_of_cavity[hole.cavity] < 0) sphere_of_cavity[hole.cavity] = sphere;
                       EXPECT_EQ(sphere_of_cavity[hole.cavity], sphere);
                       ++per_sphere[sphere];
                   }
                   EXPECT_EQ(per_sphere[0], 2);
                   EXPECT_EQ(per_sphere[1], 2);
                   expect_spaced(result.holes, options.min_center_distance);
               });
}

TEST(HoleSearch, AutomaticModeKeepsItsCeiling) {
    fabvdb::test::with_drainability_model(fabvdb::test::hollow_sphere({0, 0, 0}, 15.0, 2.5, 0.5), 20000,
               [](const DrainabilityModel& model, const std::vector<DrainHole>& candidates) {
                   fabvdb::powder::HoleSearchOptions options;
                   options.hole_count = 0;
                   options.min_per_cavity = 1;
                   options.max_holes = 5;
                   options.target_residual_fraction = 0.01;
                   fabvdb::Progress progress;
                   const auto result =
                       fabvdb::powder::search_drain_holes(model, candidates, 1, {0, 0, -1}, options, progress);
                   ASSERT_GE(result.holes.size(), 1u);
                   ASSERT_LE(result.holes.size(), 5u);
                   expect_spaced(result.holes, options.min_center_distance);
                   // Dropping the last hole never predicts less.
                   std::vector<DrainHole> fewer(result.holes.begin(), result.holes.end() - 1);
                   if (!fewer.empty())
                       EXPECT_GE(model.evaluate(fewer).residual_fraction() + 1e-12,
                                 result.evaluation.residual_fraction());
               });
}
