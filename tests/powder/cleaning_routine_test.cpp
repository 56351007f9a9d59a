// The cleaning routine in words, on hand-worked cases: two holes on the
// axes of a part, gravity turned from -z to +x to +z; which hole points
// down, the tilt and the axis it turns about.
#include <gtest/gtest.h>

#include "powder/cleaning_routine.h"

namespace {

fabvdb::powder::DrainHole hole(fabvdb::Vec3 center, fabvdb::Vec3 axis) {
    fabvdb::powder::DrainHole h;
    h.center = center;
    h.axis = axis;
    return h;
}

TEST(CleaningRoutine, NamesTheHoleDownAndTheTilt) {
    // Hole 1 opens downwards (-z), hole 2 sideways (+x).
    const std::vector<fabvdb::powder::DrainHole> holes{hole({0, 0, -10}, {0, 0, -1}), hole({10, 0, 0}, {1, 0, 0})};
    const auto steps = fabvdb::powder::cleaning_steps(holes, {0, 0, -1}, {{1, 0, 0}, {0, 0, 1}, {0, 0, 1}, {0, 0, -1}});
    ASSERT_EQ(steps.size(), 5u);
    EXPECT_EQ(steps[0].hole_down, 0);
    EXPECT_NE(steps[0].instruction.find("as printed: hole 1 points down"), std::string::npos) << steps[0].instruction;
    // -z to +x: a quarter turn about -z × +x = -y.
    EXPECT_EQ(steps[1].hole_down, 1);
    EXPECT_NEAR(steps[1].tilt_degrees, 90.0, 1e-9);
    EXPECT_NEAR(steps[1].tilt_axis[1], -1.0, 1e-12);
    EXPECT_NE(steps[1].instruction.find("tilt the part 90 deg"), std::string::npos) << steps[1].instruction;
    // +x to +z: no hole's axis lies within 60° of +z; along +z, hole 2
    // (z = 0) lies lower than hole 1 (z = -10).
    EXPECT_EQ(steps[2].hole_down, -1);
    EXPECT_EQ(steps[2].lowest_hole, 1);
    EXPECT_NE(steps[2].instruction.find("no hole points down; hole 2 is lowest"), std::string::npos)
        << steps[2].instruction;
    // The same gravity again, then a half turn.
    EXPECT_NEAR(steps[3].tilt_degrees, 0.0, 1e-9);
    EXPECT_NE(steps[3].instruction.find("keep the part as it is"), std::string::npos);
    EXPECT_NEAR(steps[4].tilt_degrees, 180.0, 1e-9);
    EXPECT_NE(steps[4].instruction.find("upside down"), std::string::npos);
}

TEST(CleaningRoutine, NoHolesNamesNone) {
    const auto steps = fabvdb::powder::cleaning_steps({}, {0, 0, -1}, {{1, 0, 0}});
    ASSERT_EQ(steps.size(), 2u);
    EXPECT_EQ(steps[0].hole_down, -1);
    EXPECT_EQ(steps[0].lowest_hole, -1);
}

}  // namespace
