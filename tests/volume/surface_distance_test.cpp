// Point-to-surface distances: to one triangle from its face, edge and corner
// regions by hand; to a box, random points inside and outside against the
// box's own distance formula, with a triangle on the nearest face; a mesh
// without triangles is Error(BAD_INPUT).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/error.h"
#include "support/shapes.h"
#include "volume/surface_distance.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;
using fabvdb::volume::SurfaceDistance;
using fabvdb::test::make_box;

TEST(SurfaceDistance, OneTriangleByRegion) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
    mesh.triangles = {{0, 1, 2}};
    const SurfaceDistance distance(mesh);
    EXPECT_NEAR(distance.nearest({1, 1, 3}).distance, 3.0, 1e-12);           // over the face
    EXPECT_NEAR(distance.nearest({1, 1, -2}).distance, 2.0, 1e-12);          // under it
    EXPECT_NEAR(distance.nearest({2, -3, 4}).distance, 5.0, 1e-12);          // beyond edge 01: (2, 0, 0)
    EXPECT_NEAR(distance.nearest({3, 3, 0}).distance, std::sqrt(2.0), 1e-12);  // beyond the hypotenuse: (2, 2, 0)
    EXPECT_NEAR(distance.nearest({-3, -4, 0}).distance, 5.0, 1e-12);         // beyond corner 0
    EXPECT_NEAR(distance.nearest({6, -1, 2}).distance, 3.0, 1e-12);          // beyond corner 1: (2, -1, 2)
    EXPECT_EQ(distance.nearest({1, 1, 3}).triangle, 0u);
    EXPECT_EQ(distance.nearest({0.5, 0.5, 0}).distance, 0.0);  // on it
}

TEST(SurfaceDistance, TheNearestOfSeveralTriangles) {
    // Three separate unit-leg triangles at z = 0, 5 and 10 (the last far off in x).
    Mesh mesh;
    for (double z : {0.0, 5.0, 10.0}) {
        const uint32_t base = uint32_t(mesh.vertices.size());
        const double x = z == 10.0 ? 100.0 : 0.0;
        mesh.vertices.push_back({x, 0, z});
        mesh.vertices.push_back({x + 1, 0, z});
        mesh.vertices.push_back({x, 1, z});
        mesh.triangles.push_back({base, base + 1, base + 2});
    }
    const SurfaceDistance distance(mesh);
    auto nearest = distance.nearest({0.2, 0.2, 1.0});
    EXPECT_EQ(nearest.triangle, 0u);
    EXPECT_NEAR(nearest.distance, 1.0, 1e-12);
    nearest = distance.nearest({0.2, 0.2, 3.0});
    EXPECT_EQ(nearest.triangle, 1u);
    EXPECT_NEAR(nearest.distance, 2.0, 1e-12);
    nearest = distance.nearest({100.2, 0.2, 9.0});
    EXPECT_EQ(nearest.triangle, 2u);
    EXPECT_NEAR(nearest.distance, 1.0, 1e-12);
}

//! Distance to the surface of the box [lo, hi], by its own formula.
double box_distance(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    double outside = 0.0, inside = 1e300;
    for (int k = 0; k < 3; ++k) {
        const double d = std::max({lo[k] - p[k], p[k] - hi[k], 0.0});
        outside += d * d;
        inside = std::min({inside, p[k] - lo[k], hi[k] - p[k]});
    }
    return outside > 0.0 ? std::sqrt(outside) : std::max(inside, 0.0);
}

TEST(SurfaceDistance, RandomPointsAroundABox) {
    const Vec3 lo{-1, 0, 2}, hi{3, 1.5, 4};
    const Mesh box = make_box(lo, hi);
    const SurfaceDistance distance(box);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> x(-4, 6), y(-3, 4.5), z(-1, 7);
    int inside = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 p{x(random), y(random), z(random)};
        const double expected = box_distance(p, lo, hi);
        const auto nearest = distance.nearest(p);
        ASSERT_NEAR(nearest.distance, expected, 1e-9) << p[0] << " " << p[1] << " " << p[2];
        ASSERT_LT(nearest.triangle, box.triangles.size());
        if (p[0] > lo[0] && p[0] < hi[0] && p[1] > lo[1] && p[1] < hi[1] && p[2] > lo[2] && p[2] < hi[2]) ++inside;
    }
    EXPECT_GT(inside, 20);
}

TEST(SurfaceDistance, TheTriangleIsOnTheNearestFace) {
    // make_box: triangles 2k and 2k + 1 make face k: z = lo, z = hi, y = lo, y = hi, x = lo, x = hi.
    const Mesh box = make_box({0, 0, 0}, {2, 2, 2});
    const SurfaceDistance distance(box);
    const struct {
        Vec3 p;
        size_t face;
        double distance;
    } cases[] = {
        {{1, 1.2, -0.5}, 0, 0.5}, {{1, 0.8, 2.25}, 1, 0.25}, {{0.5, -3, 1}, 2, 3.0},
        {{1.5, 1.9, 1.0}, 3, 0.1}, {{0.3, 1, 0.9}, 4, 0.3},  {{2.7, 0.6, 1.4}, 5, 0.7},
    };
    for (const auto& c : cases) {
        const auto nearest = distance.nearest(c.p);
        EXPECT_EQ(nearest.triangle / 2, c.face) << c.p[0] << " " << c.p[1] << " " << c.p[2];
        EXPECT_NEAR(nearest.distance, c.distance, 1e-12);
    }
}

TEST(SurfaceDistance, AMeshWithoutTrianglesIsBadInput) {
    for (const bool with_points : {false, true}) {
        Mesh mesh;
        if (with_points) mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        try {
            SurfaceDistance distance(mesh);
            ADD_FAILURE() << "no error";
        } catch (const fabvdb::Error& error) {
            EXPECT_EQ(error.status(), FABVDB_ERR_BAD_INPUT);
        }
    }
}

}  // namespace
