// Hand-over of the runs a part cannot keep: a box cut by a slab (part A)
// and the slab (part B), both molded along +Z. A's columns through the slab
// have a long run below it and a short one above; A keeps the lower, so
// without the hand-over the input's top face over the slab belongs to no
// part. Handed to B, the short runs continue B's own columns, and after
// sweeping again B reaches the top. Checked by the test support's ray
// casting of the meshed parts and by the volumes, not by the hand-over's own
// bookkeeping alone.
#include <gtest/gtest.h>

#include <atomic>

#include <openvdb/tools/Composite.h>

#include "core/error.h"
#include "support/plain_level_set.h"
#include "support/ray_cast.h"
#include "support/shapes.h"
#include "volume/double_height_field_mesh.h"
#include "volume/hand_over_runs.h"
#include "volume/sweep.h"

namespace {

//! The mesh of a swept part whose kept runs hold `level_set`'s zero crossings.
fabvdb::Mesh part_mesh(const openvdb::FloatGrid& swept, fabvdb::Progress& progress,
                       const openvdb::FloatGrid* level_set) {
    fabvdb::volume::InputSurface input;
    input.level_set = level_set;
    return fabvdb::volume::double_height_field_mesh(swept, progress, &input);
}

using fabvdb::Mesh;
using fabvdb::Vec3;
using fabvdb::test::plain_level_set;
using Grids = std::vector<openvdb::FloatGrid::Ptr>;

const double voxel = 0.4;

// Both parts swept along +Z in order, each kept out of the other (as made,
// or as its own material when still to come), as mold generation does.
Grids sweep_in_order(const Grids& own, fabvdb::Progress& progress, const openvdb::FloatGrid& input) {
    fabvdb::volume::SweepOptions options;
    options.kept_surface = &input;
    Grids made(own.size());
    for (size_t p = 0; p < own.size(); ++p) {
        std::vector<openvdb::FloatGrid::ConstPtr> keep_out;
        for (size_t q = 0; q < own.size(); ++q)
            if (q != p) keep_out.push_back(q < p ? made[q] : own[q]);
        made[p] = fabvdb::volume::sweep_double_height_field(*own[p], {0, 0, 1}, keep_out, options, progress);
    }
    return made;
}

class HandOverRuns : public ::testing::Test {
protected:
    static void SetUpTestSuite() { openvdb::initialize(); }
    void SetUp() override {
        input_ = plain_level_set(fabvdb::test::make_box({-6, -6, -6}, {6, 6, 6}), voxel);
        const Mesh slab = fabvdb::test::make_box({-3, -3, 1}, {3, 3, 3});
        openvdb::FloatGrid::Ptr box = input_->deepCopy();
        openvdb::tools::csgDifference(*box, *plain_level_set(slab, voxel));
        own_ = {box, plain_level_set(slab, voxel)};
    }
    openvdb::FloatGrid::Ptr input_;
    Grids own_;
};

TEST_F(HandOverRuns, RunsAboveTheSlabGoToTheSlabAndReachTheTopFace) {
    fabvdb::Progress progress;
    const Grids made = sweep_in_order(own_, progress, *input_);
    const Vec3 over_slab{0.1, 0.2, 5}, beside_slab{5, 5.1, 5}, under_slab{0.1, 0.2, -3};
    {
        // Without the hand-over, nothing holds the top face over the slab.
        const Mesh box = part_mesh(*made[0], progress, input_.get());
        const Mesh slab = part_mesh(*made[1], progress, input_.get());
        EXPECT_FALSE(fabvdb::test::LineCaster(box, {0.01, 0.02, 1}).inside(over_slab));
        EXPECT_FALSE(fabvdb::test::LineCaster(slab, {0.01, 0.02, 1}).inside(over_slab));
    }

    const fabvdb::volume::HandOver handed = fabvdb::volume::hand_over_unkept_runs(own_, made, input_.get(), progress);
    ASSERT_EQ(handed.parts.size(), 2u);
    const double above = 6 * 6 * 3;  // mm³ of the box over the slab
    EXPECT_NEAR(handed.given[0], above, 0.1 * above);
    EXPECT_NEAR(handed.received[1], above, 0.1 * above);
    EXPECT_EQ(handed.given[1], 0.0);
    EXPECT_EQ(handed.received[0], 0.0);

    const Grids again = sweep_in_order(handed.parts, progress, *input_);
    const Mesh box = part_mesh(*again[0], progress, input_.get());
    const Mesh slab = part_mesh(*again[1], progress, input_.get());
    const fabvdb::test::LineCaster box_lines(box, {0.01, 0.02, 1}), slab_lines(slab, {0.01, 0.02, 1});
    EXPECT_TRUE(slab_lines.inside(over_slab));
    EXPECT_FALSE(box_lines.inside(over_slab));
    EXPECT_TRUE(box_lines.inside(beside_slab));
    EXPECT_FALSE(slab_lines.inside(beside_slab));
    EXPECT_TRUE(box_lines.inside(under_slab));
    EXPECT_FALSE(slab_lines.inside(under_slab));
    // The top face over the slab is back: the slab part reaches z = 6.
    const std::vector<double> along = slab_lines.crossings({0.1, 0.2, 0});
    ASSERT_EQ(along.size(), 2u);
    EXPECT_NEAR(along.back(), 6.0, voxel);
    // Together the parts fill the box again, without overlap: as much as
    // the whole box meshed the same way (whose walls along Z the mesher
    // places from the columns' minima, a fraction of a voxel inside).
    const auto whole = fabvdb::volume::sweep_double_height_field(*input_, {0, 0, 1}, {}, {}, progress);
    const double expected = fabvdb::test::mesh_volume(
        part_mesh(*whole, progress, input_.get()));
    const double total = fabvdb::test::mesh_volume(box) + fabvdb::test::mesh_volume(slab);
    EXPECT_NEAR(total, expected, 0.01 * expected);
}

TEST_F(HandOverRuns, NothingIsGivenWhenEveryColumnHasOneRun) {
    fabvdb::Progress progress;
    // Side by side along X, no column meets both parts' material twice.
    const Grids own = {plain_level_set(fabvdb::test::make_box({-6, -6, -6}, {0, 6, 6}), voxel),
                       plain_level_set(fabvdb::test::make_box({0.2, -6, -6}, {6, 6, 6}), voxel)};
    const Grids made = sweep_in_order(own, progress, *input_);
    const fabvdb::volume::HandOver handed = fabvdb::volume::hand_over_unkept_runs(own, made, input_.get(), progress);
    EXPECT_EQ(handed.given[0], 0.0);
    EXPECT_EQ(handed.given[1], 0.0);
    EXPECT_EQ(handed.received[0] + handed.received[1], 0.0);
}

TEST_F(HandOverRuns, MismatchedListsAreRefusedAndCancelIsHonoured) {
    fabvdb::Progress progress;
    EXPECT_THROW(fabvdb::volume::hand_over_unkept_runs(own_, {own_[0]}, input_.get(), progress), fabvdb::Error);
    const Grids made = sweep_in_order(own_, progress, *input_);
    std::atomic<bool> cancel{true};
    fabvdb::Progress cancelled(nullptr, nullptr, &cancel);
    try {
        fabvdb::volume::hand_over_unkept_runs(own_, made, input_.get(), cancelled);
        FAIL() << "expected cancellation";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
