// hole_candidates on hand-placed patches in a box cavity [-10, 10]³ with a
// 3 mm wall (voxel 0.5): a hole on each face's centre, drilled out along the
// face, through ≈ 3 mm; refused when the wall is under half or over twice the
// nominal, when the normal faces out, from the middle of the cavity, when the
// drill ends in a second cavity, when a rim line (not the axis) meets a solid
// block, and near a keep-out sphere; an empty input and cancellation.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <utility>
#include <vector>

#include <openvdb/tools/Composite.h>

#include "cavity_shapes.h"
#include "core/error.h"
#include "core/progress.h"
#include "powder/hole_candidates.h"

namespace {

using fabvdb::Vec3;
using fabvdb::powder::CavityPatches;
using fabvdb::powder::DrainHole;
using fabvdb::powder::HoleCandidateOptions;
using fabvdb::powder::KeepOut;

constexpr double kVoxel = 0.5;
constexpr double kStep = 0.5 * kVoxel;  // the drill's sampling step

//! Patches with only what hole_candidates reads: site, normal (into the cavity), cavity.
CavityPatches patches_at(const std::vector<std::pair<Vec3, Vec3>>& site_and_normal, uint32_t cavity = 0) {
    CavityPatches patches;
    for (const auto& [site, normal] : site_and_normal) {
        patches.site.push_back(site);
        patches.centroid.push_back(site);
        patches.normal.push_back(normal);
        patches.area.push_back(1.0);
        patches.cavity.push_back(cavity);
        patches.neighbours.emplace_back();
    }
    patches.cavity_count = cavity + 1;
    return patches;
}

const fabvdb::test::HollowPart& room() {
    static const fabvdb::test::HollowPart part = fabvdb::test::boxes_cavity({{{-10, -10, -10}, {10, 10, 10}}}, 3.0, kVoxel);
    return part;
}

std::vector<DrainHole> candidates(const CavityPatches& patches, const fabvdb::test::HollowPart& part,
                                  const HoleCandidateOptions& options = {}, const KeepOut& keep_out = {}) {
    fabvdb::Progress progress;
    return fabvdb::powder::hole_candidates(patches, *part.shell, *part.part, keep_out, options, progress);
}

HoleCandidateOptions wall(double nominal, double diameter = 4.0) {
    HoleCandidateOptions options;
    options.nominal_wall = nominal;
    options.diameter = diameter;
    return options;
}

}  // namespace

TEST(HoleCandidates, EachFaceCentreIsDrilledStraightOutThroughTheWall) {
    const std::vector<std::pair<Vec3, Vec3>> faces{{{0, 0, -10}, {0, 0, 1}}, {{0, 0, 10}, {0, 0, -1}},
                                                   {{10, 0, 0}, {-1, 0, 0}}, {{-10, 0, 0}, {1, 0, 0}},
                                                   {{0, 10, 0}, {0, -1, 0}}, {{0, -10, 0}, {0, 1, 0}}};
    const std::vector<DrainHole> holes = candidates(patches_at(faces, 4), room(), wall(3.0, 4.0));
    ASSERT_EQ(holes.size(), 6u);
    for (size_t i = 0; i < holes.size(); ++i) {
        const DrainHole& hole = holes[i];
        EXPECT_EQ(hole.patch, i);
        EXPECT_EQ(hole.cavity, 4u);
        EXPECT_EQ(hole.center, faces[i].first);
        for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(hole.axis[k], -faces[i].second[k]) << "face " << i;
        EXPECT_EQ(hole.diameter, 4.0);
        // The wall is 3 mm; the drill finds its far side within a step.
        EXPECT_NEAR(hole.through, 3.0, kStep + 1e-6) << "face " << i;
        EXPECT_DOUBLE_EQ(hole.depth, hole.through + 4.0);
    }
}

TEST(HoleCandidates, TheWallMustBeBetweenHalfAndTwiceTheNominal) {
    const CavityPatches floor = patches_at({{{0, 0, -10}, {0, 0, 1}}});
    EXPECT_EQ(candidates(floor, room(), wall(1.75)).size(), 1u);  // 3 (+ a step) ≤ 3.5
    EXPECT_EQ(candidates(floor, room(), wall(5.0)).size(), 1u);  // 3 ≥ 2.5
    EXPECT_TRUE(candidates(floor, room(), wall(1.2)).empty());   // 3 > 2.4: a solid region
    EXPECT_TRUE(candidates(floor, room(), wall(8.0)).empty());   // 3 < 4: too thin
}

TEST(HoleCandidates, RefusesDrillsThatDoNotLeaveTheCavityThroughTheWall) {
    // Facing out of the cavity: the drill goes through the wall back into it.
    EXPECT_TRUE(candidates(patches_at({{{0, 0, -10}, {0, 0, -1}}}), room()).empty());
    // In the middle of the cavity: no wall within the lead-in.
    EXPECT_TRUE(candidates(patches_at({{{0, 0, 0}, {0, 0, 1}}}), room()).empty());
}

TEST(HoleCandidates, RefusesADrillEndingInAnotherCavity) {
    // Room A above room B, 3 mm of wall between (z ∈ [-3, 0]).
    const auto stacked =
        fabvdb::test::boxes_cavity({{{-10, -10, 0}, {10, 10, 10}}, {{-10, -10, -13}, {10, 10, -3}}}, 3.0, kVoxel);
    const auto holes = candidates(patches_at({{{0, 0, 0}, {0, 0, 1}}, {{0, 0, -13}, {0, 0, 1}}}), stacked);
    ASSERT_EQ(holes.size(), 1u);
    EXPECT_EQ(holes[0].patch, 1u);  // B's floor, whose drill comes out under the part
    EXPECT_NEAR(holes[0].through, 3.0, kStep + 1e-6);
}

TEST(HoleCandidates, EveryRimLineMustPassNotOnlyTheAxis) {
    // A solid block x ≥ 1 under the floor of the room: a floor hole at x = 0
    // has a clean axis, but the rim of a 4 mm drill reaches x ≈ 1.7 and runs
    // into the block; at x = -5 it clears it; a 2 mm drill at x = -0.5 only
    // reaches x ≈ 0.4 and passes.
    fabvdb::test::HollowPart part = room();
    auto solid = fabvdb::test::box({1, -13, -30}, {20, 13, -12}, kVoxel);
    auto with_block = part.part->deepCopy();
    openvdb::tools::csgUnion(*with_block, *solid);
    const auto blocked = fabvdb::test::finish(with_block, part.cavity->deepCopy());
    const CavityPatches floor =
        patches_at({{{0, 0, -10}, {0, 0, 1}}, {{-5, 0, -10}, {0, 0, 1}}, {{-0.5, 0, -10}, {0, 0, 1}},
                    {{3, 0, -10}, {0, 0, 1}}});
    auto holes = candidates(floor, blocked, wall(3.0, 4.0));
    ASSERT_EQ(holes.size(), 1u);
    EXPECT_EQ(holes[0].patch, 1u);
    holes = candidates(floor, blocked, wall(3.0, 2.0));
    ASSERT_EQ(holes.size(), 3u);
    EXPECT_EQ(holes[0].patch, 0u);
    EXPECT_EQ(holes[1].patch, 1u);
    EXPECT_EQ(holes[2].patch, 2u);
    EXPECT_DOUBLE_EQ(holes[2].depth, holes[2].through + 2.0);
    // Without the block all four pass.
    EXPECT_EQ(candidates(floor, room(), wall(3.0, 4.0)).size(), 4u);
}

TEST(HoleCandidates, KeepsAwayFromKeepOutSpheres) {
    const CavityPatches floor = patches_at({{{0, 0, -10}, {0, 0, 1}}});
    auto with_sphere = [&](const Vec3& center, double radius) {
        KeepOut keep_out;
        keep_out.spheres.push_back({center, radius});
        return candidates(floor, room(), wall(3.0, 4.0), keep_out).size();
    };
    // The hole's ends are (0, 0, -10) and (0, 0, ≈-13), its middle ≈ -11.5; radius 2.
    EXPECT_EQ(with_sphere({2.5, 0, -10}, 1.0), 0u);    // 2.5 from the site < 1 + 2
    EXPECT_EQ(with_sphere({0, 0, -11.5}, 0.5), 0u);    // on the middle
    EXPECT_EQ(with_sphere({0, 0, -15.5}, 1.0), 0u);    // ≤ 2.5 below the outer end < 1 + 2
    EXPECT_EQ(with_sphere({0, 0, -16.5}, 0.25), 1u);   // ≥ 3.25 below it > 0.25 + 2
    EXPECT_EQ(with_sphere({6, 0, -10}, 1.0), 1u);      // 6 from the site
    EXPECT_EQ(with_sphere({0, 0, 0}, 5.0), 1u);        // 10 from the site > 5 + 2
}

TEST(HoleCandidates, NoPatchesNoCandidates) {
    EXPECT_TRUE(candidates(CavityPatches{}, room()).empty());
}

TEST(HoleCandidates, CancelledRunsThrow) {
    std::atomic<bool> cancel{true};
    fabvdb::Progress progress(nullptr, nullptr, &cancel);
    try {
        fabvdb::powder::hole_candidates(patches_at({{{0, 0, -10}, {0, 0, 1}}}), *room().shell, *room().part, {}, {},
                                        progress);
        FAIL() << "a cancelled search returned";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}
