// build_fit: a part that fits as placed, one that fits only turned (and the
// turn returned maps its sides within the volume), and one too large in any
// quarter turn.
#include "check/build_fit.h"

#include <gtest/gtest.h>

namespace fabvdb::check {
namespace {

TEST(BuildFit, AsPlacedTurnedOrNot) {
    const Vec3 printer{250, 210, 220};
    const BuildFit placed = fit_build_volume({100, 100, 100}, printer);
    EXPECT_TRUE(placed.as_placed);
    EXPECT_TRUE(placed.turned);

    const Vec3 tall{100, 50, 240};
    const BuildFit turned = fit_build_volume(tall, printer);
    EXPECT_FALSE(turned.as_placed);
    ASSERT_TRUE(turned.turned);
    for (int k = 0; k < 3; ++k) EXPECT_LE(tall[turned.axes[k]], printer[k]) << k;

    const BuildFit none = fit_build_volume({260, 260, 10}, printer);
    EXPECT_FALSE(none.as_placed);
    EXPECT_FALSE(none.turned);
}

}  // namespace
}  // namespace fabvdb::check
