//! drain_heat_map on the hand-built room (hand_patches.h), four powder
//! samples of 2 mm³: two on the floor (1 and 0.5 mm³ left), one on the
//! front wall (all left), one on the left wall (none left).
//! - Per patch: the floor holds 4 at the start, 1.5 at the end, share
//!   1 − 1.5 / 4 = 0.625; the front 0; the left wall 1.
//! - The ceiling, empty, stands in for by the floor: 0.625; the back stands
//!   in for itself, empty: the cavity's share 1 − 3.5 / 8 = 0.5625; the right
//!   wall stands in for by the empty ceiling: the cavity's share too.
//! - The per-patch powder adds up to 8 at the start and 3.5 at the end.
#include <gtest/gtest.h>

#include <vector>

#include "powder/drain_heat_map.h"
#include "support/hand_patches.h"

namespace {

using namespace fabvdb::test;
using fabvdb::powder::drain_heat_map;
using fabvdb::powder::DrainHeatMap;
using fabvdb::powder::PowderSamples;

}  // namespace

TEST(DrainHeatMap, SharesOfTheRoomByHand) {
    const auto patches = room_patches();
    PowderSamples powder;
    powder.position = {{-1, 0, 1}, {1, 0, 1}, {0, -2, 4}, {-4, 0, 4}};
    powder.rest_patch = {kFloor, kFloor, kFront, kLeft};
    powder.sample_volume = 2.0;
    const std::vector<double> left{1.0, 0.5, 2.0, 0.0};
    const std::vector<uint32_t> stand_in{kFloor, kFloor, kFront, kBack, kLeft, kCeiling};
    const DrainHeatMap map = drain_heat_map(patches, powder, left, stand_in);
    EXPECT_EQ(map.initial_per_patch, (std::vector<double>{4, 0, 2, 0, 2, 0}));
    EXPECT_EQ(map.left_per_patch, (std::vector<double>{1.5, 0, 2, 0, 0, 0}));
    EXPECT_DOUBLE_EQ(map.drained_share[kFloor], 0.625);
    EXPECT_DOUBLE_EQ(map.drained_share[kFront], 0.0);
    EXPECT_DOUBLE_EQ(map.drained_share[kLeft], 1.0);
    EXPECT_DOUBLE_EQ(map.drained_share[kCeiling], 0.625);
    EXPECT_DOUBLE_EQ(map.drained_share[kBack], 0.5625);
    EXPECT_DOUBLE_EQ(map.drained_share[kRight], 0.5625);
}

TEST(DrainHeatMap, AFilledRimDrainsANegativeShare) {
    const auto patches = room_patches();
    PowderSamples powder;
    powder.position = {{0, 0, 1}};
    powder.rest_patch = {kFloor};
    powder.sample_volume = 2.0;
    const std::vector<uint32_t> stand_in{kFloor, kFloor, kFloor, kFloor, kFloor, kFloor};
    const DrainHeatMap map = drain_heat_map(patches, powder, {3.0}, stand_in);
    EXPECT_DOUBLE_EQ(map.drained_share[kFloor], -0.5);
    EXPECT_DOUBLE_EQ(map.drained_share[kRight], -0.5);
}
