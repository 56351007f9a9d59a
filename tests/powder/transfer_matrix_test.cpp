// transfer_matrix on hand-built patches: a box room (a patch a face) emptying
// onto its floor for gravity down, tilted 20° and upside down; a slope's shares
// (border × drop / run, lower neighbours only); the floor threshold at the
// angle of repose; falls from a ceiling onto a split floor by ray counts, and
// into nothing; on a clustered sphere, stochastic rows, moves strictly down,
// floors fixed, slopes held only with no lower neighbour, overhangs never.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

#include "powder/cavity_patches.h"
#include "volume/surface_ray_caster.h"
#include "powder/transfer_matrix.h"
#include "support/hand_patches.h"
#include "support/shapes.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;
using fabvdb::powder::CavityPatches;
using fabvdb::powder::StochasticMatrix;
using fabvdb::volume::SurfaceRayCaster;
using fabvdb::powder::transfer_matrix;
using fabvdb::powder::TransferOptions;
using fabvdb::test::kCeiling;
using fabvdb::test::kFloor;
using fabvdb::test::room_patches;
using Row = std::map<uint32_t, double>;

Row row(const StochasticMatrix& m, size_t i) {
    Row r;
    for (uint32_t e = m.row_start[i]; e < m.row_start[i + 1]; ++e) r[m.column[e]] += m.weight[e];
    return r;
}

void expect_row(const StochasticMatrix& m, size_t i, const Row& expected) {
    const Row actual = row(m, i);
    ASSERT_EQ(actual.size(), expected.size()) << "row " << i;
    for (const auto& [column, weight] : expected) {
        ASSERT_TRUE(actual.count(column)) << "row " << i << " lacks column " << column;
        EXPECT_NEAR(actual.at(column), weight, 1e-6) << "row " << i << " column " << column;
    }
}

double degrees(double d) { return d * M_PI / 180.0; }

}  // namespace

TEST(TransferMatrix, ARoomEmptiesOntoItsFloor) {
    const Mesh room = fabvdb::test::make_box({-5, -3, 0}, {5, 3, 8});
    const SurfaceRayCaster caster(room);
    const CavityPatches patches = room_patches();
    // Straight down: walls (vertical, so overhangs) and the ceiling fall onto the floor.
    // Tilted 20° towards +x (within the 35° of repose): the floor still holds;
    // the wall x = 5 now faces up at 20° and slides onto the floor, its only
    // lower neighbour; the others fall onto it.
    for (const Vec3& gravity : {Vec3{0, 0, -1}, Vec3{std::sin(degrees(20)), 0, -std::cos(degrees(20))}}) {
        const StochasticMatrix t = transfer_matrix(patches, caster, gravity, TransferOptions{});
        ASSERT_EQ(t.rows(), 6u);
        for (uint32_t i = 0; i < 6; ++i) expect_row(t, i, {{kFloor, 1.0}});
    }
    // Upside down, the ceiling is the floor.
    const StochasticMatrix t = transfer_matrix(patches, caster, {0, 0, 3}, TransferOptions{});
    for (uint32_t i = 0; i < 6; ++i) expect_row(t, i, {{kCeiling, 1.0}});
}

TEST(TransferMatrix, ASlopeSharesByBorderTimesDropOverRun) {
    const Mesh anything = fabvdb::test::make_box({0, 0, 0}, {1, 1, 1});
    const SurfaceRayCaster caster(anything);
    const double s = std::sqrt(0.5);
    // Patch 0 at z 5 faces up at 45°; neighbours: 1 (run (3, 0, -4), border 2),
    // 2 (run (0, 4, -3), border 1), 3 higher, 4 level: neither gets powder.
    const CavityPatches patches = fabvdb::test::hand_patches({{{0, 0, 5}, {0, -s, s}, 1, {{1, 2}, {2, 1}, {3, 5}, {4, 3}}},
                                              {{3, 0, 1}, {0, 0, 1}, 1, {{0, 2}}},
                                              {{0, 4, 2}, {0, 0, 1}, 1, {{0, 1}}},
                                              {{0, 0, 7}, {0, 0, 1}, 1, {{0, 5}}},
                                              {{1, 0, 5}, {0, 0, 1}, 1, {{0, 3}}}},
                                             std::vector<uint32_t>(12, 0));
    const StochasticMatrix t = transfer_matrix(patches, caster, {0, 0, -1}, TransferOptions{});
    // Shares 2·4/5 = 1.6 and 1·3/5 = 0.6, over 2.2.
    expect_row(t, 0, {{1, 1.6 / 2.2}, {2, 0.6 / 2.2}});
    for (uint32_t i = 1; i < 5; ++i) expect_row(t, i, {{i, 1.0}});
}

TEST(TransferMatrix, FloorsAreWithinTheAngleOfRepose) {
    const Mesh anything = fabvdb::test::make_box({0, 0, 0}, {1, 1, 1});
    const SurfaceRayCaster caster(anything);
    auto tilted = [](double angle) { return Vec3{std::sin(degrees(angle)), 0, std::cos(degrees(angle))}; };
    // Three tilted patches, each above a lower floor (patch 3).
    const CavityPatches patches = fabvdb::test::hand_patches({{{0, 0, 5}, tilted(30), 1, {{3, 1}}},
                                              {{0, 1, 5}, tilted(40), 1, {{3, 1}}},
                                              {{0, 2, 5}, tilted(80), 1, {}},  // steep, but nowhere lower to go
                                              {{0, 0, 0}, {0, 0, 1}, 1, {{0, 1}, {1, 1}}}},
                                             std::vector<uint32_t>(12, 0));
    StochasticMatrix t = transfer_matrix(patches, caster, {0, 0, -1}, TransferOptions{});
    expect_row(t, 0, {{0, 1.0}});  // 30° < 35°: a floor, though a lower patch is beside it
    expect_row(t, 1, {{3, 1.0}});  // 40°: slides down
    expect_row(t, 2, {{2, 1.0}});
    expect_row(t, 3, {{3, 1.0}});
    TransferOptions loose;
    loose.repose_radians = degrees(45);
    t = transfer_matrix(patches, caster, {0, 0, -1}, loose);
    expect_row(t, 1, {{1, 1.0}});  // 40° < 45°
}

TEST(TransferMatrix, AnOverhangFallsWhereItsRaysLand) {
    // A floor in two halves (x < 0: patch 0, x > 0: patch 1) 8 below a ceiling
    // (patch 2), with no walls.
    Mesh mesh;
    mesh.vertices = {{-5, -3, 0}, {0, -3, 0}, {5, -3, 0}, {-5, 3, 0}, {0, 3, 0}, {5, 3, 0},
                     {-5, -3, 8}, {5, -3, 8}, {-5, 3, 8}, {5, 3, 8}};
    // Faces out of the cavity: the floor down, the ceiling up.
    mesh.triangles = {{0, 4, 1}, {0, 3, 4}, {1, 5, 2}, {1, 4, 5}, {6, 7, 9}, {6, 9, 8}};
    const SurfaceRayCaster caster(mesh);
    auto with_ceiling_site = [&](const Vec3& site, int cone_rays) {
        CavityPatches patches = fabvdb::test::hand_patches({{{-2.5, 0, 0}, {0, 0, 1}, 30, {{1, 6}}},
                                            {{2.5, 0, 0}, {0, 0, 1}, 30, {{0, 6}}},
                                            {{0, 0, 8}, {0, 0, -1}, 60, {}}},
                                           {0, 0, 1, 1, 2, 2});
        patches.site[2] = site;
        TransferOptions options;
        options.cone_rays = cone_rays;
        return transfer_matrix(patches, caster, {0, 0, -1}, options);
    };
    // Rays start from the site (not the centroid).
    expect_row(with_ceiling_site({-2, 0, 8}, 5), 2, {{0, 1.0}});
    expect_row(with_ceiling_site({2, 1, 8}, 5), 2, {{1, 1.0}});
    expect_row(with_ceiling_site({0.3, 0, 8}, 1), 2, {{1, 1.0}});
    expect_row(with_ceiling_site({-0.3, 0, 8}, 1), 2, {{0, 1.0}});
    // At x = 0.3 the centre ray lands right; the four cone rays 8° off it
    // reach ±7.6·tan 8° ≈ 1.07 aside, 90° apart, so one or two of them land
    // left and the others right: shares of 5 rays.
    const Row split = row(with_ceiling_site({0.3, 0, 8}, 5), 2);
    ASSERT_EQ(split.size(), 2u);
    EXPECT_TRUE(std::abs(split.at(1) - 0.6) < 1e-6 || std::abs(split.at(1) - 0.8) < 1e-6) << split.at(1);
    EXPECT_NEAR(split.at(0) + split.at(1), 1.0, 1e-6);
    // Upside down the ceiling is a floor and the floor's rays go up into it.
    const StochasticMatrix up = transfer_matrix(
        fabvdb::test::hand_patches({{{-2.5, 0, 0}, {0, 0, 1}, 30, {{1, 6}}}, {{2.5, 0, 0}, {0, 0, 1}, 30, {{0, 6}}},
                    {{0, 0, 8}, {0, 0, -1}, 60, {}}},
                   {0, 0, 1, 1, 2, 2}),
        caster, {0, 0, 1}, TransferOptions{});
    expect_row(up, 0, {{2, 1.0}});
    expect_row(up, 1, {{2, 1.0}});
    expect_row(up, 2, {{2, 1.0}});
}

TEST(TransferMatrix, AnOverhangOverNothingKeepsItsPowder) {
    // Only the ceiling of a room: every ray misses.
    Mesh mesh;
    mesh.vertices = {{-5, -3, 8}, {5, -3, 8}, {-5, 3, 8}, {5, 3, 8}};
    mesh.triangles = {{0, 1, 3}, {0, 3, 2}};
    const SurfaceRayCaster caster(mesh);
    const CavityPatches patches = fabvdb::test::hand_patches({{{0, 0, 8}, {0, 0, -1}, 60, {}}}, {0, 0});
    expect_row(transfer_matrix(patches, caster, {0, 0, -1}, TransferOptions{}), 0, {{0, 1.0}});
}

TEST(TransferMatrix, OnASphereRowsAreStochasticAndMovesGoDownhill) {
    const Mesh sphere = fabvdb::test::make_sphere({0, 0, 0}, 10.0, 3);
    const CavityPatches patches = fabvdb::powder::cluster_cavity_patches(sphere, 120);
    const SurfaceRayCaster caster(sphere);
    const TransferOptions options;
    for (Vec3 gravity : {Vec3{0, 0, -1}, Vec3{1, 0, 0}, Vec3{1, 1, -1}}) {
        const double length = std::sqrt(gravity[0] * gravity[0] + gravity[1] * gravity[1] + gravity[2] * gravity[2]);
        for (double& g : gravity) g /= length;
        auto height = [&](uint32_t p) {
            const Vec3& c = patches.centroid[p];
            return -(c[0] * gravity[0] + c[1] * gravity[1] + c[2] * gravity[2]);
        };
        const StochasticMatrix t = transfer_matrix(patches, caster, gravity, options);
        ASSERT_EQ(t.rows(), patches.size());
        size_t floors = 0;
        for (uint32_t i = 0; i < t.rows(); ++i) {
            const Vec3& n = patches.normal[i];
            const double up = -(n[0] * gravity[0] + n[1] * gravity[1] + n[2] * gravity[2]);
            const bool floor = up >= std::cos(options.repose_radians);
            floors += floor;
            const Row r = row(t, i);
            const bool fixed = r.size() == 1 && r.count(i);
            // On the inside of a sphere every patch off the bottom has somewhere lower to go.
            // A slope is held only when no neighbour lies lower (a sliver patch
            // can have only larger, higher neighbours); inside a sphere every
            // overhang's rays fall onto lower patches.
            bool lower_neighbour = false;
            for (const auto& neighbour : patches.neighbours[i])
                lower_neighbour |= height(neighbour.patch) < height(i);
            if (floor)
                EXPECT_TRUE(fixed) << "floor " << i;
            else if (up > 0.0)
                EXPECT_EQ(fixed, !lower_neighbour) << "slope " << i << " up " << up;
            else
                EXPECT_FALSE(fixed) << "overhang " << i << " up " << up;
            double sum = 0;
            for (const auto& [j, w] : r) {
                sum += w;
                EXPECT_GT(w, 0.0);
                if (!fixed) EXPECT_LT(height(j), height(i)) << "patch " << i << " to " << j;
            }
            EXPECT_NEAR(sum, 1.0, 1e-5) << "patch " << i;
        }
        // The cap within 35° of the bottom: (1 − cos 35°)/2 ≈ 9% of the sphere.
        EXPECT_GT(floors, 3u);
        EXPECT_LT(floors, patches.size() / 4);
    }
}
