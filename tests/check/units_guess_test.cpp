// units_guess: a 50 mm part passes; the same part read as metres, inches
// and centimetres is flagged with the scale that restores 50 mm first among
// its readings (metres first below 1 mm, inches before centimetres); a huge
// part is offered micrometres; a size no reading fixes is flagged alone.
#include "check/units_guess.h"

#include <gtest/gtest.h>

namespace fabvdb::check {
namespace {

BoundingBox box_of(double x, double y, double z) {
    BoundingBox box;
    box.min = {-1.0, 2.0, 0.0};
    box.max = {-1.0 + x, 2.0 + y, z};
    return box;
}

TEST(UnitsGuess, MillimetresPass) {
    const UnitsGuess g = guess_units(box_of(50, 20, 10));
    EXPECT_FALSE(g.suspicious);
    EXPECT_DOUBLE_EQ(g.longest, 50.0);
    EXPECT_TRUE(g.readings.empty());
}

TEST(UnitsGuess, MetresInchesCentimetres) {
    const UnitsGuess metres = guess_units(box_of(0.05, 0.02, 0.01));
    ASSERT_TRUE(metres.suspicious);
    ASSERT_FALSE(metres.readings.empty());
    EXPECT_EQ(metres.readings[0].unit, "m");
    EXPECT_NEAR(metres.readings[0].longest, 50.0, 1e-9);

    const UnitsGuess inches = guess_units(box_of(50.0 / 25.4, 0.5, 0.4));
    ASSERT_TRUE(inches.suspicious);
    ASSERT_GE(inches.readings.size(), 2u);
    EXPECT_EQ(inches.readings[0].unit, "in");
    EXPECT_DOUBLE_EQ(inches.readings[0].scale, 25.4);
    EXPECT_NEAR(inches.readings[0].longest, 50.0, 1e-9);
    EXPECT_EQ(inches.readings[1].unit, "cm");

    const UnitsGuess huge = guess_units(box_of(50000, 10, 10));
    ASSERT_TRUE(huge.suspicious);
    ASSERT_EQ(huge.readings.size(), 1u);
    EXPECT_EQ(huge.readings[0].unit, "um");

    const UnitsGuess nothing = guess_units(box_of(0.001, 0.001, 0.001));
    EXPECT_TRUE(nothing.suspicious);
    EXPECT_TRUE(nothing.readings.empty());
}

}  // namespace
}  // namespace fabvdb::check
