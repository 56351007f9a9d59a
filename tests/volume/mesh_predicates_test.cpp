// The mesh predicates the repair relies on: is_closed_cycle,
// is_closed_manifold and crossing_pairs. Crossings are compared with CGAL's
// self-intersection test on a Surface_mesh (its own broad phase and
// predicates) over randomly jittered spheres, so the fast path is checked
// against an independent reference where crossings do and do not occur.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include "support/shapes.h"
#include "volume/closed_cycle.h"
#include "volume/closed_manifold.h"
#include "volume/crossing_pairs.h"
#include "volume/edge_table.h"
#include "volume/position_ids.h"

namespace {

using fabvdb::Mesh;
using fabvdb::test::flipped;
using fabvdb::test::make_box;
using fabvdb::test::make_sphere;
using fabvdb::test::merged;
namespace volume = fabvdb::volume;

bool closed_cycle(const Mesh& mesh) {
    return volume::is_closed_cycle(volume::build_edge_table(volume::weld_positions(mesh)));
}

// CGAL's crossing pairs of a 2-manifold mesh, as sorted (i, j), i < j.
std::set<std::pair<uint32_t, uint32_t>> reference_pairs(const Mesh& mesh) {
    using Point = CGAL::Epick::Point_3;
    using SurfaceMesh = CGAL::Surface_mesh<Point>;
    namespace PMP = CGAL::Polygon_mesh_processing;
    std::vector<Point> points;
    for (const auto& v : mesh.vertices) points.emplace_back(v[0], v[1], v[2]);
    std::vector<std::vector<std::size_t>> polygons;
    for (const auto& t : mesh.triangles) polygons.push_back({t[0], t[1], t[2]});
    SurfaceMesh surface;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, surface);
    std::vector<std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>> faces;
    PMP::self_intersections(surface, std::back_inserter(faces));
    std::set<std::pair<uint32_t, uint32_t>> pairs;
    for (const auto& [f, g] : faces) pairs.insert(std::minmax(uint32_t(f), uint32_t(g)));
    return pairs;
}

std::set<std::pair<uint32_t, uint32_t>> fast_pairs(const Mesh& mesh, const std::vector<char>& candidates = {}) {
    const auto found = volume::crossing_pairs(mesh, candidates);
    return {found.begin(), found.end()};
}

TEST(ClosedCycle, ClosedShellsInAnyArrangement) {
    const Mesh box = make_box({0, 0, 0}, {1, 1, 1});
    EXPECT_TRUE(closed_cycle(box));
    EXPECT_TRUE(closed_cycle(flipped(box)));
    // Overlapping and nested shells, one of them inverted.
    EXPECT_TRUE(closed_cycle(merged(box, flipped(make_sphere({1, 1, 1}, 0.7, 2)))));
    // A soup: every triangle with its own corners (unwelded) is still a cycle.
    EXPECT_TRUE(closed_cycle(fabvdb::test::unwelded(box)));
}

TEST(ClosedCycle, HolesAndInconsistentOrientationAreNot) {
    Mesh open = make_box({0, 0, 0}, {1, 1, 1});
    open.triangles.pop_back();
    EXPECT_FALSE(closed_cycle(open));
    Mesh inconsistent = make_box({0, 0, 0}, {1, 1, 1});
    std::swap(inconsistent.triangles[0][0], inconsistent.triangles[0][1]);
    EXPECT_FALSE(closed_cycle(inconsistent));
}

TEST(ClosedManifold, SphereIsAndDefectsAreNot) {
    const Mesh sphere = make_sphere({0, 0, 0}, 1.0, 2);
    EXPECT_TRUE(volume::is_closed_manifold(sphere));
    Mesh open = sphere;
    open.triangles.pop_back();
    EXPECT_FALSE(volume::is_closed_manifold(open));
    // Two spheres sharing one vertex index: a pinched vertex.
    Mesh pinched = merged(sphere, sphere);
    const uint32_t offset = uint32_t(sphere.vertices.size());
    for (auto& t : pinched.triangles)
        for (auto& v : t)
            if (v == offset) v = 0;
    EXPECT_FALSE(volume::is_closed_manifold(pinched));
    Mesh duplicated = sphere;
    duplicated.triangles.push_back(sphere.triangles[0]);
    EXPECT_FALSE(volume::is_closed_manifold(duplicated));
    Mesh inconsistent = sphere;
    std::swap(inconsistent.triangles[0][0], inconsistent.triangles[0][1]);
    EXPECT_FALSE(volume::is_closed_manifold(inconsistent));
}

TEST(CrossingPairs, CleanSphereHasNone) {
    EXPECT_TRUE(volume::crossing_pairs(make_sphere({0, 0, 0}, 1.0, 4)).empty());
}

TEST(CrossingPairs, OverlappingSpheresCrossAlongTheirMeetingCircle) {
    const Mesh spheres = merged(make_sphere({0, 0, 0}, 1.0, 3), make_sphere({1.2, 0.1, 0.05}, 1.0, 3));
    const auto fast = fast_pairs(spheres);
    EXPECT_FALSE(fast.empty());
    EXPECT_EQ(fast, reference_pairs(spheres));
}

TEST(CrossingPairs, AgreesWithCgalOnJitteredSpheres) {
    std::mt19937 random(7);
    for (int round = 0; round < 6; ++round) {
        Mesh sphere = make_sphere({0, 0, 0}, 1.0, 3);
        // Strong jitter folds neighbouring triangles onto each other.
        std::normal_distribution<double> jitter(0.0, 0.01 * (round + 1));
        for (auto& v : sphere.vertices)
            for (double& x : v) x += jitter(random);
        const auto reference = reference_pairs(sphere);
        EXPECT_EQ(fast_pairs(sphere), reference) << "round " << round;
        if (round == 5) EXPECT_FALSE(reference.empty()) << "the test should see crossings";
        // Candidates restrict the pairs to those with a candidate in them.
        std::vector<char> candidates(sphere.triangles.size(), 0);
        for (size_t t = 0; t < candidates.size(); t += 3) candidates[t] = 1;
        std::set<std::pair<uint32_t, uint32_t>> expected;
        for (const auto& pair : reference)
            if (candidates[pair.first] || candidates[pair.second]) expected.insert(pair);
        EXPECT_EQ(fast_pairs(sphere, candidates), expected) << "round " << round;
    }
}

TEST(CrossingPairs, LargeTrianglesMeetSmallOnes) {
    // A sphere of small triangles pierced by one large thin triangle (its own
    // size class in the broad phase).
    Mesh mesh = make_sphere({0, 0, 0}, 1.0, 4);
    const uint32_t first = uint32_t(mesh.vertices.size());
    mesh.vertices.push_back({-5.0, 0.01, -5.0});
    mesh.vertices.push_back({5.0, 0.02, -5.0});
    mesh.vertices.push_back({0.0, -0.01, 5.0});
    mesh.triangles.push_back({first, first + 1, first + 2});
    const auto fast = fast_pairs(mesh);
    EXPECT_GT(fast.size(), 20u);
    EXPECT_EQ(fast, reference_pairs(mesh));
    for (const auto& pair : fast) EXPECT_EQ(pair.second, uint32_t(mesh.triangles.size() - 1));
    std::vector<char> only_large(mesh.triangles.size(), 0);
    only_large.back() = 1;
    EXPECT_EQ(fast_pairs(mesh, only_large), fast);
}

TEST(CrossingPairs, CoplanarTrianglesCrossOnlyWhereTheyOverlapOrTouch) {
    // A flat grid: its triangles two apart lie in one plane with overlapping
    // boxes and must be told apart without crossing. Three loose triangles in
    // the same plane: one overlapping a few grid triangles, one touching a
    // grid vertex with a corner, one beyond the grid's corner (x + y >= 6.1,
    // the grid <= 6) whose box overlaps the grid's.
    Mesh mesh;
    constexpr int n = 12;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) mesh.vertices.push_back({0.25 * i, 0.25 * j + 0.03 * (i % 3), 0.0});
    for (uint32_t i = 0; i < n; ++i)
        for (uint32_t j = 0; j < n; ++j) {
            const uint32_t a = i * (n + 1) + j, b = a + n + 1;
            mesh.triangles.push_back({a, b, b + 1});
            mesh.triangles.push_back({a, b + 1, a + 1});
        }
    const auto loose = [&mesh](fabvdb::Vec3 a, fabvdb::Vec3 b, fabvdb::Vec3 c) {
        const uint32_t first = uint32_t(mesh.vertices.size());
        mesh.vertices.insert(mesh.vertices.end(), {a, b, c});
        mesh.triangles.push_back({first, first + 1, first + 2});
    };
    loose({1.1, 1.1, 0.0}, {1.6, 1.2, 0.0}, {1.3, 1.7, 0.0});
    loose({-0.5, 1.0, 0.0}, {0.0, 1.0, 0.0}, {-0.5, 1.3, 0.0});
    loose({2.8, 3.3, 0.0}, {3.3, 2.8, 0.0}, {3.3, 3.3, 0.0});
    const auto reference = reference_pairs(mesh);
    EXPECT_GT(reference.size(), 4u);
    EXPECT_EQ(fast_pairs(mesh), reference);
    const uint32_t apart = uint32_t(mesh.triangles.size() - 1);
    for (const auto& pair : reference) EXPECT_NE(pair.second, apart);
}

TEST(CrossingPairs, FanWindingTwiceAroundItsVertexCrosses) {
    // Every triangle around the centre turns the same way seen from above, but
    // the fan goes round twice (72 degrees a step, 10 steps) at heights that
    // change sign: triangles half a fan apart cross. Pairs sharing a vertex
    // whose fan winds once are skipped; this one must still be tested.
    Mesh fan;
    fan.vertices.push_back({0.0, 0.0, 0.0});
    const double pi = std::acos(-1.0);
    for (int k = 0; k < 10; ++k) {
        const double angle = 2.0 * pi * k / 5.0, height = 0.3 * std::sin(2.0 * pi * (k + 0.5) / 10.0);
        fan.vertices.push_back({std::cos(angle), std::sin(angle), height});
    }
    for (uint32_t k = 0; k < 10; ++k) fan.triangles.push_back({0, 1 + k, 1 + (k + 1) % 10});
    const auto reference = reference_pairs(fan);
    EXPECT_FALSE(reference.empty());
    EXPECT_EQ(fast_pairs(fan), reference);
}

}  // namespace
