// The viridis colour map: its ends and middle are matplotlib's published
// colours (#440154, #21918c, #fde725), values between stops blend linearly,
// out-of-range values clamp, and green rises steadily along the map.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstdlib>

#include "core/colour_map.h"

namespace {

using Rgb = std::array<uint8_t, 3>;

TEST(ColourMap, EndsAndMiddleAreViridis) {
    EXPECT_EQ(fabvdb::viridis(0.0), (Rgb{0x44, 0x01, 0x54}));
    EXPECT_EQ(fabvdb::viridis(0.5), (Rgb{0x21, 0x91, 0x8c}));
    EXPECT_EQ(fabvdb::viridis(1.0), (Rgb{0xfd, 0xe7, 0x25}));
}

TEST(ColourMap, HalfwayBetweenStopsIsTheirMean) {
    // Stops at 0 and 0.1 are (0.267004, 0.004874, 0.329415) and
    // (0.282623, 0.140926, 0.457517); their means times 255 are 70.08, 18.59
    // and 100.33.
    EXPECT_EQ(fabvdb::viridis(0.05), (Rgb{70, 19, 100}));
    // Stops at 0.9 and 1: (0.741388, 0.873449, 0.149561) and
    // (0.993248, 0.906157, 0.143936): means times 255 are 221.16, 226.95, 37.42.
    EXPECT_EQ(fabvdb::viridis(0.95), (Rgb{221, 227, 37}));
}

TEST(ColourMap, OutOfRangeValuesClamp) {
    EXPECT_EQ(fabvdb::viridis(-0.5), fabvdb::viridis(0.0));
    EXPECT_EQ(fabvdb::viridis(-1e300), fabvdb::viridis(0.0));
    EXPECT_EQ(fabvdb::viridis(1.5), fabvdb::viridis(1.0));
    EXPECT_EQ(fabvdb::viridis(1e300), fabvdb::viridis(1.0));
}

TEST(ColourMap, GreenRisesAndNeighboursAreClose) {
    Rgb previous = fabvdb::viridis(0.0);
    for (int i = 1; i <= 1000; ++i) {
        const Rgb rgb = fabvdb::viridis(i / 1000.0);
        EXPECT_GE(rgb[1], previous[1]) << "at " << i / 1000.0;
        // Linear between stops 0.1 apart: no channel jumps in a 0.001 step.
        for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(int(rgb[k]) - int(previous[k])), 2) << "at " << i / 1000.0;
        previous = rgb;
    }
}

}  // namespace
