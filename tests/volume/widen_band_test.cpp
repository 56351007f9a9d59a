// widen_band on level sets whose distance is known: a box (beside its flat
// faces the widened band is the true distance) and a sphere, each from
// OpenVDB's own meshToSignedDistanceField 3 voxels wide, widened to 8 voxels
// inside and 5 outside; every voxel in those widths active, not a fifth of
// a voxel nearer the surface than the analytic distance nor half a voxel
// farther, exact beside the box's faces, none beyond the widths;
// cancellation.
#include "volume/widen_band.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "core/error.h"
#include "support/plain_level_set.h"
#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

// Every voxel of the index box [lo, hi]: within the widths (a voxel short of
// them) it is active, its distance at most `under` nearer the surface than
// `exact` and under half a voxel farther, and within `tolerance` where
// `flat(c)`; a voxel beyond them is inactive; signs agree off the surface.
template <class Exact, class Flat>
void expect_widened(const openvdb::FloatGrid& grid, const openvdb::Coord& lo, const openvdb::Coord& hi,
                    const Exact& exact, const Flat& flat, double inside, double outside, double under,
                    double tolerance) {
    const double voxel = grid.voxelSize()[0];
    const auto accessor = grid.getConstAccessor();
    int checked = 0;
    for (openvdb::Coord c = lo; c.x() <= hi.x(); c.setX(c.x() + 1))
        for (c.setY(lo.y()); c.y() <= hi.y(); c.setY(c.y() + 1))
            for (c.setZ(lo.z()); c.z() <= hi.z(); c.setZ(c.z() + 1)) {
                const double expected = exact(grid.indexToWorld(c));
                const double actual = accessor.getValue(c);
                if (std::abs(expected) > 0.5 * voxel) ASSERT_EQ(expected < 0, actual < 0) << c;
                if (expected > -(inside - voxel) && expected < outside - voxel) {
                    ASSERT_TRUE(accessor.isValueOn(c)) << c << " at " << expected;
                    ASSERT_GE(std::abs(actual), std::abs(expected) - under) << c;
                    ASSERT_LT(std::abs(actual), std::abs(expected) + 0.5 * voxel) << c;
                    if (flat(c)) ASSERT_NEAR(actual, expected, tolerance) << c;
                    ++checked;
                }
                if (expected < -(inside + voxel) || expected > outside + voxel) ASSERT_FALSE(accessor.isValueOn(c)) << c;
            }
    EXPECT_GT(checked, 1000);
}

TEST(WidenBand, BoxIsItsDistanceFieldEightVoxelsInFiveOut) {
    const double voxel = 0.25;
    const Vec3 lo{0.03, -0.07, 0.011}, hi{8.0, 7.0, 6.0};
    const auto narrow = test::plain_level_set(test::make_box(lo, hi), voxel);
    Progress progress;
    const auto wide = widen_band(*narrow, 8, 5, progress);
    EXPECT_EQ(wide->getGridClass(), openvdb::GRID_LEVEL_SET);
    EXPECT_FLOAT_EQ(wide->background(), float(5 * voxel));
    // Beside a face: outside, out along one axis only and a voxel in from
    // the face's edges along the others; inside, nearer one face than any
    // other by two voxels.
    const auto beside_face = [&](const openvdb::Coord& c) {
        const openvdb::Vec3d p = wide->indexToWorld(c);
        int out = 0;
        double margin = 1e300, nearest = 1e300, second = 1e300;
        for (int k = 0; k < 3; ++k) {
            const double below = p[k] - lo[k], above = hi[k] - p[k];
            if (below < 0 || above < 0) ++out;
            else margin = std::min({margin, below, above});
            for (double d : {below, above}) {
                if (d < nearest) second = nearest, nearest = d;
                else second = std::min(second, d);
            }
        }
        return out == 1 ? margin > voxel : out == 0 && second - nearest > 2 * voxel;
    };
    expect_widened(*wide, openvdb::Coord(-10, -10, -10), openvdb::Coord(42, 38, 34),
                   [&](const openvdb::Vec3d& p) { return test::box_signed_distance({p[0], p[1], p[2]}, lo, hi); },
                   beside_face, 8 * voxel, 5 * voxel, 0.2 * voxel, 1e-4);
    // Deep inside, beyond the band: inside, at the interior width.
    EXPECT_FLOAT_EQ(wide->getConstAccessor().getValue(openvdb::Coord(16, 14, 12)), -float(8 * voxel));
}

TEST(WidenBand, SphereIsNearItsDistanceField) {
    const double voxel = 0.2, r = 5.0;
    const auto narrow = test::plain_level_set(test::make_sphere({0, 0, 0}, r, 5), voxel);
    Progress progress;
    const auto wide = widen_band(*narrow, 8, 5, progress);
    expect_widened(*wide, openvdb::Coord(-35, -35, -35), openvdb::Coord(35, 35, 35),
                   [&](const openvdb::Vec3d& p) { return p.length() - r; },
                   [](const openvdb::Coord&) { return false; }, 8 * voxel, 5 * voxel, 0.2 * voxel, 0.0);
}

TEST(WidenBand, Cancelled) {
    const auto narrow = test::plain_level_set(test::make_box({0, 0, 0}, {3, 3, 3}), 0.2);
    std::atomic<bool> cancel{true};
    Progress cancelled(nullptr, nullptr, &cancel);
    try {
        widen_band(*narrow, 8, 8, cancelled);
        FAIL() << "not cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
}  // namespace fabvdb::volume
