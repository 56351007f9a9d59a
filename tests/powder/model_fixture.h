//! Runs a check on the drainability model and hole candidates that the drain
//! plan builds for a hollow test part (cavity_shapes.h), gravity straight down,
//! one hole asked for: shared by the model's and the hole search's tests.
#pragma once

#include <gtest/gtest.h>

#include <vector>

#include "cavity_shapes.h"
#include "core/progress.h"
#include "powder/drain_plan.h"
#include "powder/drainability_model.h"

namespace fabvdb::test {

template <class Check>
void with_drainability_model(const HollowPart& part, size_t powder_samples, Check check) {
    powder::DrainPlanOptions options;
    options.patch_count = 600;
    options.powder_samples = powder_samples;
    options.nominal_wall = 2.5;
    options.orientations = {{0, 0, -1}};
    options.search.hole_count = 1;
    bool ran = false;
    options.inspect = [&](const powder::DrainabilityModel& model, const std::vector<powder::DrainHole>& candidates,
                          const powder::DrainPlan&) {
        ran = true;
        check(model, candidates);
    };
    Progress progress;
    powder::plan_drain_holes(*part.part, *part.cavity, *part.shell, options, progress);
    EXPECT_TRUE(ran);
}

}  // namespace fabvdb::test
