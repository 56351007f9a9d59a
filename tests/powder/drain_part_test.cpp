// fabvdb drain on meshes: a mesh that already is a hollow shell (outer
// sphere and an inward-facing inner sphere) is drilled as it is, not
// hollowed again: the cavity the model fills is the input's void, measured
// against the void's own volume; an inward shell of a dirty mesh is no
// void; a solid sphere is hollowed with the wall;
// with automatic holes the bunny's prediction ends under the target; over
// the shared models the search, the routine and the heat map agree with
// the one prediction; a void one voxel thin is drained, not refused; a
// void too small for a drain hole is filled, and the part comes back solid
// when no void takes one; a drilled part not faithful at the planning
// voxel is meshed finer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/mesh.h"
#include "io/mesh_io.h"
#include "powder/drain_part.h"
#include "support/shapes.h"

namespace {

fabvdb::powder::DrainPartOptions small_drain(int holes) {
    fabvdb::powder::DrainPartOptions options;
    options.wall = 3.0;
    options.voxel_size = 0.5;
    options.plan.patch_count = 600;
    options.plan.powder_samples = 20000;
    options.plan.search.hole_count = holes;
    return options;
}

TEST(DrainPart, HollowInputKeepsItsOwnCavity) {
    const fabvdb::Mesh inner = fabvdb::test::make_sphere({0, 0, 0}, 10.0, 4);
    const fabvdb::Mesh shell =
        fabvdb::test::merged(fabvdb::test::make_sphere({0, 0, 0}, 15.0, 4), fabvdb::test::flipped(inner));
    fabvdb::Progress progress;
    ASSERT_TRUE(fabvdb::powder::is_hollow_shell(shell, progress));
    const auto result = fabvdb::powder::drain_part(shell, small_drain(2), progress);
    EXPECT_TRUE(result.input_was_hollow);
    // Hollowed again with the 3 mm wall, the void would reach radius 12.
    const double void_volume = fabvdb::test::mesh_volume(inner);
    EXPECT_NEAR(result.plan.evaluation.total_volume, void_volume, 0.08 * void_volume);
    EXPECT_EQ(result.plan.holes.size(), 2u);
    for (const auto& hole : result.plan.holes)
        EXPECT_NEAR(std::hypot(hole.center[0], std::hypot(hole.center[1], hole.center[2])), 10.0, 0.6);
}

TEST(DrainPart, InvertedShellOfADirtyMeshIsNoVoid) {
    // An inward shell outside the part (as a CAD export with a flipped
    // body has): no void of a clean solid, so the part is hollowed.
    const fabvdb::Mesh dirty =
        fabvdb::test::merged(fabvdb::test::make_sphere({0, 0, 0}, 15.0, 4),
                             fabvdb::test::flipped(fabvdb::test::make_sphere({40, 0, 0}, 5.0, 3)));
    fabvdb::Progress progress;
    EXPECT_FALSE(fabvdb::powder::is_hollow_shell(dirty, progress));
}

TEST(DrainPart, VoidOneVoxelThinIsDrained) {
    // A 30 x 30 x 10 box around a 20 x 20 x 0.5 flat void, at 0.5 mm voxels.
    const fabvdb::Mesh inner = fabvdb::test::make_box({-10, -10, 4.75}, {10, 10, 5.25});
    const fabvdb::Mesh shell = fabvdb::test::merged(fabvdb::test::make_box({-15, -15, 0}, {15, 15, 10}),
                                                    fabvdb::test::flipped(inner));
    fabvdb::Progress progress;
    ASSERT_TRUE(fabvdb::powder::is_hollow_shell(shell, progress));
    const auto result = fabvdb::powder::drain_part(shell, small_drain(1), progress);
    EXPECT_TRUE(result.has_cavity);
    EXPECT_EQ(result.plan.holes.size(), 1u);
    EXPECT_GT(result.plan.evaluation.total_volume, 0.0);
}

// A 60 x 30 x 30 block with two inward-facing voids: a 22 mm cube behind
// 4 mm walls and a 4 mm cube 12 mm deep in the block, which no hole
// reaches through a wall under twice the nominal 3 mm. The small void is filled and the big
// one drilled; alone, the small void leaves the part solid and undrilled.
// Both with a warning, and the written part has no inward shell left.
TEST(DrainPart, VoidTooSmallForAHoleIsFilled) {
    const fabvdb::Mesh block = fabvdb::test::make_box({0, 0, 0}, {60, 30, 30});
    const fabvdb::Mesh big = fabvdb::test::flipped(fabvdb::test::make_box({4, 4, 4}, {26, 26, 26}));
    const fabvdb::Mesh small = fabvdb::test::flipped(fabvdb::test::make_box({40, 13, 13}, {44, 17, 17}));
    fabvdb::Progress progress;
    const auto both = fabvdb::powder::drain_part(fabvdb::test::merged(fabvdb::test::merged(block, big), small),
                                                 small_drain(2), progress);
    EXPECT_TRUE(both.has_cavity);
    EXPECT_EQ(both.plan.patches.cavity_count, 1u);
    ASSERT_EQ(both.plan.holes.size(), 2u);
    for (const auto& hole : both.plan.holes) EXPECT_LT(hole.center[0], 30.0);
    ASSERT_EQ(both.warnings.size(), 1u);
    EXPECT_NE(both.warnings[0].find("1 cavity"), std::string::npos) << both.warnings[0];
    const double big_volume = 22.0 * 22.0 * 22.0;
    EXPECT_NEAR(both.plan.evaluation.total_volume, big_volume, 0.1 * big_volume);

    const auto alone = fabvdb::powder::drain_part(fabvdb::test::merged(block, small), small_drain(2), progress);
    EXPECT_FALSE(alone.has_cavity);
    EXPECT_TRUE(alone.plan.holes.empty());
    ASSERT_EQ(alone.warnings.size(), 1u);
    EXPECT_NE(alone.warnings[0].find("returned solid"), std::string::npos) << alone.warnings[0];
    EXPECT_NEAR(fabvdb::test::mesh_volume(alone.drilled), 60.0 * 30.0 * 30.0, 0.01 * 60.0 * 30.0 * 30.0);
}

TEST(DrainPart, SolidInputIsHollowedWithTheWall) {
    const fabvdb::Mesh solid = fabvdb::test::make_sphere({0, 0, 0}, 15.0, 4);
    fabvdb::Progress progress;
    ASSERT_FALSE(fabvdb::powder::is_hollow_shell(solid, progress));
    const auto result = fabvdb::powder::drain_part(solid, small_drain(2), progress);
    EXPECT_FALSE(result.input_was_hollow);
    const double cavity = 4.0 / 3.0 * M_PI * 12.0 * 12.0 * 12.0;
    EXPECT_NEAR(result.plan.evaluation.total_volume, cavity, 0.1 * cavity);
}

// `path` under the shared data folder, scaled to `size` along its longest side.
fabvdb::Mesh shared_mesh(const std::string& path, double size) {
    fabvdb::Progress progress;
    fabvdb::Mesh mesh = fabvdb::io::read_mesh(std::string(FABVDB_SHARED_DATA) + "/" + path, progress);
    const fabvdb::BoundingBox box = fabvdb::bounding_box(mesh);
    const double longest = std::max({box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]});
    for (fabvdb::Vec3& p : mesh.vertices)
        for (int k = 0; k < 3; ++k) p[k] = (p[k] - box.min[k]) * size / longest;
    return mesh;
}

// Automatic mode stops once the prediction under the cleaning routine is
// under the target (or at the hole ceiling), and no hole can go: without
// any one of them (a cavity keeping its minimum) the routine's prediction
// would be over the target.
TEST(DrainPart, AutomaticHolesBringThePredictionUnderTheTarget) {
    fabvdb::Progress progress;
    fabvdb::powder::DrainPartOptions options;
    options.wall = 3.0;
    const auto result = fabvdb::powder::drain_part(shared_mesh("meshes/bunny.off", 80.0), options, progress);
    const auto& search = options.plan.search;
    ASSERT_EQ(search.hole_count, 0);
    RecordProperty("holes", std::to_string(result.plan.holes.size()));
    RecordProperty("routine_predicted", std::to_string(result.plan.routine_evaluation.residual_fraction()));
    EXPECT_TRUE(result.plan.routine_evaluation.residual_fraction() < search.target_residual_fraction ||
                int(result.plan.holes.size()) == search.max_holes)
        << result.plan.holes.size() << " holes, predicted " << result.plan.routine_evaluation.residual_fraction();
    EXPECT_GE(result.plan.holes.size(), size_t(search.min_per_cavity));
}

// Over the shared models, with 2 and 4 holes: the holes returned are never
// predicted to leave more powder than as many lowest-point holes, by the
// prediction the report gives (random routines); the recommended routine is
// predicted to leave no more than random routines do on average; and the
// heat map agrees with the prediction: its share that drains, averaged by
// the powder resting on each patch at the start, is the predicted drained
// fraction under the routine, and the powder it leaves on the patches adds
// up to the predicted residual.
TEST(DrainPart, OneModelForHolesRoutineAndHeatMap) {
    for (const char* name : {"bunny.off", "kitten.obj", "fertility.off", "spot.obj"})
        for (int holes : {2, 4}) {
            SCOPED_TRACE(std::string(name) + ", " + std::to_string(holes) + " holes");
            fabvdb::Progress progress;
            fabvdb::powder::DrainPartOptions options;
            options.wall = 3.0;
            options.plan.search.hole_count = holes;
            const auto plan = fabvdb::powder::drain_part(shared_mesh(std::string("meshes/") + name, 60.0), options, progress).plan;
            ASSERT_EQ(plan.holes.size(), plan.baseline.size());
            EXPECT_LE(plan.evaluation.residual_volume, plan.baseline_evaluation.residual_volume + 1e-9);
            EXPECT_LE(plan.routine_evaluation.residual_volume, plan.evaluation.residual_volume + 1e-9);
            const auto& map = plan.routine_evaluation;
            ASSERT_EQ(map.drained_share.size(), plan.patches.size());
            double initial = 0.0, drained = 0.0, left = 0.0;
            for (size_t j = 0; j < plan.patches.size(); ++j) {
                initial += map.initial_per_patch[j];
                drained += map.initial_per_patch[j] * map.drained_share[j];
                left += map.left_per_patch[j];
                EXPECT_LE(map.drained_share[j], 1.0 + 1e-12);
            }
            EXPECT_NEAR(initial, map.total_volume, 1e-6 * map.total_volume);
            EXPECT_NEAR(drained / initial, 1.0 - map.residual_fraction(), 1e-9);
            EXPECT_NEAR(left, map.residual_volume, 1e-9 * map.total_volume);
            ASSERT_EQ(plan.routine.size(), 9u);
        }
}

// A scanned brain at 60 mm: its repaired outer surface, snapped onto the
// scan, is faithful at the planning voxel of 0.5 mm, but the drilled part
// meshed again at that voxel rounds its folds off (2.15% of the surface
// farther than 1 mm, up to 2.75 mm); it is meshed again at 0.25 mm.
TEST(DrainPart, APartNotFaithfulAtThePlanningVoxelIsMeshedFiner) {
    fabvdb::Progress progress;
    fabvdb::powder::DrainPartOptions options = small_drain(1);
    options.wall = 2.0;
    const auto result = fabvdb::powder::drain_part(shared_mesh("corpus/brain.ply", 60.0), options, progress);
    EXPECT_TRUE(result.fidelity.passed) << result.fidelity.defect;
    EXPECT_DOUBLE_EQ(result.voxel_size, 0.5);
    EXPECT_LT(result.surface_voxel, 0.5);
    EXPECT_TRUE(std::any_of(result.warnings.begin(), result.warnings.end(), [](const std::string& w) {
        return w.find("at voxel 0.5 mm the drilled part was not the input's model") != std::string::npos;
    }));
}

}  // namespace
