// Powder coming to rest in its basins, against outcomes worked out by hand on
// a line of samples with two valleys (slides, fills from the bottom, spills
// over the saddle, passes samples without room, leaves when there is no room),
// and against a sort by height in a bowl (one basin: whatever the powder's
// start, it ends in the lowest samples), with mass kept or leaving exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <random>
#include <vector>

#include "powder/sample_grid.h"
#include "powder/settle_in_basins.h"
#include "powder/sublevel_forest.h"

namespace {

using fabvdb::powder::kNoSample;
using Neighbours = std::vector<std::array<uint32_t, 6>>;

//! Samples 0..n-1 on a line, each joined to the one before and after.
Neighbours line(size_t n) {
    Neighbours neighbours(n);
    for (size_t a = 0; a < n; ++a) {
        neighbours[a].fill(kNoSample);
        if (a + 1 < n) neighbours[a][0] = uint32_t(a + 1);
        if (a > 0) neighbours[a][1] = uint32_t(a - 1);
    }
    return neighbours;
}

//! Valley A (samples 0-4, lowest 2), a saddle at 5, valley B (6-9, lowest 8), a rise at 10.
const std::vector<float> kTwoValleys = {2, 1, 0, 1, 2, 3, 2.5f, 1.5f, 0.5f, 1.5f, 4};

struct Settled {
    std::vector<double> fill;
    double left = 0.0;
};

Settled settle(const std::vector<float>& height, std::vector<double> fill, const std::vector<uint32_t>& no_room_samples) {
    const Neighbours neighbours = line(height.size());
    const fabvdb::powder::SublevelForest forest = fabvdb::powder::sublevel_forest(neighbours, height);
    std::vector<uint64_t> no_room((height.size() + 63) / 64, 0);
    for (uint32_t a : no_room_samples) no_room[forest.rank[a] >> 6] |= uint64_t(1) << (forest.rank[a] & 63);
    fabvdb::powder::BasinFill basins(height.size());
    Settled result;
    result.left = basins.settle(forest.order, forest, fabvdb::powder::slide_targets(neighbours, forest), no_room, fill);
    result.fill = fill;
    return result;
}

TEST(SettleInBasins, PowderSlidesToTheBottomOfItsValley) {
    std::vector<double> fill(kTwoValleys.size(), 0.0);
    fill[0] = 1.0;  // high on valley A's side
    fill[10] = 0.5;  // on the rise above valley B
    const Settled settled = settle(kTwoValleys, fill, {});
    std::vector<double> expected(kTwoValleys.size(), 0.0);
    expected[2] = 1.0;
    expected[8] = 0.5;
    for (size_t a = 0; a < expected.size(); ++a) EXPECT_NEAR(settled.fill[a], expected[a], 1e-12) << a;
    EXPECT_NEAR(settled.left, 0.0, 1e-12);
}

TEST(SettleInBasins, AFullValleySpillsOverTheSaddleIntoTheNext) {
    // Valley A holds 5; it gets 6 (the saddle's powder slides into it too).
    std::vector<double> fill(kTwoValleys.size(), 0.0);
    for (size_t a = 0; a <= 5; ++a) fill[a] = 1.0;
    const Settled settled = settle(kTwoValleys, fill, {});
    std::vector<double> expected(kTwoValleys.size(), 0.0);
    for (size_t a = 0; a <= 4; ++a) expected[a] = 1.0;
    expected[8] = 1.0;  // the spill, at the bottom of valley B
    for (size_t a = 0; a < expected.size(); ++a) EXPECT_NEAR(settled.fill[a], expected[a], 1e-12) << a;
    EXPECT_NEAR(settled.left, 0.0, 1e-12);
}

TEST(SettleInBasins, PowderPassesSamplesWithoutRoomAndLeavesWhenNoneIsLeft) {
    std::vector<double> fill(kTwoValleys.size(), 0.0);
    fill[0] = 1.0;
    // Valley A's bottom holds nothing: the powder rests just above it.
    Settled settled = settle(kTwoValleys, fill, {2});
    EXPECT_NEAR(settled.fill[2], 0.0, 1e-12);
    EXPECT_NEAR(settled.fill[1] + settled.fill[3], 1.0, 1e-12);
    EXPECT_NEAR(settled.left, 0.0, 1e-12);
    // Room only at valley B's bottom: 3 given, 1 kept there, 2 leave.
    fill.assign(kTwoValleys.size(), 0.0);
    fill[0] = fill[1] = fill[6] = 1.0;
    std::vector<uint32_t> no_room;
    for (uint32_t a = 0; a < kTwoValleys.size(); ++a)
        if (a != 8) no_room.push_back(a);
    settled = settle(kTwoValleys, fill, no_room);
    for (size_t a = 0; a < kTwoValleys.size(); ++a) EXPECT_NEAR(settled.fill[a], a == 8 ? 1.0 : 0.0, 1e-12) << a;
    EXPECT_NEAR(settled.left, 2.0, 1e-12);
}

TEST(SettleInBasins, InABowlThePowderEndsInTheLowestSamples) {
    // A 9×9 bowl on a grid: one basin, so the powder, wherever it starts,
    // ends filling the samples lowest first (checked by sorting heights).
    const int n = 9;
    Neighbours neighbours(size_t(n * n));
    std::vector<float> height(size_t(n * n));
    for (int x = 0; x < n; ++x)
        for (int y = 0; y < n; ++y) {
            const size_t a = size_t(x * n + y);
            neighbours[a].fill(kNoSample);
            if (x + 1 < n) neighbours[a][0] = uint32_t(a + size_t(n));
            if (x > 0) neighbours[a][1] = uint32_t(a - size_t(n));
            if (y + 1 < n) neighbours[a][2] = uint32_t(a + 1);
            if (y > 0) neighbours[a][3] = uint32_t(a - 1);
            height[a] = float((x - 4) * (x - 4) + (y - 4) * (y - 4)) + 0.01f * float(a % 7);
        }
    const fabvdb::powder::SublevelForest forest = fabvdb::powder::sublevel_forest(neighbours, height);
    const std::vector<uint32_t> slide_to = fabvdb::powder::slide_targets(neighbours, forest);
    std::vector<uint32_t> by_height(height.size());
    std::iota(by_height.begin(), by_height.end(), 0u);
    std::sort(by_height.begin(), by_height.end(),
              [&](uint32_t a, uint32_t b) { return height[a] < height[b] || (height[a] == height[b] && a < b); });
    std::mt19937 generator(3);
    fabvdb::powder::BasinFill basins(height.size());
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<double> fill(height.size());
        double given = 0.0;
        for (double& f : fill) given += f = std::uniform_real_distribution<double>(0.0, 1.0)(generator) < 0.4 ? 1.0 : 0.0;
        const double left = basins.settle(forest.order, forest, slide_to, {}, fill);
        EXPECT_NEAR(left, 0.0, 1e-9);
        for (size_t k = 0; k < by_height.size(); ++k)
            EXPECT_NEAR(fill[by_height[k]], double(k) < given ? 1.0 : 0.0, 1e-9) << trial << " " << k;
    }
}

}  // namespace
