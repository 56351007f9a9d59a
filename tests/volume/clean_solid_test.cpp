// The clean-solid test: closed oriented solids pass; crossing shells,
// wherever the crossing lies along the part (the self-intersection test runs
// in slabs), open or inconsistently oriented surfaces and flat slivers fail. The meshes are
// built by hand, so the expected answer is known without running any test.
// With candidates, the crossings found are CGAL's self-intersections with a
// candidate in them.
#include "volume/clean_solid.h"

#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <atomic>
#include <functional>
#include <random>
#include <set>

#include "core/error.h"
#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

TEST(CleanSolid, ClosedOrientedSolidsPass) {
    Progress progress;
    EXPECT_TRUE(check_solid(test::make_box({0, 0, 0}, {80, 10, 10}), progress).clean);
    EXPECT_TRUE(check_solid(test::make_torus({0, 0, 0}, 20, 6, 64, 32), progress).clean);
    // A solid with a void: the void's shell faces inward.
    EXPECT_TRUE(check_solid(test::merged(test::make_box({0, 0, 0}, {30, 30, 30}),
                                         test::flipped(test::make_box({5, 5, 5}, {25, 25, 25}))),
                            progress)
                    .clean);
    // Two separate solids.
    EXPECT_TRUE(check_solid(
                    test::merged(test::make_box({0, 0, 0}, {10, 10, 10}), test::make_box({20, 0, 0}, {30, 10, 10})),
                    progress)
                    .clean);
}

TEST(CleanSolid, CrossingShellsFailWhereverTheCrossingLies) {
    Progress progress;
    const Mesh bar = test::make_box({0, 0, 0}, {80, 10, 10});
    // A small cube through the bar's top face, moved along the whole bar
    // (slab boundaries at multiples of 10 mm included).
    for (double x = -1.0; x <= 79.0; x += 2.5) {
        const Mesh crossing = test::merged(bar, test::make_box({x, 4, 8}, {x + 2, 6, 12}));
        const SolidCheck check = check_solid(crossing, progress);
        EXPECT_FALSE(check.clean) << "cube at x = " << x;
        // Closed, oriented and manifold otherwise: the crossings come back.
        EXPECT_FALSE(check.crossings.empty()) << "cube at x = " << x;
    }
    // Touching along a face counts as crossing too.
    EXPECT_FALSE(check_solid(test::merged(bar, test::make_box({40, 0, 10}, {42, 10, 12})), progress).clean);
}

//! CGAL's crossing pairs of `mesh` (its own broad phase and predicates) with
//! a candidate in them, as (i, j), i < j.
std::set<std::pair<uint32_t, uint32_t>> reference_crossings(const Mesh& mesh, const std::vector<char>& candidates) {
    using Point = CGAL::Epick::Point_3;
    using SurfaceMesh = CGAL::Surface_mesh<Point>;
    SurfaceMesh surface;
    for (const Vec3& p : mesh.vertices) surface.add_vertex(Point(p[0], p[1], p[2]));
    for (const Triangle& t : mesh.triangles)
        surface.add_face(SurfaceMesh::Vertex_index(t[0]), SurfaceMesh::Vertex_index(t[1]),
                         SurfaceMesh::Vertex_index(t[2]));
    EXPECT_EQ(surface.number_of_faces(), mesh.triangles.size());
    std::vector<std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>> faces;
    CGAL::Polygon_mesh_processing::self_intersections(surface, std::back_inserter(faces));
    std::set<std::pair<uint32_t, uint32_t>> pairs;
    for (const auto& [f, g] : faces)
        if (candidates[size_t(f)] || candidates[size_t(g)]) pairs.insert(std::minmax(uint32_t(f), uint32_t(g)));
    return pairs;
}

std::vector<char> candidates_where(const Mesh& mesh, const std::function<bool(uint32_t, const Vec3&)>& wanted) {
    std::vector<char> candidates(mesh.triangles.size(), 0);
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        Vec3 centre{0, 0, 0};
        for (uint32_t v : mesh.triangles[t])
            for (int k = 0; k < 3; ++k) centre[k] += mesh.vertices[v][k] / 3.0;
        candidates[t] = wanted(t, centre);
    }
    return candidates;
}

TEST(CleanSolid, CandidateCrossingsAreAllThoseWithACandidate) {
    Progress progress;
    // Small candidates against the large triangles of a box they cross
    // (each large one meets many cells of the candidates' grid), and a
    // random tenth of two crossing spheres' triangles.
    const Mesh box_and_sphere =
        test::merged(test::make_box({0, 0, 0}, {40, 40, 40}), test::make_sphere({20, 20, 40}, 5, 4));
    std::mt19937 random(7);
    const Mesh spheres = test::merged(test::make_sphere({0, 0, 0}, 10, 4), test::make_sphere({12, 3, 1}, 8, 4));
    const struct {
        const Mesh& mesh;
        std::vector<char> candidates;
        const char* what;
    } cases[] = {
        {box_and_sphere, candidates_where(box_and_sphere, [](uint32_t t, const Vec3& c) { return t >= 12 && c[2] > 37; }),
         "sphere cap through the box's top"},
        {box_and_sphere, candidates_where(box_and_sphere, [](uint32_t t, const Vec3& c) { return t >= 12 && c[2] < 38; }),
         "sphere bottom, inside the box"},
        {box_and_sphere, candidates_where(box_and_sphere, [](uint32_t t, const Vec3&) { return t < 12; }), "box"},
        {spheres, candidates_where(spheres, [&](uint32_t, const Vec3&) { return random() % 10 == 0; }),
         "random tenth of two spheres"},
    };
    for (const auto& [mesh, candidates, what] : cases) {
        const SolidCheck check = check_solid(mesh, progress, candidates);
        const std::set<std::pair<uint32_t, uint32_t>> found(check.crossings.begin(), check.crossings.end());
        EXPECT_EQ(found.size(), check.crossings.size()) << what;
        EXPECT_EQ(found, reference_crossings(mesh, candidates)) << what;
    }
    EXPECT_FALSE(reference_crossings(box_and_sphere, cases[0].candidates).empty());
    EXPECT_TRUE(reference_crossings(box_and_sphere, cases[1].candidates).empty());
    EXPECT_FALSE(reference_crossings(spheres, cases[3].candidates).empty());
}

TEST(CleanSolid, OpenOrMisorientedSurfacesFail) {
    Progress progress;
    Mesh open = test::make_box({0, 0, 0}, {10, 10, 10});
    open.triangles.pop_back();
    const SolidCheck open_check = check_solid(open, progress);
    EXPECT_FALSE(open_check.clean);
    EXPECT_TRUE(open_check.crossings.empty());  // not closed: not tested for crossings
    Mesh misoriented = test::make_box({0, 0, 0}, {10, 10, 10});
    std::swap(misoriented.triangles[0][1], misoriented.triangles[0][2]);
    EXPECT_FALSE(check_solid(misoriented, progress).clean);
    // Inside out as a whole: encloses no volume, as one shell and as a void
    // with no solid around it.
    EXPECT_FALSE(check_solid(test::flipped(test::make_box({0, 0, 0}, {10, 10, 10})), progress).clean);
    EXPECT_FALSE(check_solid(test::merged(test::flipped(test::make_box({0, 0, 0}, {30, 30, 30})),
                                          test::make_box({5, 5, 5}, {25, 25, 25})),
                             progress)
                     .clean);
    // A void outside the solid: a positive total volume, but no volume bounded.
    EXPECT_FALSE(check_solid(test::merged(test::make_box({0, 0, 0}, {30, 30, 30}),
                                          test::flipped(test::make_box({40, 0, 0}, {45, 5, 5}))),
                             progress)
                     .clean);
}

TEST(CleanSolid, FlatTetrahedraFailThinPlatesPass) {
    Progress progress;
    // A tetrahedron whose apex lies h above the base triangle (10 mm across,
    // diagonal 14 mm): its mean thickness 2V/A is about h/3, so h = 1e-5 and
    // 1e-3 mm are flat (under 1e-4 of the diagonal), 0.01 mm is not.
    const auto tetrahedron = [](double h) {
        Mesh mesh;
        mesh.vertices = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {3, 3, h}};
        mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
        return mesh;
    };
    EXPECT_TRUE(check_solid(tetrahedron(1.0), progress).clean);
    EXPECT_TRUE(check_solid(tetrahedron(0.01), progress).clean);
    EXPECT_FALSE(check_solid(tetrahedron(1e-3), progress).clean);
    EXPECT_FALSE(check_solid(tetrahedron(1e-5), progress).clean);
    EXPECT_TRUE(check_solid(test::make_box({0, 0, 0}, {60, 60, 0.1}), progress).clean);
}

TEST(CleanSolid, AFlatShellBesideASolidOneFails) {
    Progress progress;
    // A 20 mm cube (diagonal with the sliver about 48 mm, so flat is under
    // 0.005 mm) and apart from it a sliver tetrahedron 1e-4 mm high: the
    // mesh's volume and mean thickness are the cube's, yet one shell is flat.
    Mesh mesh = test::make_box({0, 0, 0}, {20, 20, 20});
    const uint32_t base = uint32_t(mesh.vertices.size());
    for (const Vec3& p : std::vector<Vec3>{{30, 0, 0}, {40, 0, 0}, {30, 10, 0}, {33, 3, 1e-4}})
        mesh.vertices.push_back(p);
    const std::vector<Triangle> sliver = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
    for (const Triangle& t : sliver) mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    EXPECT_FALSE(check_solid(mesh, progress).clean);
    mesh.vertices.back()[2] = 1.0;
    EXPECT_TRUE(check_solid(mesh, progress).clean);
}

TEST(CleanSolid, CancelledThrows) {
    std::atomic<bool> cancel{true};
    Progress progress(nullptr, nullptr, &cancel);
    try {
        check_solid(test::make_box({0, 0, 0}, {80, 10, 10}), progress);
        ADD_FAILURE() << "not cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
}  // namespace fabvdb::volume
