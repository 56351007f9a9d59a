//! settle_powder on hand-built powder (powder_block.h), cells 1 mm apart:
//! - A column of four under −z: powder on top falls to the bottom; two
//!   part-filled samples fill the bottom first, then the one above.
//! - A 3-wide, 3-high wall with a slot (x, z): the middle column holds only
//!   its top cell, so the left and right columns are two basins joined over
//!   the top. Powder on the left top falls into the left basin's room and
//!   never crosses into the empty right one, though it lies as low.
//! - A flat 5 × 1 layer under −z: nothing slides on a floor.
//! - A 5 × 1 × 3 box under gravity tilted 45° in x: powder slides down
//!   along the tilt, into the lower end; the sum is kept in every case.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "powder/settle_powder.h"
#include "powder_block.h"

namespace {

using namespace fabvdb::test;
using fabvdb::powder::settle_powder;

//! Powder per sample of cavity 0, in the later_local order, from powder per cell.
struct Fill {
    const SampleBlock& block;
    std::vector<double> value;
    explicit Fill(const SampleBlock& b) : block(b), value(b.powder.position.size(), 0.0) {}
    double& at(const Cell& cell) {
        for (size_t a = 0; a < block.powder.cell.size(); ++a)
            if (block.powder.cell[a] == cell) return value[block.samples.later_local[a]];
        throw std::logic_error("no sample at that cell");
    }
    double sum() const { return std::accumulate(value.begin(), value.end(), 0.0); }
};

}  // namespace

TEST(SettlePowder, PowderFallsDownAColumnLowestFirst) {
    const SampleBlock column(1, 1, 4, {{0, 0, -1}});
    Fill fill(column);
    fill.at({0, 0, 3}) = 1.0;
    settle_powder(column.samples, 0, 0, fill.value);
    EXPECT_DOUBLE_EQ(fill.at({0, 0, 0}), 1.0);
    EXPECT_DOUBLE_EQ(fill.at({0, 0, 3}), 0.0);
    EXPECT_DOUBLE_EQ(fill.sum(), 1.0);

    Fill part(column);
    part.at({0, 0, 2}) = 0.7;
    part.at({0, 0, 3}) = 0.5;
    settle_powder(column.samples, 0, 0, part.value);
    EXPECT_DOUBLE_EQ(part.at({0, 0, 0}), 1.0);
    EXPECT_NEAR(part.at({0, 0, 1}), 0.2, 1e-12);
    EXPECT_DOUBLE_EQ(part.at({0, 0, 2}), 0.0);
    EXPECT_DOUBLE_EQ(part.at({0, 0, 3}), 0.0);
}

TEST(SettlePowder, PowderNeverClimbsIntoAnotherBasin) {
    const SampleBlock wall(3, 1, 3, {{0, 0, -1}}, {0, 0, -1}, {{1, 0, 0}, {1, 0, 1}});
    Fill fill(wall);
    fill.at({0, 0, 0}) = 1.0;
    fill.at({0, 0, 2}) = 1.0;
    settle_powder(wall.samples, 0, 0, fill.value);
    EXPECT_DOUBLE_EQ(fill.at({0, 0, 0}), 1.0);
    EXPECT_DOUBLE_EQ(fill.at({0, 0, 1}), 1.0);
    EXPECT_DOUBLE_EQ(fill.at({0, 0, 2}), 0.0);
    for (int z = 0; z < 3; ++z) EXPECT_DOUBLE_EQ(fill.at({2, 0, z}), 0.0);
    EXPECT_DOUBLE_EQ(fill.at({1, 0, 2}), 0.0);
    EXPECT_DOUBLE_EQ(fill.sum(), 2.0);
}

TEST(SettlePowder, NothingSlidesOnAFloor) {
    const SampleBlock layer(5, 1, 1, {{0, 0, -1}});
    Fill fill(layer);
    fill.at({4, 0, 0}) = 1.0;
    fill.at({2, 0, 0}) = 0.5;
    const std::vector<double> before = fill.value;
    settle_powder(layer.samples, 0, 0, fill.value);
    EXPECT_EQ(fill.value, before);
}

TEST(SettlePowder, PowderSlidesAlongASteepTilt) {
    const double c = std::sqrt(0.5);
    const SampleBlock box(5, 1, 3, {{c, 0, -c}});  // down and toward +x, 45°
    Fill fill(box);
    fill.at({0, 0, 0}) = 1.0;
    fill.at({1, 0, 0}) = 1.0;
    settle_powder(box.samples, 0, 0, fill.value);
    // The lowest cell along gravity is (4, 0, 0); the powder fills it and its neighbour up the slope.
    EXPECT_DOUBLE_EQ(fill.at({4, 0, 0}), 1.0);
    EXPECT_DOUBLE_EQ(fill.at({0, 0, 0}) + fill.at({1, 0, 0}), 0.0);
    EXPECT_DOUBLE_EQ(fill.sum(), 2.0);
}
