// find_cups on solids whose cups are known by construction: a 10 mm box with
// a 6 x 6 x 6 mm square pocket open along +z is a cup of 216 mm³ (opening
// 36 mm² at the rim) when built along +z (the pocket opens toward the vat);
// built along -z (it opens toward the plate) or along +x (sideways) it is
// none; a pocket through the box, a solid block, a pocket vented through its
// floor and a sealed cavity (left to trapped_volumes) hold none; the cell
// grows to keep the cell count; cancellation. The solids are unions of
// overlapping boxes, signed by the robust signed distance.
#include "check/resin_cups.h"

#include <gtest/gtest.h>

#include <atomic>

#include "core/error.h"
#include "support/shapes.h"
#include "volume/extract_mesh.h"
#include "volume/signed_distance.h"

namespace fabvdb::check {
namespace {

constexpr double kVoxel = 0.25;

//! A 10 x 10 x 8 mm box with a pocket [2, 8]² open at its top, its floor
//! 2 mm thick (`floor` false: the pocket goes through), vented by a square
//! hole `vent` mm wide in the middle of the floor (0: none).
Mesh pocketed_box(bool floor, double vent = 0.0) {
    Mesh m = test::make_box({0, 0, 0}, {2, 10, 8});
    m = test::merged(m, test::make_box({8, 0, 0}, {10, 10, 8}));
    m = test::merged(m, test::make_box({2, 0, 0}, {8, 2, 8}));
    m = test::merged(m, test::make_box({2, 8, 0}, {8, 10, 8}));
    if (!floor) return m;
    if (vent <= 0.0) return test::merged(m, test::make_box({2, 2, 0}, {8, 8, 2}));
    const double a = 5.0 - vent / 2, b = 5.0 + vent / 2;
    m = test::merged(m, test::make_box({2, 2, 0}, {a, 8, 2}));
    m = test::merged(m, test::make_box({b, 2, 0}, {8, 8, 2}));
    m = test::merged(m, test::make_box({a, 2, 0}, {b, a, 2}));
    return test::merged(m, test::make_box({a, b, 0}, {b, 8, 2}));
}

CupSearch cups_of(const Mesh& mesh, const Vec3& up, uint64_t max_cells = uint64_t(1) << 23) {
    volume::SignedDistanceOptions options;
    options.voxel_size = kVoxel;
    Progress progress;
    const auto grid = volume::signed_distance_from_mesh(mesh, options, progress);
    const Mesh surface = volume::extract_mesh(*grid, 0.0, progress);
    return find_cups(*grid, surface.vertices, up, max_cells, 1.0, progress);
}

TEST(ResinCups, PocketOpenTowardTheVatIsACup) {
    const CupSearch found = cups_of(pocketed_box(true), {0, 0, 1});
    EXPECT_DOUBLE_EQ(found.cell, kVoxel);
    ASSERT_EQ(found.cups.size(), 1u);
    const Cup& cup = found.cups[0];
    // 6 x 6 x 6 mm; the cells can miss one layer at the rim or the floor.
    EXPECT_NEAR(cup.volume, 216.0, 36.0 * kVoxel);
    EXPECT_NEAR(cup.opening_area, 36.0, 1e-9 + 4 * 6.0 * kVoxel);
    for (int k = 0; k < 2; ++k) {
        EXPECT_NEAR(cup.center[k], 5.0, 0.5 * kVoxel);
        EXPECT_NEAR(cup.opening_center[k], 5.0, 0.5 * kVoxel);
        EXPECT_NEAR(cup.box.min[k], 2.0, kVoxel);
        EXPECT_NEAR(cup.box.max[k], 8.0, kVoxel);
    }
    EXPECT_NEAR(cup.center[2], 5.0, kVoxel);
    EXPECT_NEAR(cup.opening_center[2], 8.0, kVoxel);  // the top layer of cells, under the rim
    EXPECT_NEAR(cup.box.min[2], 2.0, kVoxel);
    EXPECT_NEAR(cup.box.max[2], 8.0, kVoxel);
}

TEST(ResinCups, PocketOpenTowardThePlateOrSidewaysIsNone) {
    EXPECT_TRUE(cups_of(pocketed_box(true), {0, 0, -1}).cups.empty());
    EXPECT_TRUE(cups_of(pocketed_box(true), {1, 0, 0}).cups.empty());
    EXPECT_TRUE(cups_of(pocketed_box(true), {0, -1, 0}).cups.empty());
}

TEST(ResinCups, ThroughPocketSolidBlockVentAndSealedCavityAreNone) {
    EXPECT_TRUE(cups_of(pocketed_box(false), {0, 0, 1}).cups.empty());
    EXPECT_TRUE(cups_of(pocketed_box(false), {0, 0, -1}).cups.empty());
    EXPECT_TRUE(cups_of(test::make_box({0, 0, 0}, {10, 10, 8}), {0, 0, 1}).cups.empty());
    // A 1.5 mm vent (6 cells) through the floor lets the resin in from below.
    EXPECT_TRUE(cups_of(pocketed_box(true, 1.5), {0, 0, 1}).cups.empty());
    const Mesh hollow = test::merged(test::make_box({0, 0, 0}, {10, 10, 10}),
                                     test::flipped(test::make_box({2, 2, 2}, {8, 8, 8})));
    EXPECT_TRUE(cups_of(hollow, {0, 0, 1}).cups.empty());
}

TEST(ResinCups, TiltedBuildDirectionKeepsTheCupBelowTheRim) {
    // Tilted 30 degrees about x: the pocket still opens toward the vat, and
    // holds what lies under its rim's lowest edge in the tilted frame.
    const double s = 0.5, c = std::sqrt(3.0) / 2;
    const CupSearch found = cups_of(pocketed_box(true), {0, s, c});
    ASSERT_EQ(found.cups.size(), 1u);
    EXPECT_LT(found.cups[0].volume, 216.0);
    // The resin surface is the plane through the low rim edge (y = 2 or 8,
    // z = 8) at right angles to up; under it the pocket holds 216 minus the
    // wedge above: 6 · (6 · 6·tan30 / 2) = 62.4 mm³.
    const double wedge = 6.0 * 6.0 * 6.0 * std::tan(M_PI / 6) / 2;
    EXPECT_NEAR(found.cups[0].volume, 216.0 - wedge, 0.08 * 216.0);
}

TEST(ResinCups, CellGrowsToKeepTheCount) {
    const CupSearch found = cups_of(pocketed_box(true), {0, 0, 1}, 20000);
    EXPECT_GT(found.cell, kVoxel);
    EXPECT_LE(10.0 / found.cell + 3, 40.0);  // about 20000^(1/3) ≈ 27 cells across
    ASSERT_EQ(found.cups.size(), 1u);
    EXPECT_NEAR(found.cups[0].volume, 216.0, 0.25 * 216.0);
}

TEST(ResinCups, Cancellation) {
    volume::SignedDistanceOptions options;
    options.voxel_size = kVoxel;
    Progress progress;
    const auto grid = volume::signed_distance_from_mesh(pocketed_box(true), options, progress);
    const Mesh surface = volume::extract_mesh(*grid, 0.0, progress);
    std::atomic<bool> cancel{true};
    Progress cancelled(nullptr, nullptr, &cancel);
    try {
        find_cups(*grid, surface.vertices, {0, 0, 1}, uint64_t(1) << 23, 1.0, cancelled);
        FAIL() << "not cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
}  // namespace fabvdb::check
