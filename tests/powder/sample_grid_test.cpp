// The coarse powder sample grid: which samples each stride keeps (all
// coordinates multiples of it, negatives too, in powder order), their six
// neighbours against a brute-force search (kNoSample at holes, symmetric),
// the nearest kept sample against a brute-force search and none beyond two
// strides, and a stride under 1 is Error(INVALID_ARGUMENT).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/error.h"
#include "powder/sample_grid.h"

namespace {

using fabvdb::Vec3;
using fabvdb::powder::kNoSample;
using fabvdb::powder::PowderSamples;
using fabvdb::powder::sample_grid;
using Cell = std::array<int32_t, 3>;

//! Cells x in [-4, 4], y in [-3, 3], z in [0, 4] except `holes`, in a shuffled order.
PowderSamples block(const std::vector<Cell>& holes = {}) {
    PowderSamples powder;
    powder.origin = {1, 2, 3};
    powder.spacing = 0.5;
    std::vector<Cell> cells;
    for (int32_t x = -4; x <= 4; ++x)
        for (int32_t y = -3; y <= 3; ++y)
            for (int32_t z = 0; z <= 4; ++z)
                if (std::find(holes.begin(), holes.end(), Cell{x, y, z}) == holes.end()) cells.push_back({x, y, z});
    std::shuffle(cells.begin(), cells.end(), std::mt19937(3));
    for (const Cell& c : cells) {
        powder.cell.push_back(c);
        powder.position.push_back({1 + 0.5 * c[0], 2 + 0.5 * c[1], 3 + 0.5 * c[2]});
        powder.rest_patch.push_back(0);
    }
    powder.sample_volume = 0.125;
    return powder;
}

bool kept(const Cell& c, int stride) { return c[0] % stride == 0 && c[1] % stride == 0 && c[2] % stride == 0; }

TEST(SampleGrid, KeepsTheMultiplesOfTheStrideInPowderOrder) {
    const PowderSamples powder = block();
    for (const int stride : {1, 2, 3}) {
        const auto grid = sample_grid(powder, stride);
        EXPECT_EQ(grid.stride, stride);
        std::vector<uint32_t> expected;
        for (uint32_t s = 0; s < powder.cell.size(); ++s)
            if (kept(powder.cell[s], stride)) expected.push_back(s);
        EXPECT_EQ(grid.sample, expected) << "stride " << stride;
        EXPECT_EQ(grid.size(), expected.size());
        EXPECT_EQ(grid.neighbours.size(), expected.size());
    }
    // By count: 9 × 7 × 5 at stride 1; x in {-4, -2, 0, 2, 4}, y in {-2, 0, 2}, z in {0, 2, 4} at 2;
    // x in {-3, 0, 3}, y in {-3, 0, 3}, z in {0, 3} at 3; at 5 only (0, 0, 0).
    EXPECT_EQ(sample_grid(powder, 1).size(), 315u);
    EXPECT_EQ(sample_grid(powder, 2).size(), 45u);
    EXPECT_EQ(sample_grid(powder, 3).size(), 18u);
    EXPECT_EQ(sample_grid(powder, 5).size(), 1u);  // only (0, 0, 0)
}

TEST(SampleGrid, NeighboursAgreeWithABruteForceSearchAndAreSymmetric) {
    const PowderSamples powder = block({{0, 0, 2}, {2, 0, 2}, {-4, -2, 0}, {1, 1, 1}});
    for (const int stride : {1, 2}) {
        const auto grid = sample_grid(powder, stride);
        const int step[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        int missing = 0;
        for (size_t k = 0; k < grid.size(); ++k) {
            const Cell& c = powder.cell[grid.sample[k]];
            for (int d = 0; d < 6; ++d) {
                const Cell want{c[0] + stride * step[d][0], c[1] + stride * step[d][1], c[2] + stride * step[d][2]};
                uint32_t expected = kNoSample;
                for (size_t other = 0; other < grid.size(); ++other)
                    if (powder.cell[grid.sample[other]] == want) expected = uint32_t(other);
                ASSERT_EQ(grid.neighbours[k][d], expected) << "stride " << stride << " sample " << k << " side " << d;
                if (expected == kNoSample) {
                    ++missing;
                } else {
                    // The opposite side of the neighbour leads back.
                    EXPECT_EQ(grid.neighbours[expected][d ^ 1], uint32_t(k));
                }
            }
        }
        EXPECT_GT(missing, 0);
    }
}

TEST(SampleGrid, AHoleLeavesNoSampleOnItsSides) {
    // Stride 2: the hole at (0, 0, 2) is a kept cell; its neighbours along x are (±2, 0, 2).
    const PowderSamples powder = block({{0, 0, 2}});
    const auto grid = sample_grid(powder, 2);
    const auto index_of = [&](const Cell& c) {
        for (size_t k = 0; k < grid.size(); ++k)
            if (powder.cell[grid.sample[k]] == c) return uint32_t(k);
        return kNoSample;
    };
    ASSERT_EQ(index_of({0, 0, 2}), kNoSample);
    EXPECT_EQ(grid.neighbours[index_of({2, 0, 2})][1], kNoSample);   // -x
    EXPECT_EQ(grid.neighbours[index_of({-2, 0, 2})][0], kNoSample);  // +x
    EXPECT_EQ(grid.neighbours[index_of({0, 0, 0})][4], kNoSample);   // +z
    EXPECT_EQ(grid.neighbours[index_of({0, 0, 4})][5], kNoSample);   // -z
    EXPECT_EQ(grid.neighbours[index_of({0, 0, 0})][5], kNoSample);   // below the block
    EXPECT_EQ(grid.neighbours[index_of({0, 0, 0})][0], index_of({2, 0, 0}));
}

TEST(SampleGrid, NearestAgreesWithABruteForceSearch) {
    const PowderSamples powder = block({{0, 0, 2}, {1, 1, 1}, {2, 1, 1}});
    for (const int stride : {1, 2}) {
        const auto grid = sample_grid(powder, stride);
        std::mt19937 random(5);
        // Points within the block's extent (x 1 ± 2, y 2 ± 1.5, z 3 .. 5).
        std::uniform_real_distribution<double> x(-1, 3), y(0.5, 3.5), z(3, 5);
        for (int i = 0; i < 500; ++i) {
            const Vec3 p{x(random), y(random), z(random)};
            double best = HUGE_VAL;
            for (size_t k = 0; k < grid.size(); ++k) {
                const Vec3& q = powder.position[grid.sample[k]];
                best = std::min(best, std::hypot(q[0] - p[0], q[1] - p[1], q[2] - p[2]));
            }
            const uint32_t found = grid.nearest(p);
            ASSERT_NE(found, kNoSample);
            const Vec3& q = powder.position[grid.sample[found]];
            EXPECT_NEAR(std::hypot(q[0] - p[0], q[1] - p[1], q[2] - p[2]), best, 1e-12);
        }
    }
}

TEST(SampleGrid, NearestOnASampleIsThatSample) {
    const PowderSamples powder = block();
    const auto grid = sample_grid(powder, 2);
    for (size_t k = 0; k < grid.size(); ++k) EXPECT_EQ(grid.nearest(powder.position[grid.sample[k]]), uint32_t(k));
}

TEST(SampleGrid, NothingBeyondTwoStrides) {
    const PowderSamples powder = block();
    const auto grid = sample_grid(powder, 2);
    // The block's top kept layer is cell z 4 (world z 5); at stride 2 the search
    // reaches two strides (2 world units) past the nearest kept cell.
    EXPECT_NE(grid.nearest({1, 2, 6.9}), kNoSample);  // cell z 7.8 → 8: layer 4 is 2 strides away
    EXPECT_EQ(grid.nearest({1, 2, 7.6}), kNoSample);  // cell z 9.2 → 10: 3 strides
    EXPECT_EQ(grid.nearest({100, 2, 4}), kNoSample);
}

TEST(SampleGrid, NoSamples) {
    const PowderSamples powder;
    const auto grid = sample_grid(powder, 1);
    EXPECT_EQ(grid.size(), 0u);
    PowderSamples spaced;
    spaced.spacing = 1.0;
    EXPECT_EQ(sample_grid(spaced, 3).nearest({0, 0, 0}), kNoSample);
}

TEST(SampleGrid, AStrideUnderOneIsInvalid) {
    const PowderSamples powder = block();
    for (const int stride : {0, -1, -2}) {
        try {
            sample_grid(powder, stride);
            ADD_FAILURE() << "no error for stride " << stride;
        } catch (const fabvdb::Error& error) {
            EXPECT_EQ(error.status(), FABVDB_ERR_INVALID_ARGUMENT);
        }
    }
}

}  // namespace
