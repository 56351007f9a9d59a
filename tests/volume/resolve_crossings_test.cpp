// Resolving crossing triangles, checked with CGAL alone (surface mesh,
// self-intersection test, AABB distances, side of triangle mesh): the
// result is closed, crosses nothing, lies on the input's triangles, and is
// the boundary of the input's inside, facing outward also for an input
// stored inside out. Inputs with too many crossings are left to the repair;
// cancellation throws.
#include "volume/resolve_crossings.h"

#include <gtest/gtest.h>

#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <set>

#include "core/error.h"
#include "io/mesh_io.h"
#include "support/cgal_mesh.h"
#include "support/shapes.h"
#include "support/winding_number.h"
#include "volume/clean_solid.h"

namespace fabvdb::volume {
namespace {

using test::cgal::point;
using test::cgal::SurfaceMesh;
using test::cgal::Tree;
using test::cgal::Triangle3;
using test::cgal::triangles_of;

//! The input's winding number just in front of and just behind triangle t
//! of `mesh`, at its centre, a millionth of its inradius away (a sheet that
//! crosses its plane only along its sides, at any angle above a
//! millionth of a radian, passes farther away).
std::pair<double, double> sides(const Mesh& input, const Mesh& mesh, const Triangle& t) {
    Vec3 centre{0, 0, 0};
    const Vec3 normal = triangle_normal(mesh, t);
    double perimeter = 0.0;
    for (int k = 0; k < 3; ++k) {
        const Vec3 &a = mesh.vertices[t[k]], &b = mesh.vertices[t[(k + 1) % 3]];
        perimeter += std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
        for (int i = 0; i < 3; ++i) centre[i] += a[i] / 3.0;
    }
    const double twice_area = std::hypot(normal[0], normal[1], normal[2]);
    const double step = 1e-6 * (twice_area / perimeter) / twice_area;
    Vec3 front, back;
    for (int i = 0; i < 3; ++i) front[i] = centre[i] + step * normal[i], back[i] = centre[i] - step * normal[i];
    return {test::winding_number(input, front), test::winding_number(input, back)};
}

// dragon_20k is closed and manifold, but folds through itself in places (20
// crossing pairs). CGAL's own autorefine_and_remove_self_intersections keeps
// 6 of its triangles; the resolved surface keeps the whole dragon: it is
// closed and clean, lies on the input (but for the copies of a pinched
// vertex, parted by a hair), has the input's winding number 0 in front and 1
// behind (every cut piece and a sample of the rest), and the input triangles
// it drops are not on that boundary.
TEST(ResolveCrossings, DragonKeepsItsSurfaceWithoutTheFolds) {
    Progress progress;
    const Mesh dragon = io::read_mesh(FABVDB_SHARED_DATA "/meshes/dragon_20k.obj", progress);
    const SolidCheck check = check_solid(dragon, progress);
    ASSERT_FALSE(check.crossings.empty());
    const std::optional<Mesh> resolved = resolve_crossings(dragon, check.crossings, progress);
    ASSERT_TRUE(resolved.has_value());

    SurfaceMesh surface = test::cgal::surface_mesh_of(*resolved);
    EXPECT_TRUE(CGAL::is_closed(surface));
    EXPECT_FALSE(CGAL::Polygon_mesh_processing::does_self_intersect(surface));
    const double scale = bounding_box(dragon).diagonal();
    const std::vector<Triangle3> input = triangles_of(dragon);
    Tree input_tree(input.begin(), input.end());
    input_tree.accelerate_distance_queries();
    double farthest = 0.0;
    int off_input = 0;
    for (const Vec3& p : resolved->vertices) {
        const double distance = std::sqrt(input_tree.squared_distance(point(p)));
        farthest = std::max(farthest, distance);
        off_input += distance > 1e-12 * scale;
    }
    EXPECT_LE(off_input, 2);
    EXPECT_LE(farthest, 1e-4 * scale);
    EXPECT_GT(resolved->triangles.size(), dragon.triangles.size());

    // The cut pieces (a corner that is no input vertex, but on the input) and
    // every 97th triangle.
    std::set<std::array<double, 3>> input_vertices(dragon.vertices.begin(), dragon.vertices.end());
    int pieces = 0;
    for (size_t t = 0; t < resolved->triangles.size(); ++t) {
        const Triangle& triangle = resolved->triangles[t];
        bool piece = false, parted = false;
        for (uint32_t v : triangle) {
            const Vec3& p = resolved->vertices[v];
            piece |= !input_vertices.count(p);
            parted |= input_tree.squared_distance(point(p)) > 1e-24 * scale * scale;
        }
        if (parted || (!piece && t % 97 != 0)) continue;
        pieces += piece;
        const auto [front, back] = sides(dragon, *resolved, triangle);
        EXPECT_NEAR(front, 0.0, 0.1) << "output triangle " << t;
        EXPECT_NEAR(back, 1.0, 0.1) << "output triangle " << t;
    }
    EXPECT_GT(pieces, 0);

    // Points of the crossing input triangles (a grid on each) off the output:
    // not between winding numbers 0 and 1 (those at a parted pinch, whose
    // corner moved, aside).
    const std::vector<Triangle3> output = triangles_of(*resolved);
    Tree output_tree(output.begin(), output.end());
    output_tree.accelerate_distance_queries();
    const std::set<std::array<double, 3>> output_vertices(resolved->vertices.begin(), resolved->vertices.end());
    std::set<uint32_t> crossing;
    for (const auto& [a, b] : check.crossings) crossing.insert({a, b});
    int dropped = 0;
    constexpr int steps = 12;
    for (uint32_t index : crossing) {
        const Triangle& t = dragon.triangles[index];
        if (!output_vertices.count(dragon.vertices[t[0]]) || !output_vertices.count(dragon.vertices[t[1]]) ||
            !output_vertices.count(dragon.vertices[t[2]]))
            continue;
        const Vec3 normal = triangle_normal(dragon, t);
        const double step = 1e-9 * scale / std::hypot(normal[0], normal[1], normal[2]);
        for (int i = 1; i < steps; ++i)
            for (int j = 1; i + j < steps; ++j) {
                Vec3 p, front, back;
                for (int k = 0; k < 3; ++k) {
                    p[k] = (i * dragon.vertices[t[0]][k] + j * dragon.vertices[t[1]][k] +
                            (steps - i - j) * dragon.vertices[t[2]][k]) /
                           steps;
                    front[k] = p[k] + step * normal[k];
                    back[k] = p[k] - step * normal[k];
                }
                if (output_tree.squared_distance(point(p)) <= 1e-12 * scale * scale) continue;
                ++dropped;
                const double w_front = test::winding_number(dragon, front), w_back = test::winding_number(dragon, back);
                EXPECT_NEAR(w_back - w_front, 1.0, 0.1);
                EXPECT_GT(std::abs(w_front), 0.9) << "a dropped input point on the boundary";
            }
    }
    EXPECT_GT(dropped, 0);
}

// Two overlapping balls and the dragon, each stored inside out (every
// triangle turned round): the result is the same solid facing outward —
// the volume of the union, as resolved from the outward input, within a
// part in 1e6, and outward (positive volume, by the divergence theorem).
TEST(ResolveCrossings, InsideOutSurfaceGivesTheSameSolidFacingOut) {
    Progress progress;
    const Mesh balls =
        test::merged(test::make_sphere({0, 0, 0}, 10, 3), test::make_sphere({7.3, 1.1, 0.7}, 9, 3));
    const Mesh dragon = io::read_mesh(FABVDB_SHARED_DATA "/meshes/dragon_20k.obj", progress);
    for (const Mesh* outward : {&balls, &dragon}) {
        const SolidCheck check = check_solid(*outward, progress);
        ASSERT_FALSE(check.crossings.empty());
        const std::optional<Mesh> expected = resolve_crossings(*outward, check.crossings, progress);
        ASSERT_TRUE(expected.has_value());
        const Mesh inside_out = test::flipped(*outward);
        const SolidCheck turned = check_solid(inside_out, progress);
        ASSERT_EQ(turned.crossings.size(), check.crossings.size());
        const std::optional<Mesh> resolved = resolve_crossings(inside_out, turned.crossings, progress);
        ASSERT_TRUE(resolved.has_value());
        const double volume = test::mesh_volume(*expected);
        EXPECT_GT(volume, 0.0);
        EXPECT_NEAR(test::mesh_volume(*resolved), volume, 1e-6 * volume);
        SurfaceMesh surface = test::cgal::surface_mesh_of(*resolved);
        EXPECT_TRUE(CGAL::is_closed(surface));
        EXPECT_FALSE(CGAL::Polygon_mesh_processing::does_self_intersect(surface));
    }
}

// The result is the same on every run and whatever the order of the
// crossing pairs (CGAL's autorefinement orders its pieces, their corners and
// the cut points differently from run to run).
TEST(ResolveCrossings, SameResultEveryRun) {
    Progress progress;
    const Mesh dragon = io::read_mesh(FABVDB_SHARED_DATA "/meshes/dragon_20k.obj", progress);
    std::vector<std::pair<uint32_t, uint32_t>> crossings = check_solid(dragon, progress).crossings;
    ASSERT_FALSE(crossings.empty());
    const std::optional<Mesh> first = resolve_crossings(dragon, crossings, progress);
    ASSERT_TRUE(first.has_value());
    for (int run = 0; run < 8; ++run) {
        std::rotate(crossings.begin(), crossings.begin() + 1, crossings.end());
        const std::optional<Mesh> again = resolve_crossings(dragon, crossings, progress);
        ASSERT_TRUE(again.has_value());
        EXPECT_EQ(again->vertices, first->vertices) << "run " << run;
        EXPECT_EQ(again->triangles, first->triangles) << "run " << run;
    }
}

// A lattice of sticks, each crossing every stick across it: more crossings
// than resolving them pays for (the repair is left to do it), so no answer.
TEST(ResolveCrossings, TooManyCrossingsAreLeftToTheRepair) {
    Progress progress;
    Mesh lattice;
    for (int i = 0; i < 40; ++i) {
        const double at = 2.0 * i;
        lattice = test::merged(lattice, test::make_box({-1, at, 0}, {81, at + 0.5, 1}));
        lattice = test::merged(lattice, test::make_box({at + 0.3, -1, 0.2}, {at + 0.8, 81, 1.3}));
    }
    const SolidCheck check = check_solid(lattice, progress);
    ASSERT_GT(check.crossings.size(), max_crossing_pairs(lattice.triangles.size()));
    EXPECT_FALSE(resolve_crossings(lattice, check.crossings, progress).has_value());
}

TEST(ResolveCrossings, CancelledThrows) {
    Progress quiet;
    const Mesh balls =
        test::merged(test::make_sphere({0, 0, 0}, 10, 3), test::make_sphere({7.3, 1.1, 0.7}, 9, 3));
    const SolidCheck check = check_solid(balls, quiet);
    ASSERT_FALSE(check.crossings.empty());
    ASSERT_TRUE(resolve_crossings(balls, check.crossings, quiet).has_value());
    std::atomic<bool> cancel{true};
    Progress progress(nullptr, nullptr, &cancel);
    try {
        resolve_crossings(balls, check.crossings, progress);
        ADD_FAILURE() << "not cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
}  // namespace fabvdb::volume
