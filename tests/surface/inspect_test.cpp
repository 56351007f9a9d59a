// Tests of the mesh inspection behind `fabvdb info` on synthetic meshes whose
// answers are known by construction: boxes, a torus, and hand-made defects
// (holes, non-manifold edges and vertices, flipped, duplicated and degenerate
// triangles, intersecting and touching triangles). Expected numbers are counted
// by hand in the comments; self-intersections are also checked against an
// all-pairs sweep with CGAL's exact-construction kernel.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <random>
#include <string>
#include <variant>
#include <utility>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include "core/error.h"
#include "surface/inspect.h"
#include "surface/self_intersections.h"
#include "support/shapes.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Triangle;
using fabvdb::Vec3;
using nlohmann::json;

json inspect(const Mesh& mesh) {
    fabvdb::Progress progress;
    return fabvdb::surface::inspect_mesh(mesh, progress);
}

//! `b` appended to `a`, where b's vertices at a position of one of a's
//! vertices become that vertex (a test-side weld by a plain search).
Mesh glued(const Mesh& a, const Mesh& b) {
    Mesh out = a;
    std::vector<uint32_t> index(b.vertices.size());
    for (size_t i = 0; i < b.vertices.size(); ++i) {
        index[i] = uint32_t(out.vertices.size());
        for (size_t j = 0; j < a.vertices.size(); ++j)
            if (a.vertices[j] == b.vertices[i]) index[i] = uint32_t(j);
        if (index[i] == out.vertices.size()) out.vertices.push_back(b.vertices[i]);
    }
    for (const Triangle& t : b.triangles) out.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
    return out;
}

//! The unit box's triangles lying in the plane `axis` = `value`.
std::vector<size_t> triangles_in_plane(const Mesh& mesh, int axis, double value) {
    std::vector<size_t> found;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        bool in_plane = true;
        for (uint32_t v : mesh.triangles[t]) in_plane = in_plane && mesh.vertices[v][axis] == value;
        if (in_plane) found.push_back(t);
    }
    return found;
}

Mesh without_triangles(Mesh mesh, std::vector<size_t> drop) {
    std::sort(drop.rbegin(), drop.rend());
    for (size_t t : drop) mesh.triangles.erase(mesh.triangles.begin() + long(t));
    return mesh;
}

void expect_clean_closed(const json& r) {
    EXPECT_TRUE(r["closed"].get<bool>());
    EXPECT_EQ(r["boundary_edges"], 0);
    EXPECT_EQ(r["boundary_loops"], 0);
    EXPECT_EQ(r["non_manifold_edges"], 0);
    EXPECT_EQ(r["non_manifold_vertices"], 0);
    EXPECT_EQ(r["degenerate_triangles"], 0);
    EXPECT_EQ(r["duplicate_triangles"], 0);
    EXPECT_EQ(r["self_intersecting_pairs"], 0);
    EXPECT_EQ(r["inconsistent_edges"], 0);
    EXPECT_TRUE(r["consistently_oriented"].get<bool>());
    EXPECT_EQ(r["unreferenced_vertices"], 0);
}

TEST(Inspect, BoxIsCleanAndItsVolumeExact) {
    const json r = inspect(fabvdb::test::make_box({1, 2, 3}, {2, 4, 6}));
    EXPECT_EQ(r["vertices"], 8);
    EXPECT_EQ(r["triangles"], 12);
    EXPECT_EQ(r["components"], 1);
    expect_clean_closed(r);
    EXPECT_EQ(r["volume"].get<double>(), 1.0 * 2.0 * 3.0);  // exact: small integers and halves
    EXPECT_EQ(r["negative_volume_shells"], 0);
    EXPECT_EQ(r["genus"], 0);
    EXPECT_EQ(r["bbox"]["min"], json({1, 2, 3}));
    EXPECT_EQ(r["bbox"]["max"], json({2, 4, 6}));
    EXPECT_EQ(r["welded"]["components"], 1);
    EXPECT_TRUE(r["welded"]["closed"].get<bool>());
}

// Sizes that suggest other units, and places far from the origin, are
// warned about; a part in millimetres near the origin is not.
TEST(Inspect, SizeAndPlaceSuggestingOtherUnitsAreWarnedAbout) {
    EXPECT_EQ(inspect(fabvdb::test::make_box({1, 2, 3}, {2, 4, 6}))["warnings"], json::array());
    const json metres = inspect(fabvdb::test::make_box({0, 0, 0}, {0.045, 0.03, 0.01}))["warnings"];
    ASSERT_EQ(metres.size(), 1u);
    EXPECT_NE(metres[0].get<std::string>().find("0.045 mm across"), std::string::npos) << metres[0];
    EXPECT_NE(metres[0].get<std::string>().find("--scale 1000"), std::string::npos) << metres[0];
    const json huge = inspect(fabvdb::test::make_box({0, 0, 0}, {3000, 10, 10}))["warnings"];
    ASSERT_EQ(huge.size(), 1u);
    EXPECT_NE(huge[0].get<std::string>().find("3e+03 mm across"), std::string::npos) << huge[0];
    const json far = inspect(fabvdb::test::make_box({4e6, 0, 0}, {4e6 + 40, 40, 40}))["warnings"];
    ASSERT_EQ(far.size(), 1u);
    EXPECT_NE(far[0].get<std::string>().find("from the origin"), std::string::npos) << far[0];
    EXPECT_NE(far[0].get<std::string>().find("0.25 mm apart"), std::string::npos) << far[0];
}

TEST(Inspect, TorusHasGenusOne) {
    const Mesh torus = fabvdb::test::make_torus({0, 0, 0}, 3.0, 1.0, 32, 16);
    const json r = inspect(torus);
    expect_clean_closed(r);
    EXPECT_EQ(r["genus"], 1);
    EXPECT_EQ(r["components"], 1);
    // Polyhedral volume (independent sum in the test support), and within 4 % of
    // 2π²Rr² (the inscribed polygons of 32 and 16 sides lose about 3.2 %).
    EXPECT_NEAR(r["volume"].get<double>(), fabvdb::test::mesh_volume(torus), 1e-9);
    EXPECT_NEAR(r["volume"].get<double>(), 2 * M_PI * M_PI * 3.0, 0.04 * 2 * M_PI * M_PI * 3.0);
}

TEST(Inspect, SphereAndTwoToriAddUpGenus) {
    const Mesh mesh = fabvdb::test::merged(
        fabvdb::test::make_sphere({0, 0, 0}, 1.0, 2),
        fabvdb::test::merged(fabvdb::test::make_torus({5, 0, 0}, 2.0, 0.5, 24, 8),
                             fabvdb::test::make_torus({12, 0, 0}, 2.0, 0.5, 24, 8)));
    const json r = inspect(mesh);
    expect_clean_closed(r);
    EXPECT_EQ(r["components"], 3);
    EXPECT_EQ(r["genus"], 2);  // 0 + 1 + 1
}

TEST(Inspect, BoxWithAFaceRemovedHasOneHole) {
    const Mesh box = fabvdb::test::make_box({0, 0, 0}, {1, 1, 1});
    const json r = inspect(without_triangles(box, triangles_in_plane(box, 2, 1.0)));
    EXPECT_FALSE(r["closed"].get<bool>());
    EXPECT_EQ(r["triangles"], 10);
    EXPECT_EQ(r["boundary_edges"], 4);  // the square's four sides
    EXPECT_EQ(r["boundary_loops"], 1);
    EXPECT_EQ(r["non_manifold_edges"], 0);
    EXPECT_EQ(r["non_manifold_vertices"], 0);
    EXPECT_TRUE(r["volume"].is_null());
    EXPECT_TRUE(r["genus"].is_null());
    EXPECT_TRUE(r["consistently_oriented"].get<bool>());
}

TEST(Inspect, TubeHasTwoHoles) {
    const Mesh box = fabvdb::test::make_box({0, 0, 0}, {1, 1, 1});
    std::vector<size_t> ends = triangles_in_plane(box, 0, 0.0);
    for (size_t t : triangles_in_plane(box, 0, 1.0)) ends.push_back(t);
    const json r = inspect(without_triangles(box, ends));
    EXPECT_EQ(r["boundary_edges"], 8);
    EXPECT_EQ(r["boundary_loops"], 2);
    EXPECT_EQ(r["components"], 1);
}

TEST(Inspect, BoxesGluedOnAnEdgeHaveANonManifoldEdge) {
    // The vertical edge x = y = 1, z in [0, 1] is a side of two triangles of each box.
    const Mesh mesh = glued(fabvdb::test::make_box({0, 0, 0}, {1, 1, 1}), fabvdb::test::make_box({1, 1, 0}, {2, 2, 1}));
    ASSERT_EQ(mesh.vertices.size(), 14u);
    const json r = inspect(mesh);
    EXPECT_EQ(r["non_manifold_edges"], 1);
    EXPECT_EQ(r["boundary_edges"], 0);
    EXPECT_FALSE(r["closed"].get<bool>());
    EXPECT_EQ(r["components"], 1);
    // The edge's end points: the four triangles along the edge join both boxes' fans.
    EXPECT_EQ(r["non_manifold_vertices"], 0);
    EXPECT_EQ(r["self_intersecting_pairs"], 0);  // the boxes meet only on the shared edge
    EXPECT_TRUE(r["volume"].is_null());
}

TEST(Inspect, TetrahedraSharingAVertexHaveANonManifoldVertex) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3},   // outward tetrahedron in +x+y+z
                      {0, 4, 5}, {0, 6, 4}, {0, 5, 6}, {4, 6, 5}};  // its mirror image through 0
    const json r = inspect(mesh);
    EXPECT_EQ(r["non_manifold_vertices"], 1);
    EXPECT_EQ(r["non_manifold_edges"], 0);
    EXPECT_EQ(r["boundary_edges"], 0);
    EXPECT_TRUE(r["closed"].get<bool>());
    EXPECT_EQ(r["components"], 1);
    EXPECT_TRUE(r["genus"].is_null());  // not a manifold
    EXPECT_TRUE(r["consistently_oriented"].get<bool>());
    EXPECT_NEAR(r["volume"].get<double>(), 2.0 / 6.0, 1e-15);
    EXPECT_EQ(r["self_intersecting_pairs"], 0);
}

TEST(Inspect, FlippedTriangleMakesThreeInconsistentEdges) {
    Mesh box = fabvdb::test::make_box({0, 0, 0}, {1, 1, 1});
    std::swap(box.triangles[5][1], box.triangles[5][2]);
    const json r = inspect(box);
    EXPECT_EQ(r["inconsistent_edges"], 3);
    EXPECT_FALSE(r["consistently_oriented"].get<bool>());
    EXPECT_TRUE(r["closed"].get<bool>());
}

TEST(Inspect, InsideOutBoxHasNegativeVolume) {
    const json r = inspect(fabvdb::test::flipped(fabvdb::test::make_box({0, 0, 0}, {2, 2, 2})));
    EXPECT_TRUE(r["consistently_oriented"].get<bool>());
    EXPECT_EQ(r["volume"].get<double>(), -8.0);
    EXPECT_EQ(r["negative_volume_shells"], 1);
}

TEST(Inspect, DuplicatedTriangle) {
    Mesh box = fabvdb::test::make_box({0, 0, 0}, {1, 1, 1});
    const Triangle t = box.triangles[0];
    box.triangles.push_back({t[1], t[2], t[0]});  // same triangle, rotated
    box.triangles.push_back({t[0], t[2], t[1]});  // same corners, flipped
    const json r = inspect(box);
    EXPECT_EQ(r["duplicate_triangles"], 2);
    EXPECT_EQ(r["non_manifold_edges"], 3);  // each side of t is now used four times
    EXPECT_FALSE(r["closed"].get<bool>());
    EXPECT_EQ(r["self_intersecting_pairs"], 0);  // copies share their corners
}

TEST(Inspect, DegenerateTriangles) {
    Mesh box = fabvdb::test::make_box({0, 0, 0}, {4, 4, 4});
    const uint32_t n = uint32_t(box.vertices.size());
    box.vertices.push_back({10, 0, 0});
    box.vertices.push_back({11, 1, 1});
    box.vertices.push_back({13, 3, 3});              // collinear with the two before
    box.vertices.push_back({10, 0, 1e-300});         // off their line by a hair: not degenerate
    box.vertices.push_back({12, 2, 2});              // twice at the same position
    box.vertices.push_back({12, 2, 2});
    box.triangles.push_back({n, n + 1, n + 2});      // collinear
    box.triangles.push_back({n + 1, n + 1, n + 2});  // repeated index
    box.triangles.push_back({n + 4, n + 5, n});      // two corners coincide
    box.triangles.push_back({n + 1, n + 3, n + 2});  // sliver, but a real triangle
    const json r = inspect(box);
    EXPECT_EQ(r["degenerate_triangles"], 3);
    EXPECT_EQ(r["degenerate_triangle_indices"], json({12, 13, 14}));
    EXPECT_EQ(r["vertices"], 14);
    EXPECT_EQ(r["welded"]["vertices"], 13);
}

TEST(Inspect, NegativeZeroIsTheSamePositionAsZero) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-0.0, 0, -0.0}, {0, -1, 0}, {1, 0, 0}};
    mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
    const json r = inspect(mesh);
    EXPECT_EQ(r["components"], 2);
    EXPECT_EQ(r["welded"]["vertices"], 4);
    EXPECT_EQ(r["welded"]["components"], 1);
    EXPECT_EQ(r["welded"]["boundary_edges"], 4);  // the shared side joins the two triangles
    EXPECT_EQ(r["self_intersecting_pairs"], 0);   // they share positions
}

TEST(Inspect, MeshWithoutTrianglesIsNotClosed) {
    Mesh mesh;
    mesh.vertices = {{1, 2, 3}, {4, 5, 6}};
    const json r = inspect(mesh);
    EXPECT_EQ(r["triangles"], 0);
    EXPECT_EQ(r["unreferenced_vertices"], 2);
    EXPECT_EQ(r["components"], 0);
    EXPECT_FALSE(r["closed"].get<bool>());
    EXPECT_TRUE(r["volume"].is_null());
    EXPECT_TRUE(r["genus"].is_null());
    EXPECT_EQ(r["self_intersecting_pairs"], 0);
}

TEST(Inspect, UnreferencedVerticesAreCountedButNotInTheBox) {
    Mesh box = fabvdb::test::make_box({0, 0, 0}, {1, 1, 1});
    box.vertices.push_back({50, 50, 50});
    const json r = inspect(box);
    EXPECT_EQ(r["unreferenced_vertices"], 1);
    EXPECT_EQ(r["vertices"], 9);
    EXPECT_EQ(r["bbox"]["max"], json({1, 1, 1}));
    EXPECT_TRUE(r["closed"].get<bool>());
}

TEST(Inspect, UnweldedSeamCountsOnlyAfterWelding) {
    // Two halves of a box that share positions but not indices along their seam.
    const Mesh box = fabvdb::test::make_box({0, 0, 0}, {1, 1, 1});
    Mesh split = box;
    const std::vector<size_t> top = triangles_in_plane(box, 2, 1.0);
    for (size_t t : top)
        for (uint32_t& v : split.triangles[t]) {
            split.vertices.push_back(box.vertices[v]);
            v = uint32_t(split.vertices.size() - 1);
        }
    const json r = inspect(split);
    EXPECT_EQ(r["components"], 3);          // the two top triangles were cut from each other too
    EXPECT_EQ(r["boundary_edges"], 10);     // 3 + 3 for the loose triangles, 4 around the open top
    EXPECT_EQ(r["self_intersecting_pairs"], 0);  // neighbours across the seam share positions
    EXPECT_EQ(r["welded"]["components"], 1);
    EXPECT_EQ(r["welded"]["boundary_edges"], 0);
    EXPECT_TRUE(r["welded"]["closed"].get<bool>());
    EXPECT_EQ(r["welded"]["vertices"], 8);
}

TEST(Inspect, PillarThroughABoxMakesEightPairs) {
    // The pillar's eight side triangles cross the box's top face inside its
    // triangle on the side x < y (the face's diagonal is x = y): 8 pairs.
    const Mesh mesh = fabvdb::test::merged(fabvdb::test::make_box({0, 0, 0}, {2, 2, 2}),
                                           fabvdb::test::make_box({0.2, 1.2, 1}, {0.6, 1.8, 3}));
    const json r = inspect(mesh);
    EXPECT_EQ(r["self_intersecting_pairs"], 8);
    EXPECT_EQ(r["self_intersecting_pairs_degenerate"], 0);
    EXPECT_EQ(r["components"], 2);
    EXPECT_TRUE(r["closed"].get<bool>());
    // The triangles to show: the pillar's eight sides (its triangles, after
    // the box's 12, not lying in z = 1 or z = 3) and the box's top triangle
    // under it (in z = 2, holding the pillar's footprint centre (0.4, 1.5)).
    std::vector<uint32_t> expected;
    for (size_t t = 0; t < 12; ++t) {
        const auto& c = mesh.triangles[t];
        const Vec3 &a = mesh.vertices[c[0]], &b = mesh.vertices[c[1]], &d = mesh.vertices[c[2]];
        if (a[2] != 2 || b[2] != 2 || d[2] != 2) continue;
        const auto side = [](const Vec3& p, const Vec3& q) {
            return (q[0] - p[0]) * (1.5 - p[1]) - (q[1] - p[1]) * (0.4 - p[0]);
        };
        const double s0 = side(a, b), s1 = side(b, d), s2 = side(d, a);
        if ((s0 > 0 && s1 > 0 && s2 > 0) || (s0 < 0 && s1 < 0 && s2 < 0)) expected.push_back(uint32_t(t));
    }
    for (size_t t = 12; t < mesh.triangles.size(); ++t) {
        const auto& c = mesh.triangles[t];
        const double z0 = mesh.vertices[c[0]][2], z1 = mesh.vertices[c[1]][2], z2 = mesh.vertices[c[2]][2];
        if (!(z0 == z1 && z1 == z2)) expected.push_back(uint32_t(t));
    }
    ASSERT_EQ(expected.size(), 9u);
    EXPECT_EQ(r["self_intersecting_triangle_indices"].get<std::vector<uint32_t>>(), expected);
}

std::vector<std::pair<uint32_t, uint32_t>> pairs_of(const Mesh& mesh) {
    fabvdb::Progress progress;
    return fabvdb::surface::self_intersecting_pairs(mesh, progress);
}

TEST(SelfIntersections, CoplanarOverlapAndTouching) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0},   {2, 0, 0},   {0, 2, 0},     // A
                     {1, 1, 0},   {3, 1, 0},   {1, 3, 0},     // B: corner on A's long side (touch)
                     {0.5, 0.5, 0}, {3, 0.5, 0}, {0.5, 3, 0},  // C: overlaps A and B in their plane
                     {5, 5, 0},   {6, 5, 0},   {5, 6, 0.5}};  // D: apart
    mesh.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}};
    const std::vector<std::pair<uint32_t, uint32_t>> expected = {{0, 1}, {0, 2}, {1, 2}};
    EXPECT_EQ(pairs_of(mesh), expected);
}

TEST(SelfIntersections, DegenerateTrianglesAreTestedAsSegmentsAndPoints) {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0},         {2, 0, 0},         {0, 2, 0},          // a triangle in z = 0
                     {0.5, 0.5, -1},    {0.5, 0.5, 0},     {0.5, 0.5, 1},     // a vertical needle through it
                     {0.25, 1, 0},      {0.25, 1, 0},      {0.25, 1, 0},      // a point on it
                     {1.5, 1.5, -1},    {1.5, 1.5, 1},                        // a needle beside it
                     {0.5, 0.5, 0.25}};
    mesh.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 9, 10}, {11, 11, 11}};
    // needle (1) pierces the triangle; the point (2) lies in it; the point-like
    // triangle 4 lies on the needle; the needle beside it (3) touches nothing.
    const std::vector<std::pair<uint32_t, uint32_t>> expected = {{0, 1}, {0, 2}, {1, 4}};
    EXPECT_EQ(pairs_of(mesh), expected);
    mesh.triangles.push_back({0, 1, 2});  // a duplicate: shares every corner with triangle 0
    const json r = inspect(mesh);
    EXPECT_EQ(r["self_intersecting_pairs"], 5);             // and meets the needle and the point
    EXPECT_EQ(r["self_intersecting_pairs_degenerate"], 5);  // every pair has a collapsed triangle
    EXPECT_EQ(r["degenerate_triangles"], 4);
}

TEST(SelfIntersections, AgreesWithAnAllPairsSweep) {
    // Random small triangles in a cube, some of them sharing corners and some
    // collapsed: every pair checked with the exact-construction kernel.
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(0.0, 4.0), offset(-0.8, 0.8);
    Mesh mesh;
    for (int i = 0; i < 300; ++i) {
        const Vec3 c{coordinate(random), coordinate(random), coordinate(random)};
        for (int k = 0; k < 3; ++k) mesh.vertices.push_back({c[0] + offset(random), c[1] + offset(random), c[2] + offset(random)});
        const uint32_t b = uint32_t(3 * i);
        mesh.triangles.push_back({b, b + 1, b + 2});
    }
    for (int i = 0; i < 30; ++i) {  // triangles reusing corners of others
        const uint32_t a = uint32_t(random() % mesh.vertices.size()), b = uint32_t(random() % mesh.vertices.size());
        mesh.vertices.push_back({coordinate(random), coordinate(random), coordinate(random)});
        mesh.triangles.push_back({a, b, uint32_t(mesh.vertices.size() - 1)});
    }
    mesh.vertices.push_back(mesh.vertices[0]);  // a copy of a position: shares it with triangle 0
    mesh.triangles.push_back({uint32_t(mesh.vertices.size() - 1), 100, 200});
    mesh.triangles.push_back({5, 5, 301});  // a segment
    mesh.triangles.push_back({7, 7, 7});    // a point (on triangle 2's corner: shares its position)

    // The point set of a triangle's corners, built another way than the code
    // under test does: the longest side for a collapsed triangle.
    using K = CGAL::Epeck;
    using CornerSet = std::variant<K::Triangle_3, K::Segment_3, K::Point_3>;
    auto corner_set = [&](const Triangle& t) -> CornerSet {
        auto point = [&](uint32_t v) { return K::Point_3(mesh.vertices[v][0], mesh.vertices[v][1], mesh.vertices[v][2]); };
        const K::Point_3 a = point(t[0]), b = point(t[1]), c = point(t[2]);
        if (!CGAL::collinear(a, b, c)) return K::Triangle_3(a, b, c);
        K::Segment_3 longest(a, b);
        for (const K::Segment_3& side : {K::Segment_3(b, c), K::Segment_3(a, c)})
            if (side.squared_length() > longest.squared_length()) longest = side;
        if (longest.is_degenerate()) return a;
        return longest;
    };
    auto hull_intersects = [&](const Triangle& s, const Triangle& t) {
        return std::visit([](const auto& x, const auto& y) { return CGAL::do_intersect(x, y); }, corner_set(s),
                          corner_set(t));
    };
    auto share_position = [&](const Triangle& s, const Triangle& t) {
        for (uint32_t u : s)
            for (uint32_t v : t)
                if (mesh.vertices[u] == mesh.vertices[v]) return true;
        return false;
    };
    std::vector<std::pair<uint32_t, uint32_t>> expected;
    for (uint32_t i = 0; i < mesh.triangles.size(); ++i)
        for (uint32_t j = i + 1; j < mesh.triangles.size(); ++j)
            if (!share_position(mesh.triangles[i], mesh.triangles[j]) &&
                hull_intersects(mesh.triangles[i], mesh.triangles[j]))
                expected.push_back({i, j});
    ASSERT_GT(expected.size(), 20u);  // the scene is dense enough to test something
    EXPECT_EQ(pairs_of(mesh), expected);
}

int cancel_at_once(void*, const char*, double) { return 1; }

TEST(Inspect, CancelThrowsAndReturnsNothing) {
    const Mesh mesh = fabvdb::test::make_sphere({0, 0, 0}, 1.0, 4);
    std::atomic<bool> flag{false};
    fabvdb::Progress progress(cancel_at_once, nullptr, &flag);
    try {
        fabvdb::surface::inspect_mesh(mesh, progress);
        FAIL() << "inspection was not cancelled";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

TEST(Inspect, CancelDuringSelfIntersections) {
    const Mesh mesh = fabvdb::test::make_sphere({0, 0, 0}, 1.0, 5);
    auto cancel_in_exact_tests = [](void*, const char* stage, double) {
        return std::string(stage).find("exact") != std::string::npos ? 1 : 0;
    };
    fabvdb::Progress progress(cancel_in_exact_tests, nullptr, nullptr);
    try {
        fabvdb::surface::inspect_mesh(mesh, progress);
        FAIL() << "inspection was not cancelled";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
        EXPECT_NE(std::string(e.what()).find("exact"), std::string::npos) << e.what();
    }
}

}  // namespace
