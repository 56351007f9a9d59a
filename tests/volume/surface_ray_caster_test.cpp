// SurfaceRayCaster's first hits: from inside a box along each axis, the face
// ahead at its distance (t in units of the direction's length); nothing
// when the box is missed, behind, or beyond max_distance; the nearer of two
// nested boxes; on an icosphere from inside, the distance the tests' own line
// caster finds, on the plane of the triangle reported; a ray from a point of
// a face does not hit it (only t > 0 counts); the same answers from threads;
// a mesh without triangles is refused. Every hit of a segment: the same
// crossings as the tests' own line caster on an icosphere, ordered, none
// outside the segment; a line through a face's diagonal edge or a box's
// corner is not lost between the triangles that meet there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <tbb/parallel_for.h>

#include "core/error.h"
#include "volume/surface_ray_caster.h"
#include "support/ray_cast.h"
#include "support/shapes.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;
using fabvdb::volume::SurfaceRayCaster;

//! Whether every corner of triangle `t` has coordinate `axis` equal to `value`.
bool on_plane(const Mesh& mesh, int64_t t, int axis, double value) {
    if (t < 0 || size_t(t) >= mesh.triangles.size()) return false;
    for (uint32_t corner : mesh.triangles[size_t(t)])
        if (mesh.vertices[corner][axis] != value) return false;
    return true;
}

}  // namespace

TEST(SurfaceRayCaster, HitsTheFaceAheadInsideABox) {
    const Mesh box = fabvdb::test::make_box({-2, -3, -4}, {5, 6, 7});
    const SurfaceRayCaster caster(box);
    const Vec3 from{1, 0.5, 0.25};
    struct Case {
        Vec3 direction;
        int axis;
        double plane, distance;
    };
    const Case cases[] = {{{1, 0, 0}, 0, 5, 4},      {{-1, 0, 0}, 0, -2, 3},  {{0, 1, 0}, 1, 6, 5.5},
                          {{0, -1, 0}, 1, -3, 3.5},  {{0, 0, 1}, 2, 7, 6.75}, {{0, 0, -1}, 2, -4, 4.25},
                          {{0, 0, -2}, 2, -4, 2.125}};  // t counts lengths of the direction
    for (const Case& c : cases) {
        double distance = -1;
        const int64_t hit = caster.first_hit(from, c.direction, 100.0, &distance);
        EXPECT_TRUE(on_plane(box, hit, c.axis, c.plane)) << "direction axis " << c.axis << " hit " << hit;
        EXPECT_NEAR(distance, c.distance, 1e-5);
    }
    // A slanted ray: from (1, 0.5, 0.25) along (1, 1, 1) it reaches x = 5 first, at t = 4.
    double distance = -1;
    EXPECT_TRUE(on_plane(box, caster.first_hit(from, {1, 1, 1}, 100.0, &distance), 0, 5));
    EXPECT_NEAR(distance, 4.0, 1e-5);
}

TEST(SurfaceRayCaster, MissesAreMinusOneAndLeaveTheDistanceAlone) {
    const Mesh box = fabvdb::test::make_box({0, 0, 0}, {1, 1, 1});
    const SurfaceRayCaster caster(box);
    double distance = 42;
    // Beside the box, pointing past it.
    EXPECT_EQ(caster.first_hit({3, 0.5, 0.5}, {0, 1, 0}, HUGE_VAL, &distance), -1);
    // The box is behind the origin.
    EXPECT_EQ(caster.first_hit({3, 0.5, 0.5}, {1, 0, 0}, HUGE_VAL, &distance), -1);
    // The box is 2 ahead, but the ray stops at 1.5; at 2.5 it reaches it.
    EXPECT_EQ(caster.first_hit({3, 0.5, 0.5}, {-1, 0, 0}, 1.5, &distance), -1);
    EXPECT_EQ(distance, 42);
    EXPECT_TRUE(on_plane(box, caster.first_hit({3, 0.5, 0.5}, {-1, 0, 0}, 2.5, &distance), 0, 1));
    EXPECT_NEAR(distance, 2.0, 1e-6);
    // No distance asked for.
    EXPECT_TRUE(on_plane(box, caster.first_hit({0.5, 0.5, 3}, {0, 0, -1}, HUGE_VAL), 2, 1));
}

TEST(SurfaceRayCaster, ARayFromASurfaceDoesNotHitItAtZero) {
    // Only hits with 0 < t count: from a point of the bottom face of a unit
    // box (off the quad's diagonal), up finds the top at 1, down finds nothing.
    const Mesh box = fabvdb::test::make_box({0, 0, 0}, {1, 1, 1});
    const SurfaceRayCaster caster(box);
    double distance = -1;
    EXPECT_TRUE(on_plane(box, caster.first_hit({0.3, 0.6, 0}, {0, 0, 1}, HUGE_VAL, &distance), 2, 1));
    EXPECT_NEAR(distance, 1.0, 1e-6);
    EXPECT_EQ(caster.first_hit({0.3, 0.6, 0}, {0, 0, -1}, HUGE_VAL), -1);
}

TEST(SurfaceRayCaster, TheNearerOfNestedSurfacesComesFirst) {
    const Mesh outer = fabvdb::test::make_box({-10, -10, -10}, {10, 10, 10});
    const Mesh inner = fabvdb::test::make_box({-1, -1, -1}, {1, 1, 1});
    const Mesh both = fabvdb::test::merged(outer, inner);
    const SurfaceRayCaster caster(both);
    double distance = 0;
    // From outside the inner box, towards it: its face x = -1 (triangles 12..23).
    const int64_t hit = caster.first_hit({-5, 0.3, 0.2}, {1, 0, 0}, HUGE_VAL, &distance);
    EXPECT_GE(hit, 12);
    EXPECT_TRUE(on_plane(both, hit, 0, -1));
    EXPECT_NEAR(distance, 4.0, 1e-5);
    // Away from it: the outer box.
    const int64_t back = caster.first_hit({-5, 0.3, 0.2}, {-1, 0, 0}, HUGE_VAL, &distance);
    EXPECT_LT(back, 12);
    EXPECT_TRUE(on_plane(both, back, 0, -10));
    EXPECT_NEAR(distance, 5.0, 1e-5);
}

TEST(SurfaceRayCaster, AgreesWithAnIndependentLineCasterOnASphere) {
    const Vec3 center{1, 2, 3};
    const Mesh sphere = fabvdb::test::make_sphere(center, 10.0, 3);
    const SurfaceRayCaster caster(sphere);
    std::mt19937 random(7);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> offset(-4, 4);
    for (int i = 0; i < 200; ++i) {
        Vec3 d{normal(random), normal(random), normal(random)};
        const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (double& x : d) x /= length;
        const Vec3 from{center[0] + offset(random), center[1] + offset(random), center[2] + offset(random)};
        double distance = -1;
        const int64_t hit = caster.first_hit(from, d, HUGE_VAL, &distance);
        ASSERT_GE(hit, 0) << "from inside a closed surface every ray hits";
        // The line caster gives the crossings of the whole line; the first hit is the one ahead.
        const std::vector<double> crossings = fabvdb::test::LineCaster(sphere, d).crossings(from);
        double ahead = HUGE_VAL;
        for (double t : crossings)
            if (t > 0 && t < ahead) ahead = t;
        EXPECT_NEAR(distance, ahead, 1e-4) << "ray " << i;
        // The hit point lies in the plane of the triangle reported.
        const auto& tri = sphere.triangles[size_t(hit)];
        const Vec3 n = fabvdb::triangle_normal(sphere, tri);
        const Vec3& a = sphere.vertices[tri[0]];
        const Vec3 p{from[0] + distance * d[0], from[1] + distance * d[1], from[2] + distance * d[2]};
        const double n_length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        EXPECT_NEAR(((p[0] - a[0]) * n[0] + (p[1] - a[1]) * n[1] + (p[2] - a[2]) * n[2]) / n_length, 0.0, 1e-4);
        // Inside an icosphere of radius 10 the surface lies within 0.1 of it (level 3).
        const double r = std::sqrt(std::pow(p[0] - center[0], 2) + std::pow(p[1] - center[1], 2) +
                                   std::pow(p[2] - center[2], 2));
        EXPECT_GT(r, 9.8);
        EXPECT_LE(r, 10.0 + 1e-4);
    }
}

TEST(SurfaceRayCaster, AllHitsAreTheLineCastersCrossingsInsideTheSegment) {
    const Vec3 center{1, 2, 3};
    const Mesh sphere = fabvdb::test::make_sphere(center, 10.0, 3);
    const SurfaceRayCaster caster(sphere);
    std::mt19937 random(11);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> offset(-6, 6);
    for (int i = 0; i < 200; ++i) {
        Vec3 d{normal(random), normal(random), normal(random)};
        const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (double& x : d) x /= length;
        const Vec3 from{center[0] + offset(random), center[1] + offset(random), center[2] + offset(random)};
        const double t_min = -15 + 5 * (i % 3), t_max = 25 - 7 * (i % 4);
        const std::vector<fabvdb::volume::RayHit> hits = caster.all_hits(from, d, t_min, t_max);
        std::vector<double> expected;
        for (double t : fabvdb::test::LineCaster(sphere, d).crossings(from))
            if (t > t_min && t < t_max) expected.push_back(t);
        ASSERT_EQ(hits.size(), expected.size()) << "line " << i;
        for (size_t k = 0; k < hits.size(); ++k) {
            EXPECT_NEAR(hits[k].t, expected[k], 1e-4) << "line " << i << " hit " << k;
            EXPECT_LT(hits[k].triangle, sphere.triangles.size());
            if (k > 0) EXPECT_LE(hits[k - 1].t, hits[k].t);
        }
    }
}

TEST(SurfaceRayCaster, ALineThroughEdgesAndCornersIsNotLost) {
    const Mesh box = fabvdb::test::make_box({0, 0, 0}, {4, 4, 4});
    const SurfaceRayCaster caster(box);
    // Along z through every point of a fine grid over the square, the
    // diagonals and the corners included: the bottom and the top face.
    for (int i = 0; i <= 8; ++i)
        for (int j = 0; j <= 8; ++j) {
            const std::vector<fabvdb::volume::RayHit> hits = caster.all_hits({0.5 * i, 0.5 * j, -1}, {0, 0, 1}, 0, 10);
            bool bottom = false, top = false;
            for (const auto& hit : hits) {
                bottom |= std::abs(hit.t - 1) < 1e-6 && on_plane(box, hit.triangle, 2, 0);
                top |= std::abs(hit.t - 5) < 1e-6 && on_plane(box, hit.triangle, 2, 4);
            }
            EXPECT_TRUE(bottom && top) << "line through (" << 0.5 * i << ", " << 0.5 * j << ")";
        }
}

TEST(SurfaceRayCaster, AMeshWithoutTrianglesIsBadInput) {
    try {
        fabvdb::volume::SurfaceRayCaster caster{fabvdb::Mesh{}};
        ADD_FAILURE() << "an empty mesh was accepted";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT);
    }
}

TEST(SurfaceRayCaster, ConcurrentQueriesGiveTheSameAnswers) {
    const Mesh sphere = fabvdb::test::make_sphere({0, 0, 0}, 5.0, 3);
    const SurfaceRayCaster caster(sphere);
    const size_t n = 4000;
    std::vector<Vec3> directions(n);
    for (size_t i = 0; i < n; ++i) {
        const double phi = 2.399963 * double(i), z = 1.0 - 2.0 * (double(i) + 0.5) / double(n);
        const double s = std::sqrt(1.0 - z * z);
        directions[i] = {s * std::cos(phi), s * std::sin(phi), z};
    }
    std::vector<int64_t> serial(n), parallel(n);
    std::vector<double> serial_t(n), parallel_t(n);
    for (size_t i = 0; i < n; ++i) serial[i] = caster.first_hit({0.1, 0.2, 0.3}, directions[i], HUGE_VAL, &serial_t[i]);
    tbb::parallel_for(size_t(0), n, [&](size_t i) {
        parallel[i] = caster.first_hit({0.1, 0.2, 0.3}, directions[i], HUGE_VAL, &parallel_t[i]);
    });
    EXPECT_EQ(serial, parallel);
    EXPECT_EQ(serial_t, parallel_t);
    // Rays spread evenly over the sphere hit most of its 1280 triangles.
    std::vector<bool> seen(sphere.triangles.size(), false);
    for (int64_t t : serial) {
        ASSERT_GE(t, 0);
        seen[size_t(t)] = true;
    }
    EXPECT_GT(std::count(seen.begin(), seen.end(), true), 1000);
}
