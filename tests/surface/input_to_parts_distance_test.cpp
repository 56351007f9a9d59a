// Distance from the input surface to the parts, against answers worked out
// by hand: a 10 mm square of two triangles over a part that is the same
// square with a 4 mm hole in the middle. Every input vertex lies on the part,
// yet the hole's centre is 2 mm from it, and the area-weighted mean is the
// hole's mean distance to its rim (side / 6) times its share of the area
// (16 / 100): 0.1067 mm. A second part under the hole takes the samples
// there; with parts that hold the input exactly, every distance is 0.
// Of an input made of two boxes, a part holding only the outer box
// reproduces the solid when the second box lies inside the first (its
// surface is left out), and misses it by up to 20 mm when it lies beside it.
// Of two boxes side by side, a part holding both and the slit between them
// reproduces the solid when the slit is narrower than 0.3 mm (no mold blade
// is that thin), and misses the slit's walls by up to 10 mm when it is 0.5 mm
// wide.
#include <gtest/gtest.h>

#include <vector>

#include "support/shapes.h"
#include "surface/input_to_parts_distance.h"

namespace {

using fabvdb::Mesh;

Mesh square(double lo, double hi, double z) {
    Mesh m;
    m.vertices = {{lo, lo, z}, {hi, lo, z}, {hi, hi, z}, {lo, hi, z}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

// The square [0, 10]² at z = 0 without the hole [3, 7]²: eight triangles.
Mesh ring() {
    Mesh m;
    m.vertices = {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}, {3, 3, 0}, {7, 3, 0}, {7, 7, 0}, {3, 7, 0}};
    for (uint32_t k = 0; k < 4; ++k) {
        const uint32_t next = (k + 1) % 4;
        m.triangles.push_back({k, next, 4 + next});
        m.triangles.push_back({k, 4 + next, 4 + k});
    }
    return m;
}

TEST(InputToPartsDistance, MeasuresInsideLargeTriangles) {
    fabvdb::Progress progress;
    const Mesh input = square(0, 10, 0), part = ring();
    const auto d = fabvdb::surface::input_to_parts_distance(input, {&part}, 0.05, progress);
    EXPECT_NEAR(d.max, 2.0, 0.05);
    EXPECT_LE(d.max, 2.0 + 1e-12);
    EXPECT_NEAR(d.mean, 4.0 / 6.0 * 16.0 / 100.0, 0.005);
    ASSERT_EQ(d.part_max.size(), 1u);
    EXPECT_EQ(d.part_max[0], d.max);
    EXPECT_EQ(d.part_mean[0], d.mean);
}

TEST(InputToPartsDistance, SamplesGoToTheNearestPart) {
    fabvdb::Progress progress;
    const Mesh input = square(0, 10, 0), outer = ring(), hole = square(3, 7, -0.5);
    const auto d = fabvdb::surface::input_to_parts_distance(input, {&outer, &hole}, 0.05, progress);
    EXPECT_NEAR(d.part_max[1], 0.5, 1e-9);   // the hole's samples, 0.5 mm above it
    EXPECT_NEAR(d.part_mean[1], 0.5, 0.02);  // those nearer the rim went to the ring
    EXPECT_LE(d.part_max[0], 0.5 + 1e-9);
    EXPECT_LT(d.mean, 0.5 * 16.0 / 100.0);
}

TEST(InputToPartsDistance, IsZeroOnTheInputItself) {
    fabvdb::Progress progress;
    const Mesh input = square(0, 10, 0), part = ring(), hole = square(3, 7, 0);
    const auto d = fabvdb::surface::input_to_parts_distance(input, {&part, &hole}, 0.3, progress);
    EXPECT_LT(d.max, 1e-12);
    EXPECT_LT(d.mean, 1e-12);
}

TEST(InputToPartsDistance, LeavesOutSurfaceTheInputsSolidEncloses) {
    fabvdb::Progress progress;
    const Mesh outer = fabvdb::test::make_box({0, 0, 0}, {20, 20, 20});
    const Mesh inside = fabvdb::test::merged(outer, fabvdb::test::make_box({5, 5, 5}, {15, 15, 15}));
    const auto enclosed = fabvdb::surface::input_to_parts_distance(inside, {&outer}, 0.5, progress);
    EXPECT_LT(enclosed.max, 1e-9);
    EXPECT_LT(enclosed.mean, 1e-9);
    EXPECT_GT(enclosed.enclosed_samples, 0u);

    const Mesh beside = fabvdb::test::merged(outer, fabvdb::test::make_box({30, 0, 0}, {40, 10, 10}));
    const auto apart = fabvdb::surface::input_to_parts_distance(beside, {&outer}, 0.5, progress);
    EXPECT_NEAR(apart.max, 20.0, 1e-9);
    EXPECT_EQ(apart.enclosed_samples, 0u);
}

TEST(InputToPartsDistance, LeavesOutTheWallsOfASlitNarrowerThanAMoldBlade) {
    fabvdb::Progress progress;
    for (const double width : {0.05, 0.2, 0.5}) {
        const Mesh input = fabvdb::test::merged(fabvdb::test::make_box({0, 0, 0}, {10, 20, 20}),
                                                fabvdb::test::make_box({10 + width, 0, 0}, {20 + width, 20, 20}));
        const Mesh part = fabvdb::test::make_box({0, 0, 0}, {20 + width, 20, 20});
        const auto d = fabvdb::surface::input_to_parts_distance(input, {&part}, 0.5, progress);
        if (width < 0.3) {
            EXPECT_LE(d.max, 0.25);
            EXPECT_GT(d.enclosed_samples, 0u);
        } else {
            EXPECT_GT(d.max, 9.5);  // the wall's centre: 10 mm from every face of the part
            EXPECT_EQ(d.enclosed_samples, 0u);
        }
    }
}

}  // namespace
