//! build_orientation_flows on hand-built patches whose flow is worked out by
//! hand: a box room (a patch per face) empties onto its floor for gravity
//! down and onto its ceiling upside down, one flow per gravity in order; a
//! ridge between two floors that do not touch sends 2/3 of its powder to the
//! floor with twice the border (its main destination), the floors are two
//! regions and the ridge none; two floors side by side are one region.
//! Settle rows are stochastic. A cancelled run throws.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "core/error.h"
#include "powder/orientation_flows.h"
#include "support/hand_patches.h"
#include "support/shapes.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;
using fabvdb::powder::CavityPatches;
using fabvdb::powder::OrientationFlow;
using fabvdb::volume::SurfaceRayCaster;

std::vector<OrientationFlow> flows_of(const CavityPatches& patches, const Mesh& mesh, const std::vector<Vec3>& gravities) {
    const SurfaceRayCaster caster(mesh);
    fabvdb::Progress progress;
    return fabvdb::powder::build_orientation_flows(patches, caster, gravities, {}, progress);
}

//! Weight of column `to` in row `from` of the settle matrix (0 if absent).
double settle_share(const OrientationFlow& flow, uint32_t from, uint32_t to) {
    double share = 0;
    for (uint32_t e = flow.settle.row_start[from]; e < flow.settle.row_start[from + 1]; ++e)
        if (flow.settle.column[e] == to) share += flow.settle.weight[e];
    return share;
}

void expect_stochastic(const OrientationFlow& flow) {
    for (size_t i = 0; i < flow.settle.rows(); ++i) {
        double sum = 0;
        for (uint32_t e = flow.settle.row_start[i]; e < flow.settle.row_start[i + 1]; ++e) sum += flow.settle.weight[e];
        EXPECT_NEAR(sum, 1.0, 1e-6) << "row " << i;
    }
}

}  // namespace

TEST(OrientationFlows, RoomSettlesOnItsFloorOrItsCeilingPerGravity) {
    const CavityPatches patches = fabvdb::test::room_patches();
    const auto flows = flows_of(patches, fabvdb::test::make_box({-5, -3, 0}, {5, 3, 8}), {{0, 0, -1}, {0, 0, 1}});
    ASSERT_EQ(flows.size(), 2u);
    EXPECT_EQ(flows[0].gravity, (Vec3{0, 0, -1}));
    EXPECT_EQ(flows[1].gravity, (Vec3{0, 0, 1}));
    for (int k = 0; k < 2; ++k) {
        const uint32_t rest = k == 0 ? fabvdb::test::kFloor : fabvdb::test::kCeiling;
        const OrientationFlow& flow = flows[k];
        ASSERT_EQ(flow.settle.rows(), 6u);
        expect_stochastic(flow);
        for (uint32_t i = 0; i < 6; ++i) {
            EXPECT_NEAR(settle_share(flow, i, rest), 1.0, 1e-6) << "gravity " << k << " patch " << i;
            EXPECT_EQ(flow.main_destination[i], rest) << "gravity " << k << " patch " << i;
            EXPECT_EQ(flow.region[i], i == rest ? 0 : -1) << "gravity " << k << " patch " << i;
        }
    }
}

TEST(OrientationFlows, RidgeBetweenTwoFloorsFeedsBothAndTheyAreTwoRegions) {
    // Floors 0 and 1 at z 1 on either side of a ridge 2 at z 5 (facing up at
    // 45°), 5 away from each with a drop of 4: shares border × 4/5, borders
    // 2 and 1, so 2/3 and 1/3.
    const double s = std::sqrt(0.5);
    const CavityPatches patches = fabvdb::test::hand_patches({{{0, -3, 1}, {0, 0, 1}, 1, {{2, 2}}},
                                              {{0, 3, 1}, {0, 0, 1}, 1, {{2, 1}}},
                                              {{0, 0, 5}, {0, -s, s}, 1, {{0, 2}, {1, 1}}}},
                                             std::vector<uint32_t>(12, 0));
    const auto flows = flows_of(patches, fabvdb::test::make_box({0, 0, 0}, {1, 1, 1}), {{0, 0, -1}});
    ASSERT_EQ(flows.size(), 1u);
    const OrientationFlow& flow = flows[0];
    expect_stochastic(flow);
    EXPECT_NEAR(settle_share(flow, 2, 0), 2.0 / 3.0, 1e-6);
    EXPECT_NEAR(settle_share(flow, 2, 1), 1.0 / 3.0, 1e-6);
    EXPECT_EQ(flow.main_destination, (std::vector<uint32_t>{0, 1, 0}));
    EXPECT_EQ(flow.region, (std::vector<int32_t>{0, 1, -1}));
}

TEST(OrientationFlows, FloorsSideBySideAreOneRegion) {
    // Floors 0 and 1 share a border; floor 2 touches neither.
    const CavityPatches patches = fabvdb::test::hand_patches({{{0, 0, 0}, {0, 0, 1}, 1, {{1, 1}}},
                                              {{1, 0, 0}, {0, 0, 1}, 1, {{0, 1}}},
                                              {{9, 0, 0}, {0, 0, 1}, 1, {}}},
                                             std::vector<uint32_t>(12, 0));
    const auto flows = flows_of(patches, fabvdb::test::make_box({0, 0, 0}, {1, 1, 1}), {{0, 0, -1}});
    EXPECT_EQ(flows[0].region, (std::vector<int32_t>{0, 0, 1}));
    EXPECT_EQ(flows[0].main_destination, (std::vector<uint32_t>{0, 1, 2}));
}

TEST(OrientationFlows, CancelledRunThrowsCancelled) {
    const CavityPatches patches = fabvdb::test::room_patches();
    const SurfaceRayCaster caster(fabvdb::test::make_box({-5, -3, 0}, {5, 3, 8}));
    std::atomic<bool> cancel{true};
    fabvdb::Progress cancelled(nullptr, nullptr, &cancel);
    try {
        fabvdb::powder::build_orientation_flows(patches, caster, {{0, 0, -1}}, {}, cancelled);
        FAIL() << "no exception";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}
