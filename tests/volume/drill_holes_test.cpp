// drill_holes on the level set of a 10 mm box (0.25 mm voxels, 0.75 mm half
// band): a through hole of radius 2 removes π·2²·10 mm³ and a blind one half
// that; at voxels near the wall φ is exactly minus the distance to it; the
// input grid is untouched; a drill beside the solid or no drill changes
// nothing; zero length or radius is INVALID_ARGUMENT; cancellation throws.
#include "volume/drill_holes.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include <openvdb/tools/LevelSetMeasure.h>

#include "core/error.h"
#include "support/plain_level_set.h"
#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double voxel = 0.25;

openvdb::FloatGrid::Ptr box_grid() { return test::plain_level_set(test::make_box({0, 0, 0}, {10, 10, 10}), voxel); }

openvdb::FloatGrid::Ptr drilled(const openvdb::FloatGrid& grid, const std::vector<DrillCylinder>& cylinders) {
    Progress progress;
    return drill_holes(grid, cylinders, progress);
}

// The voxel at a world point that lies on a voxel centre.
openvdb::Coord at(double x, double y, double z) {
    return openvdb::Coord(int(std::lround(x / voxel)), int(std::lround(y / voxel)), int(std::lround(z / voxel)));
}

// Every active value inside the band, the background kept.
void expect_narrow_band(const openvdb::FloatGrid& grid, float background) {
    EXPECT_EQ(grid.background(), background);
    size_t outside = 0;
    for (auto it = grid.cbeginValueOn(); it; ++it) outside += !(std::abs(*it) < background);
    EXPECT_EQ(outside, 0u);
}

TEST(DrillHoles, ThroughHoleRemovesItsCylinder) {
    const auto box = box_grid();
    const double before = openvdb::tools::levelSetVolume(*box);
    ASSERT_NEAR(before, 1000.0, 5.0);
    // Along z through the middle, past both faces.
    const auto result = drilled(*box, {{{5, 5, -2}, {5, 5, 12}, 2.0}});
    const double removed = pi * 2.0 * 2.0 * 10.0;
    EXPECT_NEAR(openvdb::tools::levelSetVolume(*result), before - removed, 0.01 * removed);
    expect_narrow_band(*result, box->background());
    auto accessor = result->getConstAccessor();
    // On the axis, deep in the hole: outside (the background).
    EXPECT_GT(accessor.getValue(at(5, 5, 5)), 0.0f);
    EXPECT_FALSE(accessor.isValueOn(at(5, 5, 5)));
    // 1.5 from the axis, 0.5 inside the hole: φ = 0.5. 2.5 from it, 0.5 into
    // the material (3 from the box's faces, beyond the band): φ = −0.5.
    EXPECT_TRUE(accessor.isValueOn(at(6.5, 5, 5)));
    EXPECT_FLOAT_EQ(accessor.getValue(at(6.5, 5, 5)), 0.5f);
    EXPECT_TRUE(accessor.isValueOn(at(5, 7.5, 5)));
    EXPECT_FLOAT_EQ(accessor.getValue(at(5, 7.5, 5)), -0.5f);
    // Far from the hole the solid is as it was.
    EXPECT_EQ(accessor.getValue(at(1, 1, 5)), box->getConstAccessor().getValue(at(1, 1, 5)));
    EXPECT_LT(accessor.getValue(at(8.5, 8.5, 5)), 0.0f);
}

TEST(DrillHoles, BlindHoleStopsAtItsCap) {
    const auto box = box_grid();
    const double before = openvdb::tools::levelSetVolume(*box);
    // From above the top face down to z = 5: a flat-bottomed hole 5 deep.
    const auto result = drilled(*box, {{{5, 5, 12}, {5, 5, 5}, 2.0}});
    const double removed = pi * 2.0 * 2.0 * 5.0;
    EXPECT_NEAR(openvdb::tools::levelSetVolume(*result), before - removed, 0.01 * removed);
    auto accessor = result->getConstAccessor();
    EXPECT_GT(accessor.getValue(at(5, 5, 7)), 0.0f);
    // 0.5 below the hole's floor, on the axis: φ = −0.5; 3 below it, solid.
    EXPECT_FLOAT_EQ(accessor.getValue(at(5, 5, 4.5)), -0.5f);
    EXPECT_LT(accessor.getValue(at(5, 5, 2)), 0.0f);
}

TEST(DrillHoles, InputIsLeftAsItWas) {
    const auto box = box_grid();
    const auto copy = box->deepCopy();
    const auto result = drilled(*box, {{{5, 5, -2}, {5, 5, 12}, 2.0}, {{-1, 3, 3}, {11, 3, 3}, 1.0}});
    EXPECT_NE(result.get(), box.get());
    EXPECT_EQ(box->activeVoxelCount(), copy->activeVoxelCount());
    auto a = box->getConstAccessor();
    auto b = copy->getConstAccessor();
    for (auto it = copy->cbeginValueOn(); it; ++it) EXPECT_EQ(a.getValue(it.getCoord()), *it);
    EXPECT_EQ(a.getValue(at(5, 5, 5)), b.getValue(at(5, 5, 5)));
    EXPECT_LT(a.getValue(at(5, 5, 5)), 0.0f);
}

TEST(DrillHoles, DrillsAwayFromTheSolidChangeNothing) {
    const auto box = box_grid();
    const auto beside = drilled(*box, {{{20, 20, -2}, {20, 20, 12}, 1.0}});
    const auto none = drilled(*box, {});
    for (const auto& result : {beside, none}) {
        EXPECT_EQ(result->activeVoxelCount(), box->activeVoxelCount());
        auto accessor = result->getConstAccessor();
        for (auto it = box->cbeginValueOn(); it; ++it) EXPECT_EQ(accessor.getValue(it.getCoord()), *it);
        EXPECT_NEAR(openvdb::tools::levelSetVolume(*result), openvdb::tools::levelSetVolume(*box), 1e-6);
    }
}

TEST(DrillHoles, ZeroLengthOrRadiusIsInvalid) {
    const auto box = box_grid();
    const std::vector<std::vector<DrillCylinder>> bad = {
        {{{5, 5, 5}, {5, 5, 5}, 1.0}},
        {{{5, 5, 0}, {5, 5, 10}, 0.0}},
        {{{5, 5, 0}, {5, 5, 10}, -1.0}},
        {{{5, 5, 0}, {5, 5, 10}, std::nan("")}},
        // A good drill first: the bad one still fails the call.
        {{{2, 2, -1}, {2, 2, 11}, 1.0}, {{5, 5, 0}, {5, 5, 10}, 0.0}},
    };
    for (size_t i = 0; i < bad.size(); ++i) {
        try {
            drilled(*box, bad[i]);
            ADD_FAILURE() << "case " << i << " accepted";
        } catch (const Error& e) {
            EXPECT_EQ(e.status(), FABVDB_ERR_INVALID_ARGUMENT) << "case " << i;
            EXPECT_NE(std::string(e.what()).find("radius"), std::string::npos) << e.what();
        }
    }
    // The failed calls left the input as it was.
    EXPECT_LT(box->getConstAccessor().getValue(at(2, 2, 5)), 0.0f);
}

TEST(DrillHoles, CancelledThrows) {
    const auto box = box_grid();
    std::atomic<bool> cancel{true};
    Progress progress(nullptr, nullptr, &cancel);
    try {
        drill_holes(*box, {{{5, 5, -2}, {5, 5, 12}, 2.0}}, progress);
        ADD_FAILURE() << "not cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
}  // namespace fabvdb::volume
