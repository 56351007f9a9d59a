// Robust signed distance: checked against analytic distances of the shapes
// (sampled with OpenVDB's accessor, not with the code under test).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <random>

#include "core/error.h"
#include "support/defect_shapes.h"
#include "support/shapes.h"
#include "volume/signed_distance.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;
using fabvdb::test::box_signed_distance;
namespace volume = fabvdb::volume;

openvdb::FloatGrid::Ptr distance(const Mesh& mesh, double voxel, volume::SignedDistanceStats* stats = nullptr,
                                 double thicken = 0.0) {
    fabvdb::Progress progress;
    volume::SignedDistanceOptions options;
    options.voxel_size = voxel;
    options.thicken = thicken;
    return volume::signed_distance_from_mesh(mesh, options, progress, stats);
}

double value_at(const openvdb::FloatGrid& grid, const Vec3& p) {
    const openvdb::Coord ijk = grid.transform().worldToIndexCellCentered(openvdb::Vec3d(p[0], p[1], p[2]));
    return grid.getConstAccessor().getValue(ijk);
}

Vec3 voxel_centre(const openvdb::FloatGrid& grid, const Vec3& p) {
    const openvdb::Coord ijk = grid.transform().worldToIndexCellCentered(openvdb::Vec3d(p[0], p[1], p[2]));
    const openvdb::Vec3d c = grid.transform().indexToWorld(ijk);
    return {c[0], c[1], c[2]};
}

// Compares the grid with an analytic signed distance at random points of a
// box: the sign everywhere off a thin shell, the value inside the band.
template <class Exact>
void expect_matches(const openvdb::FloatGrid& grid, const Vec3& lo, const Vec3& hi, const Exact& exact,
                    double tolerance) {
    const double voxel = grid.voxelSize()[0], band = grid.background();
    std::mt19937 random(3);
    int sign_errors = 0;
    for (int i = 0; i < 20000; ++i) {
        Vec3 p;
        for (int k = 0; k < 3; ++k) p[k] = std::uniform_real_distribution<double>(lo[k], hi[k])(random);
        const Vec3 c = voxel_centre(grid, p);
        const double expected = exact(c), actual = value_at(grid, c);
        if (std::abs(expected) > voxel && (expected < 0) != (actual < 0)) ++sign_errors;
        if (std::abs(expected) < band - voxel) EXPECT_NEAR(actual, expected, tolerance) << c[0] << " " << c[1] << " " << c[2];
    }
    EXPECT_EQ(sign_errors, 0);
}

double sphere_distance(const Vec3& p, const Vec3& c, double r) {
    return std::sqrt((p[0] - c[0]) * (p[0] - c[0]) + (p[1] - c[1]) * (p[1] - c[1]) + (p[2] - c[2]) * (p[2] - c[2])) - r;
}

TEST(SignedDistance, SphereIsItsDistanceField) {
    const Mesh sphere = fabvdb::test::make_sphere({1, 2, 3}, 10.0, 5);
    volume::SignedDistanceStats stats;
    auto grid = distance(sphere, 0.4, &stats);
    EXPECT_EQ(grid->getGridClass(), openvdb::GRID_LEVEL_SET);
    EXPECT_FALSE(stats.rebuilt);
    EXPECT_GT(stats.active_voxels, 0u);
    expect_matches(*grid, {-12, -12, -12}, {14, 16, 18},
                   [](const Vec3& p) { return sphere_distance(p, {1, 2, 3}, 10.0); }, 0.1);
}

TEST(SignedDistance, InvertedSphereIsTheSameSolid) {
    auto grid = distance(fabvdb::test::flipped(fabvdb::test::make_sphere({0, 0, 0}, 10.0, 4)), 0.4);
    expect_matches(*grid, {-14, -14, -14}, {14, 14, 14},
                   [](const Vec3& p) { return sphere_distance(p, {0, 0, 0}, 10.0); }, 0.15);
}

TEST(SignedDistance, OverlappingShellsUnite) {
    const Mesh both = fabvdb::test::merged(fabvdb::test::make_box({0, 0, 0}, {10, 10, 10}),
                                           fabvdb::test::flipped(fabvdb::test::make_box({5, 5, 5}, {15, 15, 15})));
    volume::SignedDistanceStats stats;
    auto grid = distance(both, 0.25, &stats);
    EXPECT_TRUE(stats.rebuilt);
    expect_matches(*grid, {-2, -2, -2}, {17, 17, 17},
                   [](const Vec3& p) {
                       return std::min(box_signed_distance(p, {0, 0, 0}, {10, 10, 10}),
                                       box_signed_distance(p, {5, 5, 5}, {15, 15, 15}));
                   },
                   0.3);  // the rebuilt band rounds sharp edges by about a voxel
}

TEST(SignedDistance, PlateThinnerThanAVoxelKeepsItsTrueDistance) {
    // A closed plate 0.2 voxel thick between two layers of voxel centres,
    // beside a box: no voxel lies inside the plate, so its band has no sign
    // change, yet its distances are true and the band is kept as it is.
    const Vec3 plate_lo = {12, 0, 5.05}, plate_hi = {16, 10, 5.1};
    const Mesh both = fabvdb::test::merged(fabvdb::test::make_box({0, 0, 0}, {10, 10, 10}),
                                           fabvdb::test::make_box(plate_lo, plate_hi));
    volume::SignedDistanceStats stats;
    auto grid = distance(both, 0.25, &stats);
    EXPECT_FALSE(stats.rebuilt);
    expect_matches(*grid, {-2, -2, -2}, {18, 12, 12},
                   [&](const Vec3& p) {
                       return std::min(box_signed_distance(p, {0, 0, 0}, {10, 10, 10}),
                                       box_signed_distance(p, plate_lo, plate_hi));
                   },
                   0.1);
}

TEST(SignedDistance, OpenBoxIsClosedAcrossItsHole) {
    const Mesh open = fabvdb::test::make_open_box({0, 0, 0}, {10, 10, 10});
    volume::SignedDistanceStats stats;
    auto grid = distance(open, 0.25, &stats);
    EXPECT_TRUE(stats.rebuilt);
    expect_matches(*grid, {-2, -2, -2}, {12, 12, 12},
                   [](const Vec3& p) { return box_signed_distance(p, {0, 0, 0}, {10, 10, 10}); }, 0.3);
}

// A hollow part as a farm receives it: the outer shell faces out and the
// cavity shell faces in. The cavity is kept, whether the band is consistent
// (closed shells) or rebuilt (the outer shell has a hole).
double hollow_box_distance(const Vec3& p) {
    return std::max(box_signed_distance(p, {0.13, 0.07, 0.11}, {20.13, 20.07, 20.11}),
                    -box_signed_distance(p, {3.13, 3.07, 3.11}, {17.13, 17.07, 17.11}));
}

Mesh hollow_box() {
    return fabvdb::test::merged(fabvdb::test::make_box({0.13, 0.07, 0.11}, {20.13, 20.07, 20.11}),
                                fabvdb::test::flipped(fabvdb::test::make_box({3.13, 3.07, 3.11}, {17.13, 17.07, 17.11})));
}

TEST(SignedDistance, HollowInputKeepsItsCavity) {
    auto grid = distance(hollow_box(), 0.25);
    expect_matches(*grid, {-2, -2, -2}, {22, 22, 22}, hollow_box_distance, 0.3);
    EXPECT_GT(value_at(*grid, {10, 10, 10}), 0.0);
}

TEST(SignedDistance, HollowInputWithAHoleKeepsItsCavityWhenRebuilt) {
    const Mesh hollow = hollow_box();
    Mesh holed;
    holed.vertices = hollow.vertices;
    holed.triangles.assign(hollow.triangles.begin() + 1, hollow.triangles.end());  // half of one outer face gone
    volume::SignedDistanceStats stats;
    auto grid = distance(holed, 0.25, &stats);
    EXPECT_TRUE(stats.rebuilt);
    expect_matches(*grid, {-2, -2, -2}, {22, 22, 22}, hollow_box_distance, 0.3);
}

TEST(SignedDistance, NestedOutwardShellsUnite) {
    const Mesh nested = fabvdb::test::merged(fabvdb::test::make_box({0.13, 0.07, 0.11}, {20.13, 20.07, 20.11}),
                                             fabvdb::test::make_box({3.13, 3.07, 3.11}, {17.13, 17.07, 17.11}));
    auto grid = distance(nested, 0.25);
    expect_matches(*grid, {-2, -2, -2}, {22, 22, 22},
                   [](const Vec3& p) { return box_signed_distance(p, {0.13, 0.07, 0.11}, {20.13, 20.07, 20.11}); }, 0.3);
}

TEST(SignedDistance, OpenSheetEnclosesNothingUnlessThickened) {
    Mesh sheet;
    sheet.vertices = {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}};
    sheet.triangles = {{0, 1, 2}, {0, 2, 3}};
    try {
        distance(sheet, 0.25);
        FAIL() << "an open sheet has no inside";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT);
        EXPECT_NE(std::string(e.what()).find("encloses no volume"), std::string::npos);
    }
    volume::SignedDistanceStats stats;
    auto grid = distance(sheet, 0.25, &stats, 1.0);
    EXPECT_TRUE(stats.thickened);
    EXPECT_LT(value_at(*grid, {5, 5, 0}), -0.3);
    EXPECT_GT(value_at(*grid, {5, 5, 1.0}), 0.3);
    EXPECT_GT(value_at(*grid, {5, 5, -1.0}), 0.3);
}

// A soup of unrelated, partly crossing triangles encloses nothing: refused by the
// winding-number probe before any voxel is built (it once ran 96 s and made a
// 3.9-million-triangle mesh), with the share it measured; thickened on demand.
TEST(SignedDistance, SoupIsRefusedUnlessThickened) {
    const Mesh soup = fabvdb::test::make_triangle_soup(100, 100.0, 15.0, 7);
    try {
        distance(soup, 0.25);
        FAIL() << "a soup has no inside";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT);
        EXPECT_NE(std::string(e.what()).find("encloses no volume"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("soup"), std::string::npos) << e.what();
    }
    volume::SignedDistanceStats stats;
    auto grid = distance(soup, 0.5, &stats, 1.0);
    EXPECT_TRUE(stats.thickened);
    EXPECT_LT(stats.enclosed_share, 0.05);
    const fabvdb::Vec3& corner = soup.vertices[0];
    const fabvdb::Vec3& other = soup.vertices[1];
    const fabvdb::Vec3 on_edge{0.5 * (corner[0] + other[0]), 0.5 * (corner[1] + other[1]), 0.5 * (corner[2] + other[2])};
    EXPECT_LT(value_at(*grid, on_edge), 0.0);
}

TEST(SignedDistance, RefusesOverBudgetWithAVoxelThatFits) {
    fabvdb::Progress progress;
    volume::SignedDistanceOptions options;
    options.voxel_size = 0.01;
    options.memory_budget_bytes = 64ull << 20;
    options.input_name = "ball.stl";
    try {
        volume::signed_distance_from_mesh(fabvdb::test::make_sphere({0, 0, 0}, 50.0, 3), options, progress);
        FAIL() << "over budget";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_OUT_OF_BUDGET);
        const std::string message = e.what();
        EXPECT_NE(message.find("ball.stl"), std::string::npos);
        const size_t at = message.find("--voxel ");
        ASSERT_NE(at, std::string::npos);
        options.voxel_size = std::stod(message.substr(at + 8));
        EXPECT_GT(options.voxel_size, 0.01);
        auto grid = volume::signed_distance_from_mesh(fabvdb::test::make_sphere({0, 0, 0}, 50.0, 3), options, progress);
        EXPECT_GT(grid->activeVoxelCount(), 0u);
    }
}

TEST(SignedDistance, CancelledGivesNoResult) {
    std::atomic<bool> cancel{false};
    int calls = 0;
    struct Context {
        std::atomic<bool>* cancel;
        int* calls;
    } context{&cancel, &calls};
    fabvdb::Progress progress(
        [](void* user, const char*, double) {
            auto* c = static_cast<Context*>(user);
            if (++*c->calls == 3) c->cancel->store(true);
            return 0;
        },
        &context, &cancel);
    volume::SignedDistanceOptions options;
    options.voxel_size = 0.2;
    try {
        volume::signed_distance_from_mesh(fabvdb::test::make_sphere({0, 0, 0}, 10.0, 4), options, progress);
        FAIL() << "cancelled";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
