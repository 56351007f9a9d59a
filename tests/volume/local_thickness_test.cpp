// local_thickness on solids whose thickness is known by construction: a plate
// (every point, its corners and edges included, measures the plate within
// half a voxel), a tube wall, a pin, an L of two plates (no thin reading at
// its concave edge), a slot between two plates measured on the gap side, the
// cap (with the ball beside a thick face), and cancellation. The level sets come from OpenVDB's own
// meshToSignedDistanceField, not from fabvdb's signed distance.
#include "volume/local_thickness.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "core/error.h"
#include "support/plain_level_set.h"
#include "support/shapes.h"
#include "support/tube.h"

namespace fabvdb::volume {
namespace {

// An L of two plates of thickness t and length 10 meeting at a right angle
// in xz, 8 mm deep along y: one closed shell, facing out.
Mesh make_l(double t) {
    const double outline[6][2] = {{0, 0}, {10, 0}, {10, t}, {t, t}, {t, 10}, {0, 10}};
    Mesh mesh;
    for (double y : {0.0, 8.0})
        for (const auto& p : outline) mesh.vertices.push_back({p[0], y, p[1]});
    const uint32_t caps[4][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}};
    for (const auto& c : caps) {
        mesh.triangles.push_back({c[0], c[1], c[2]});
        mesh.triangles.push_back({c[0] + 6, c[2] + 6, c[1] + 6});
    }
    for (uint32_t i = 0; i < 6; ++i) {
        const uint32_t j = (i + 1) % 6;
        mesh.triangles.push_back({i, i + 6, j + 6});
        mesh.triangles.push_back({i, j + 6, j});
    }
    return test::mesh_volume(mesh) > 0 ? mesh : test::flipped(mesh);
}

// Points on the faces, edges and corners of the box [lo, hi].
std::vector<Vec3> box_points(const Vec3& lo, const Vec3& hi) {
    std::vector<Vec3> points;
    for (double fx : {0.0, 0.1, 0.5, 1.0})
        for (double fy : {0.0, 0.3, 1.0})
            for (double fz : {0.0, 1.0})
                points.push_back({lo[0] + fx * (hi[0] - lo[0]), lo[1] + fy * (hi[1] - lo[1]),
                                  lo[2] + fz * (hi[2] - lo[2])});
    return points;
}

TEST(LocalThickness, PlateMeasuresItsThicknessEverywhereWithinHalfAVoxel) {
    for (double voxel : {0.1, 0.17, 0.25}) {
        const double t = 1.3;
        const Vec3 lo{0.03, -0.07, 0.011}, hi{12.0, 9.0, 0.011 + t};
        const auto grid = test::plain_level_set(test::make_box(lo, hi), voxel, 1.5 + 5 * voxel);
        Progress progress;
        const auto points = box_points(lo, hi);
        const LocalThickness result = local_thickness(*grid, points, ThicknessSide::solid, 1.5, progress);
        for (size_t i = 0; i < points.size(); ++i) {
            EXPECT_NEAR(result.thickness[i], t, 0.5 * voxel)
                << "voxel " << voxel << " at " << points[i][0] << " " << points[i][1] << " " << points[i][2];
            EXPECT_EQ(result.capped[i], 0);
        }
    }
}

TEST(LocalThickness, TubeWallAndPinMeasureTheirThickness) {
    const double voxel = 0.1;
    {
        const Mesh tube = test::make_tube(4.0, 4.9, 6.0, 256);
        const auto grid = test::plain_level_set(tube, voxel, 2.0);
        std::vector<Vec3> points;
        for (int i = 0; i < 16; ++i) {
            const double a = 0.37 + 2.0 * M_PI * i / 16;
            for (double z : {0.0, 1.7, 3.0, 6.0}) {
                points.push_back({4.9 * std::cos(a), 4.9 * std::sin(a), z});
                points.push_back({4.0 * std::cos(a), 4.0 * std::sin(a), z});
            }
        }
        Progress progress;
        const LocalThickness result = local_thickness(*grid, points, ThicknessSide::solid, 1.5, progress);
        for (size_t i = 0; i < points.size(); ++i) EXPECT_NEAR(result.thickness[i], 0.9, 0.5 * voxel) << i;
    }
    {
        const Mesh pin = test::make_tube(0.0, 0.4, 5.0, 128);
        const auto grid = test::plain_level_set(pin, voxel, 1.2);
        std::vector<Vec3> points;
        for (int i = 0; i < 12; ++i) {
            const double a = 2.0 * M_PI * i / 12;
            for (double z : {0.5, 2.2, 4.5}) points.push_back({0.4 * std::cos(a), 0.4 * std::sin(a), z});
        }
        Progress progress;
        const LocalThickness result = local_thickness(*grid, points, ThicknessSide::solid, 1.0, progress);
        for (size_t i = 0; i < points.size(); ++i) {
            EXPECT_NEAR(result.thickness[i], 0.8, 0.5 * voxel) << i;
            // The ball's centre is on the pin's axis.
            EXPECT_LT(std::hypot(result.centre[i][0], result.centre[i][1]), voxel) << i;
        }
    }
}

TEST(LocalThickness, ConcaveEdgeOfAnLDoesNotReadThin) {
    const double voxel = 0.12, t = 1.0;
    const auto grid = test::plain_level_set(make_l(t), voxel, 2.5);
    std::vector<Vec3> points;
    for (double y : {1.0, 4.0, 7.0})
        for (double d : {0.0, 0.05, 0.3, 1.0, 3.0}) {
            points.push_back({t + d, y, t});  // along the floor up to the concave edge
            points.push_back({t, y, t + d});  // along the wall up to it
        }
    Progress progress;
    const LocalThickness result = local_thickness(*grid, points, ThicknessSide::solid, 2.0, progress);
    for (size_t i = 0; i < points.size(); ++i) EXPECT_GT(result.thickness[i], t - 0.5 * voxel) << i;
}

TEST(LocalThickness, SlotWidthOnTheGapSide) {
    const double voxel = 0.1, w = 0.7;
    const Mesh slot = test::merged(test::make_box({0, 0, 0}, {10, 10, 2}), test::make_box({0, 0, 2 + w}, {10, 10, 4 + w}));
    const auto grid = test::plain_level_set(slot, voxel, 1.5);
    std::vector<Vec3> points;
    for (double x : {2.0, 5.0, 7.3}) {
        points.push_back({x, 5.0, 2.0});
        points.push_back({x, 4.1, 2.0 + w});
    }
    Progress progress;
    const LocalThickness gap = local_thickness(*grid, points, ThicknessSide::gap, 1.0, progress);
    for (size_t i = 0; i < points.size(); ++i) EXPECT_NEAR(gap.thickness[i], w, 0.5 * voxel) << i;
    // The plates themselves, 2 mm thick, are capped at 2·1.0 mm on the solid side.
    const LocalThickness solid = local_thickness(*grid, points, ThicknessSide::solid, 0.8, progress);
    for (size_t i = 0; i < points.size(); ++i) {
        EXPECT_DOUBLE_EQ(solid.thickness[i], 1.6) << i;
        EXPECT_EQ(solid.capped[i], 1) << i;
    }
}

TEST(LocalThickness, ThickFacesAreCappedWithTheBallBesideThem) {
    const double voxel = 0.2, radius = 1.0;
    const auto grid = test::plain_level_set(test::make_box({0, 0, 0}, {10, 10, 4}), voxel, radius + 5 * voxel);
    // Face points away from the edges, each with its inward normal.
    const std::vector<std::pair<Vec3, Vec3>> faces = {{{5.1, 4.3, 4.0}, {0, 0, -1}}, {{3.7, 6.2, 0.0}, {0, 0, 1}},
                                                      {{0.0, 5.5, 2.1}, {1, 0, 0}}, {{6.6, 10.0, 1.9}, {0, -1, 0}}};
    std::vector<Vec3> points;
    for (const auto& face : faces) points.push_back(face.first);
    Progress progress;
    const LocalThickness result = local_thickness(*grid, points, ThicknessSide::solid, radius, progress);
    for (size_t i = 0; i < points.size(); ++i) {
        EXPECT_DOUBLE_EQ(result.thickness[i], 2.0 * radius) << i;
        EXPECT_EQ(result.capped[i], 1) << i;
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(result.centre[i][k], faces[i].first[k] + radius * faces[i].second[k], 0.25 * voxel) << i;
    }
}

TEST(LocalThickness, NoPointsAndCancellation) {
    const auto grid = test::plain_level_set(test::make_box({0, 0, 0}, {2, 2, 2}), 0.2, 1.5);
    Progress progress;
    EXPECT_TRUE(local_thickness(*grid, {}, ThicknessSide::solid, 1.0, progress).thickness.empty());
    std::atomic<bool> cancel{true};
    Progress cancelled(nullptr, nullptr, &cancel);
    try {
        local_thickness(*grid, box_points({0, 0, 0}, {2, 2, 2}), ThicknessSide::solid, 1.0, cancelled);
        FAIL() << "not cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
}  // namespace fabvdb::volume
