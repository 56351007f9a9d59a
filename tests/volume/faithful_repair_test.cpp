// The repair held to the fidelity gate: a fin thinner than the voxel is
// lost and the repair refined until it is kept; surface that encloses
// nothing is not refined for; a refinement the memory budget refuses ends
// the attempts with the coarser one. Fins, sheets and budgets are built
// here; what is kept is read off the output's vertices.
#include "volume/faithful_repair.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "support/shapes.h"
#include "volume/memory_estimate.h"

namespace fabvdb::volume {
namespace {

// A 10 mm box with a fin 0.3 mm thick standing 6 mm out of its top,
// crossing into it (a dirty input: two crossing shells).
Mesh box_with_fin() {
    return test::merged(test::make_box({0, 0, 0}, {10, 10, 10}), test::make_box({2, 4.85, 8}, {8, 5.15, 16}));
}

RepairOptions at_voxel(double voxel) {
    RepairOptions options;
    options.distance.voxel_size = voxel;
    options.distance.input_name = "fin.stl";
    return options;
}

TEST(FaithfulRepair, AFinLostAtTheVoxelIsKeptAtAFinerOne) {
    Progress progress;
    const Mesh input = box_with_fin();
    const FaithfulRepair coarse = faithful_repair(input, input, at_voxel(0.8), 0, nullptr, progress);
    EXPECT_FALSE(coarse.fidelity.passed);  // the fin, 6 mm tall, is gone at 0.8 mm
    ASSERT_EQ(coarse.voxels.size(), 1u);
    const FaithfulRepair refined = faithful_repair(input, input, at_voxel(0.8), 2, nullptr, progress);
    EXPECT_TRUE(refined.fidelity.passed) << refined.fidelity.defect;
    ASSERT_GE(refined.voxels.size(), 2u);
    EXPECT_DOUBLE_EQ(refined.voxels[1], 0.4);
    EXPECT_EQ(refined.warnings.size(), refined.voxels.size() - 1);
    EXPECT_NE(refined.warnings[0].find("fin.stl: at voxel 0.8 mm"), std::string::npos) << refined.warnings[0];
    // The fin's top, 16 mm up, is on the refined surface, not on the coarse one.
    const auto top = [](const Mesh& mesh) {
        double z = -1e9;
        for (const Vec3& p : mesh.vertices) z = std::max(z, p[2]);
        return z;
    };
    EXPECT_GT(top(refined.repaired.mesh), 15.5);
    EXPECT_LT(top(coarse.repaired.mesh), 15.5);
}

// A box and an open sheet beside it: no voxel makes the sheet solid, so no
// refinement is tried.
TEST(FaithfulRepair, FarSheetsAreNotRefinedFor) {
    Progress progress;
    const Mesh input =
        test::merged(test::make_box({0, 0, 0}, {10, 10, 10}),
                     test::loose_triangles({{Vec3{20, 0, 0}, Vec3{30, 0, 0}, Vec3{30, 10, 0}},
                                            {Vec3{20, 0, 0}, Vec3{30, 10, 0}, Vec3{20, 10, 0}}}));
    const FaithfulRepair result = faithful_repair(input, input, at_voxel(0.4), 2, nullptr, progress);
    EXPECT_FALSE(result.fidelity.passed);
    EXPECT_EQ(result.voxels.size(), 1u);
    EXPECT_GT(result.fidelity.far_sheet_share, 0.1);
}

// A budget that holds the level set at 0.8 mm and not at 0.4 mm: the
// attempt at 0.8 mm stands, and its defect says why it was not refined.
TEST(FaithfulRepair, ARefinementTheBudgetRefusesEndsTheAttempts) {
    Progress progress;
    const Mesh input = box_with_fin();
    double area = 0.0;
    for (const Triangle& t : input.triangles) area += triangle_area(input, t);
    RepairOptions options = at_voxel(0.8);
    options.distance.memory_budget_bytes = 2 * estimate_level_set_bytes(area, 0.8, options.distance.half_band_voxels);
    ASSERT_GT(estimate_level_set_bytes(area, 0.4, options.distance.half_band_voxels),
              options.distance.memory_budget_bytes);
    const FaithfulRepair result = faithful_repair(input, input, options, 2, nullptr, progress);
    EXPECT_FALSE(result.fidelity.passed);
    ASSERT_EQ(result.voxels.size(), 1u);
    EXPECT_NE(result.fidelity.defect.find("at voxel 0.4 mm it would exceed the memory budget"), std::string::npos)
        << result.fidelity.defect;
    EXPECT_FALSE(result.repaired.mesh.triangles.empty());
}

}  // namespace
}  // namespace fabvdb::volume
