// Memory estimate of a narrow band: the surface area of boxes and triangles
// by hand (duplicates counted), active voxels = area / voxel² × band width plus
// a fixed 4096, 48 bytes each, and the budget's voxel size rounded up to two
// significant digits, so its estimate fits and the next smaller size does not.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "support/shapes.h"
#include "volume/memory_estimate.h"

namespace {

using fabvdb::Mesh;
using fabvdb::test::make_box;
using fabvdb::test::make_sphere;
using fabvdb::test::merged;
using namespace fabvdb::volume;

TEST(SurfaceArea, BoxesAndTriangles) {
    EXPECT_NEAR(surface_area(make_box({0, 0, 0}, {2, 3, 4})), 2 * (6 + 8 + 12), 1e-12);
    EXPECT_NEAR(surface_area(make_box({-1, -1, -1}, {1, 1, 1})), 24.0, 1e-12);
    Mesh triangle;
    triangle.vertices = {{0, 0, 0}, {3, 0, 0}, {0, 4, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
    triangle.triangles = {{0, 1, 2}};
    EXPECT_NEAR(surface_area(triangle), 6.0, 1e-12);
    // A degenerate (collinear) triangle adds nothing; orientation does not matter.
    triangle.triangles = {{0, 2, 1}, {3, 4, 5}};
    EXPECT_NEAR(surface_area(triangle), 6.0, 1e-12);
}

TEST(SurfaceArea, DuplicatesCountAndEmptyIsZero) {
    const Mesh box = make_box({0, 0, 0}, {1, 1, 1});
    EXPECT_NEAR(surface_area(merged(box, box)), 12.0, 1e-12);
    Mesh twice = box;
    twice.triangles.insert(twice.triangles.end(), box.triangles.begin(), box.triangles.end());
    EXPECT_NEAR(surface_area(twice), 12.0, 1e-12);
    EXPECT_EQ(surface_area(Mesh{}), 0.0);
}

TEST(SurfaceArea, SphereIsJustUnderItsArea) {
    const double area = surface_area(make_sphere({1, 2, 3}, 5.0, 4));
    const double exact = 4.0 * M_PI * 25.0;
    EXPECT_LT(area, exact);
    EXPECT_GT(area, 0.99 * exact);
}

TEST(EstimateActiveVoxels, AreaOverVoxelSquaredTimesBandPlus4096) {
    // 52 mm² at 0.5 mm: 208 voxels of surface, 7 thick, plus 4096.
    EXPECT_EQ(estimate_active_voxels(52.0, 0.5, 3), 208u * 7u + 4096u);
    EXPECT_EQ(estimate_active_voxels(100.0, 1.0, 0), 100u + 4096u);
    EXPECT_EQ(estimate_active_voxels(0.0, 0.1, 3), 4096u);
    // Rounded down: 10 / 3² × 3 = 3.33.
    EXPECT_EQ(estimate_active_voxels(10.0, 3.0, 1), 3u + 4096u);
    // 1 m² at 1/16 mm with a band of 10: 2.56e8 × 21 = 5.376e9 voxels, beyond 32 bits.
    EXPECT_EQ(estimate_active_voxels(1e6, 0.0625, 10), 5376000000ull + 4096u);
}

TEST(EstimateLevelSetBytes, FortyEightBytesPerVoxel) {
    EXPECT_EQ(estimate_level_set_bytes(52.0, 0.5, 3), (208u * 7u + 4096u) * 48u);
    EXPECT_EQ(estimate_level_set_bytes(0.0, 1.0, 3), 4096u * 48u);
    // Halving the voxel quadruples the surface voxels.
    const uint64_t coarse = estimate_level_set_bytes(1e4, 1.0, 3) - 4096u * 48u;
    const uint64_t fine = estimate_level_set_bytes(1e4, 0.5, 3) - 4096u * 48u;
    EXPECT_EQ(fine, 4 * coarse);
}

TEST(VoxelSizeForBudget, RoundedUpToTwoSignificantDigits) {
    // 100 mm², band 3 (7 voxels thick), 2 403 158 bytes: 45 969.96 voxels
    // beyond the 4096, so sqrt(700 / 45969.96) = 0.12340 mm, rounded up to 0.13.
    EXPECT_NEAR(voxel_size_for_budget(100.0, 3, 2403158), 0.13, 1e-12);
    // 1e6 mm² in 8 GB: sqrt(7e6 / 166 662 570.7) = 0.20494 → 0.21.
    EXPECT_NEAR(voxel_size_for_budget(1e6, 3, 8000000000ull), 0.21, 1e-12);
    // 52 mm² in 1 GB: 0.0041804 → 0.0042.
    EXPECT_NEAR(voxel_size_for_budget(52.0, 3, 1000000000ull), 0.0042, 1e-15);
}

TEST(VoxelSizeForBudget, TheAnswerFitsAndASmallerStepDoesNot) {
    // 1e6 mm² in 8 GB: 0.21 mm needs 7.62 GB, 0.20 mm 8.40 GB.
    const double size = voxel_size_for_budget(1e6, 3, 8000000000ull);
    EXPECT_LE(estimate_level_set_bytes(1e6, size, 3), 8000000000ull);
    EXPECT_GT(estimate_level_set_bytes(1e6, size - 0.01, 3), 8000000000ull);
    EXPECT_EQ(estimate_level_set_bytes(1e6, 0.21, 3), 158734254ull * 48u);
    for (const double area : {1.0, 37.5, 2e3, 4.4e5}) {
        for (const uint64_t budget : {uint64_t(1) << 20, uint64_t(1) << 26, uint64_t(1) << 33}) {
            const double found = voxel_size_for_budget(area, 2, budget);
            SCOPED_TRACE(testing::Message() << "area " << area << " budget " << budget << " size " << found);
            ASSERT_GT(found, 0.0);
            EXPECT_LE(estimate_level_set_bytes(area, found, 2), budget);
            // Two significant digits: found / 10^(e-1) is a whole number from 10 to 100.
            const double scale = std::pow(10.0, std::floor(std::log10(found)) - 1.0);
            const double mantissa = found / scale;
            EXPECT_NEAR(mantissa, std::round(mantissa), 1e-6);
            // One step down in the second digit would not fit.
            EXPECT_GT(estimate_level_set_bytes(area, found - scale, 2), budget);
        }
    }
}

TEST(VoxelSizeForBudget, NoAnswerForATinyBudgetOrNoArea) {
    // The fixed 4096 voxels alone take 196 608 bytes.
    EXPECT_EQ(voxel_size_for_budget(100.0, 3, 4096u * 48u), 0.0);
    EXPECT_EQ(voxel_size_for_budget(100.0, 3, 1000), 0.0);
    EXPECT_EQ(voxel_size_for_budget(100.0, 3, 0), 0.0);
    EXPECT_EQ(voxel_size_for_budget(0.0, 3, 1ull << 30), 0.0);
    EXPECT_EQ(voxel_size_for_budget(-5.0, 3, 1ull << 30), 0.0);
}

}  // namespace
