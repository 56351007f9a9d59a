// Moldability enforcement by sweeping: a ring standing on its side (a torus
// whose axis is perpendicular to d, so lines along d cross it four times)
// becomes a double height field along d that still contains the ring; the
// added volume avoids a keep-out solid, also one on a turned grid; checked on
// the grid's columns and by ray casting on the extracted mesh, not by
// anything the sweep computed.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <openvdb/tools/Composite.h>

#include "core/error.h"
#include "support/cgal_mesh.h"
#include "support/check_vec3.h"
#include "support/plain_level_set.h"
#include "support/ray_cast.h"
#include "support/shapes.h"
#include "volume/double_height_field_mesh.h"
#include "volume/extract_mesh.h"
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
using fabvdb::test::unit;
namespace cgal = fabvdb::test::cgal;

class Sweep : public ::testing::TestWithParam<Vec3> {
protected:
    static void SetUpTestSuite() { openvdb::initialize(); }
};

TEST_P(Sweep, RingBecomesDoubleHeightFieldContainingIt) {
    const Vec3 d = unit(GetParam());
    const Mesh ring = fabvdb::test::make_standing_torus(10.0, 3.0, 48, 24);
    // Premise: the ring is not a double height field along d.
    EXPECT_GT(fabvdb::test::check_double_height_field(ring, d, 40).lines_over_two, 10u);

    fabvdb::Progress progress;
    fabvdb::volume::SweepStats stats;
    auto swept = fabvdb::volume::sweep_double_height_field(*plain_level_set(ring, 0.4), d, {}, {}, progress, &stats);
    const Mesh result = fabvdb::volume::extract_mesh(*swept, 0.0, progress);

    // On the grid: its index z axis is d, and along every index column the
    // inside (negative) voxels form one run.
    const openvdb::Vec3d axis =
        swept->transform().indexToWorld(openvdb::Vec3d(0, 0, 1)) - swept->transform().indexToWorld(openvdb::Vec3d(0));
    EXPECT_NEAR(axis.dot(openvdb::Vec3d(d[0], d[1], d[2])), axis.length(), 1e-9 * axis.length());
    const openvdb::CoordBBox box = swept->evalActiveVoxelBoundingBox();
    auto access = swept->getConstAccessor();
    size_t columns = 0, split_columns = 0;
    for (int i = box.min().x(); i <= box.max().x(); ++i)
        for (int j = box.min().y(); j <= box.max().y(); ++j) {
            int runs = 0;
            bool inside = false;
            for (int k = box.min().z() - 1; k <= box.max().z() + 1; ++k) {
                const bool now = access.getValue(openvdb::Coord(i, j, k)) < 0;
                runs += now && !inside;
                inside = now;
            }
            columns += runs > 0;
            split_columns += runs > 1;
        }
    EXPECT_GT(columns, 500u);
    EXPECT_EQ(split_columns, 0u);

    // The extracted surface is closed and, but for voxel-scale corners of the
    // extraction, a double height field too.
    ASSERT_TRUE(fabvdb::test::closed_two_manifold(result));
    const auto check = fabvdb::test::check_double_height_field(result, d, 80);
    EXPECT_GT(check.lines, 1000u);
    EXPECT_LE(check.lines_over_two, check.lines / 500) << "max crossings " << check.max_crossings;
    EXPECT_EQ(check.odd_lines, 0u);

    // The result contains the ring: points well inside the ring are inside it.
    fabvdb::test::LineCaster inside_result(result, {0.31, 0.17, 0.93});
    for (int i = 0; i < 64; ++i) {
        const double u = 2 * M_PI * i / 64;
        const Vec3 tube_center{10 * std::cos(u), 0.0, 10 * std::sin(u)};
        EXPECT_TRUE(inside_result.inside(tube_center)) << "tube point " << i;
    }
    const double ring_volume = fabvdb::test::mesh_volume(ring);
    const double result_volume = fabvdb::test::mesh_volume(result);
    EXPECT_GT(result_volume, 1.2 * ring_volume);
    EXPECT_NEAR(stats.volume_before, ring_volume, 0.03 * ring_volume);
    EXPECT_NEAR(stats.volume_after, result_volume, 0.02 * result_volume);
    EXPECT_NEAR(stats.added_volume, result_volume - ring_volume, 0.05 * (result_volume - ring_volume));
}

INSTANTIATE_TEST_SUITE_P(Directions, Sweep,
                         ::testing::Values(Vec3{0, 0, 1}, Vec3{0, 0, -1}, Vec3{1, 0, 0.3}, Vec3{0.3, -0.2, 1}));

// The ring's hole is filled by the sweep along z, except where `keep_out` (a
// block in the middle of the hole) lies.
void expect_ring_sweep_avoids_block(const openvdb::FloatGrid::ConstPtr& keep_out) {
    const Mesh ring = fabvdb::test::make_standing_torus(10.0, 3.0, 48, 24);
    fabvdb::Progress progress;
    fabvdb::volume::SweepStats stats;
    auto swept = fabvdb::volume::sweep_double_height_field(*plain_level_set(ring, 0.4), {0, 0, 1}, {keep_out}, {},
                                                           progress, &stats);
    const Mesh result = fabvdb::volume::extract_mesh(*swept, 0.0, progress);
    ASSERT_TRUE(fabvdb::test::closed_two_manifold(result));
    fabvdb::test::LineCaster caster(result, {0.31, 0.17, 0.93});
    for (double x = -3.5; x <= 3.5; x += 0.5)
        for (double z = -3.5; z <= 3.5; z += 0.5) EXPECT_FALSE(caster.inside({x, 0.1, z})) << x << " " << z;
    // Outside the block, the hole is still filled.
    EXPECT_TRUE(caster.inside({6.0, 0.1, 0.0}));
    EXPECT_GT(stats.removed_by_keep_out, 0.8 * 8 * 4 * 8);
}

Mesh block_in_the_ring() { return fabvdb::test::make_box({-4, -2, -4}, {4, 2, 4}); }

TEST(SweepKeepOut, AddedVolumeAvoidsOtherParts) {
    openvdb::initialize();
    expect_ring_sweep_avoids_block(plain_level_set(block_in_the_ring(), 0.4));
}

// Parts already swept lie on grids turned to their own directions.
TEST(SweepKeepOut, OtherPartOnATurnedGridIsAvoidedToo) {
    openvdb::initialize();
    const openvdb::math::Transform::Ptr turned = fabvdb::volume::aligned_transform(0.4, {1.0, 0.5, 0.2});
    expect_ring_sweep_avoids_block(plain_level_set(block_in_the_ring(), *turned));
}

// A block with a slot cut into its side, under the top: every column over the
// slot meets the block twice, so the sweep fills the slot and buries its
// surface up to the slot's depth. Given the input surface, the columns near
// the mouth are trimmed instead: the input surface (sampled on the block's
// and the slot's faces) then lies much nearer the part's surface (CGAL
// distances), the part is still a double height field (ray casting) and lies
// within the filled one.
TEST(SweepTrim, SlotUnderTheTopIsHalfTrimmedHalfFilled) {
    openvdb::initialize();
    const double voxel = 0.5;
    const Vec3 lo{-6, -10, 8}, hi{20, 10, 30};
    const double slot_back = 16.5, slot_y = 5, slot_floor = 18, slot_ceiling = 20;
    openvdb::FloatGrid::Ptr input = plain_level_set(fabvdb::test::make_box(lo, hi), voxel);
    openvdb::tools::csgDifference(
        *input, *plain_level_set(fabvdb::test::make_box({slot_back, -slot_y, slot_floor}, {hi[0] + 1, slot_y, slot_ceiling}),
                                 voxel));
    const Vec3 d{0, 0, 1};
    fabvdb::Progress progress;
    fabvdb::volume::SweepStats filled_stats, trimmed_stats;
    const auto filled_grid = fabvdb::volume::sweep_double_height_field(*input, d, {}, {}, progress, &filled_stats);
    fabvdb::volume::SweepOptions trimming;
    trimming.kept_surface = input.get();
    const auto trimmed_grid = fabvdb::volume::sweep_double_height_field(*input, d, {}, trimming, progress, &trimmed_stats);
    const Mesh filled = part_mesh(*filled_grid, progress, input.get());
    const Mesh trimmed = part_mesh(*trimmed_grid, progress, input.get());
    EXPECT_EQ(filled_stats.columns_trimmed, 0u);
    EXPECT_GT(trimmed_stats.columns_trimmed, 0u);

    // The input surface, sampled every 0.25 mm on each face.
    std::vector<Vec3> samples;
    const auto face = [&](int axis, double at, double u0, double u1, double v0, double v1,
                          const std::function<bool(double, double)>& skip) {
        for (double u = u0; u <= u1 + 1e-9; u += 0.25)
            for (double v = v0; v <= v1 + 1e-9; v += 0.25) {
                if (skip(u, v)) continue;
                Vec3 p;
                p[axis] = at;
                p[(axis + 1) % 3] = u;
                p[(axis + 2) % 3] = v;
                samples.push_back(p);
            }
    };
    const auto none = [](double, double) { return false; };
    const auto in_slot_yz = [&](double y, double z) {
        return std::abs(y) < slot_y && z > slot_floor && z < slot_ceiling;
    };
    // Axis x: (u, v) = (y, z); axis y: (z, x); axis z: (x, y).
    face(0, lo[0], lo[1], hi[1], lo[2], hi[2], none);
    face(0, hi[0], lo[1], hi[1], lo[2], hi[2], in_slot_yz);
    face(1, lo[1], lo[2], hi[2], lo[0], hi[0], none);
    face(1, hi[1], lo[2], hi[2], lo[0], hi[0], none);
    face(2, lo[2], lo[0], hi[0], lo[1], hi[1], none);
    face(2, hi[2], lo[0], hi[0], lo[1], hi[1], none);
    face(0, slot_back, -slot_y, slot_y, slot_floor, slot_ceiling, none);
    face(1, -slot_y, slot_floor, slot_ceiling, slot_back, hi[0], none);
    face(1, slot_y, slot_floor, slot_ceiling, slot_back, hi[0], none);
    face(2, slot_floor, slot_back, hi[0], -slot_y, slot_y, none);
    face(2, slot_ceiling, slot_back, hi[0], -slot_y, slot_y, none);

    const auto max_distance = [&](const Mesh& mesh) {
        const std::vector<cgal::Triangle3> triangles = cgal::triangles_of(mesh);
        cgal::Tree tree(triangles.begin(), triangles.end());
        tree.accelerate_distance_queries();
        double worst = 0;
        for (const Vec3& p : samples) worst = std::max(worst, std::sqrt(tree.squared_distance(cgal::point(p))));
        return worst;
    };
    const double slot_depth = hi[0] - slot_back;
    const double filled_max = max_distance(filled), trimmed_max = max_distance(trimmed);
    RecordProperty("filled_max_mm", std::to_string(filled_max));
    RecordProperty("trimmed_max_mm", std::to_string(trimmed_max));
    // Filled, the slot's back wall is buried its depth deep; trimmed near the
    // mouth, about half that, on both sides of the cut.
    EXPECT_GT(filled_max, 0.85 * slot_depth);
    EXPECT_LT(trimmed_max, 0.7 * slot_depth) << "filled " << filled_max;

    ASSERT_TRUE(fabvdb::test::closed_two_manifold(trimmed));
    const auto check = fabvdb::test::check_double_height_field(trimmed, d, 80);
    EXPECT_GT(check.lines, 1000u);
    EXPECT_EQ(check.lines_over_two, 0u) << "max crossings " << check.max_crossings;
    EXPECT_EQ(check.odd_lines, 0u);
    // Trimming only takes away from the filled part.
    fabvdb::test::LineCaster in_filled(filled, {0.31, 0.17, 0.93}), in_trimmed(trimmed, {0.29, -0.13, 0.95});
    size_t inside_trimmed = 0;
    for (double x = lo[0] + 0.13; x < hi[0]; x += 0.7)
        for (double y = lo[1] + 0.11; y < hi[1]; y += 0.7)
            for (double z = lo[2] + 0.17; z < hi[2]; z += 0.7) {
                if (!in_trimmed.inside({x, y, z})) continue;
                ++inside_trimmed;
                EXPECT_TRUE(in_filled.inside({x, y, z})) << x << " " << y << " " << z;
            }
    EXPECT_GT(inside_trimmed, 1000u);
}

// A thick ring standing on its side, swept nearly across its plane with the
// input surface to keep: the columns through the ring's hole near its inner
// rim are trimmed, and each gives up a thin edge of one arc. Those whose
// given-up edge would lie farther from the part than the column, filled,
// buries its surface are filled again, so the ring's surface stays within
// about 3 voxels of the part (CGAL distances from a finer ring's vertices;
// 1.43 mm when every such column stays trimmed, 1.19 mm with the refill).
TEST(SweepTrim, GivenUpEdgesOfAThickRingAreFilledAgain) {
    openvdb::initialize();
    const double voxel = 0.4, minor = 4.0;
    const Mesh ring = fabvdb::test::make_standing_torus(10.0, minor, 48, 24);
    const Vec3 d = unit({0.0, 0.2, 1.0});
    fabvdb::Progress progress;
    const auto input = plain_level_set(ring, voxel);
    fabvdb::volume::SweepOptions trimming;
    trimming.kept_surface = input.get();
    fabvdb::volume::SweepStats stats;
    const auto grid = fabvdb::volume::sweep_double_height_field(*input, d, {}, trimming, progress, &stats);
    const Mesh part = part_mesh(*grid, progress, input.get());
    EXPECT_GT(stats.columns_trimmed, 0u);
    ASSERT_TRUE(fabvdb::test::closed_two_manifold(part));
    const auto check = fabvdb::test::check_double_height_field(part, d, 80);
    EXPECT_GT(check.lines, 1000u);
    EXPECT_EQ(check.lines_over_two, 0u) << "max crossings " << check.max_crossings;

    const std::vector<cgal::Triangle3> triangles = cgal::triangles_of(part);
    cgal::Tree tree(triangles.begin(), triangles.end());
    tree.accelerate_distance_queries();
    double worst = 0;
    for (const Vec3& p : fabvdb::test::make_standing_torus(10.0, minor, 384, 192).vertices)
        worst = std::max(worst, std::sqrt(tree.squared_distance(cgal::point(p))));
    RecordProperty("worst_mm", std::to_string(worst));
    EXPECT_LT(worst, 3.25 * voxel);
}

TEST(SweepErrors, RejectsZeroDirectionAndFogVolumes) {
    openvdb::initialize();
    fabvdb::Progress progress;
    auto part = plain_level_set(fabvdb::test::make_box({0, 0, 0}, {2, 2, 2}), 0.5);
    EXPECT_THROW(fabvdb::volume::sweep_double_height_field(*part, {0, 0, 0}, {}, {}, progress), fabvdb::Error);
    openvdb::FloatGrid fog;
    EXPECT_THROW(fabvdb::volume::sweep_double_height_field(fog, {0, 0, 1}, {}, {}, progress), fabvdb::Error);
    fabvdb::volume::SweepOptions tight;
    tight.memory_budget_bytes = 1000;
    try {
        fabvdb::volume::sweep_double_height_field(*part, {0, 0, 1}, {}, tight, progress);
        FAIL() << "expected a budget error";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_OUT_OF_BUDGET);
    }
}

TEST(SweepErrors, CancelledSweepThrowsCancelled) {
    openvdb::initialize();
    std::atomic<bool> cancel{true};
    fabvdb::Progress progress(nullptr, nullptr, &cancel);
    auto part = plain_level_set(fabvdb::test::make_standing_torus(10.0, 3.0, 48, 24), 0.5);
    try {
        fabvdb::volume::sweep_double_height_field(*part, {0, 0, 1}, {}, {}, progress);
        FAIL() << "expected cancellation";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
