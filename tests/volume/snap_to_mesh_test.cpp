// snap_to_mesh against an icosphere input (radius 5, no sharp edges) and a
// surface that is the same sphere grown by 2 %: each grown vertex's closest
// input point is the input vertex it came from, so snapping gives the input
// back, to a float step (every vertex goes where a float file stores it).
// Checked too: in a frame kilometres off, every vertex lands on the float
// grid of its world position; a max_distance under the gap moves nothing, a
// piece far from the input stays, a radial fin the snapped sphere would cut
// keeps its neighbourhood where it was (no crossing is left, none reported),
// and cancellation.
#include "volume/snap_to_mesh.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "core/error.h"
#include "core/float_coordinates.h"
#include "support/ray_cast.h"
#include "support/shapes.h"
#include "volume/crossing_pairs.h"
#include "volume/signed_distance.h"

namespace fabvdb::volume {
namespace {

constexpr double radius = 5.0;
constexpr double voxel = 0.25;
constexpr double grown = 1.02;

OrientedInput sphere_input() {
    SignedDistanceOptions options;
    options.voxel_size = voxel;
    OrientedInput input;
    Progress progress;
    signed_distance_from_mesh(test::make_sphere({0, 0, 0}, radius, 3), options, progress, nullptr, &input);
    return input;
}

// The mesh scaled about the origin, its coordinates rounded to floats (as
// an extraction gives them), so vertices that do not move stay bit for bit.
Mesh scaled(Mesh mesh, double factor) {
    for (Vec3& p : mesh.vertices) p = nearest_float(Vec3{p[0] * factor, p[1] * factor, p[2] * factor});
    return mesh;
}

const CentredFrame origin;

TEST(SnapToMesh, GrownSphereSnapsBackOntoTheInputVertices) {
    const OrientedInput input = sphere_input();
    ASSERT_TRUE(input.closest_triangle);
    Mesh surface = scaled(input.mesh, grown);
    Progress progress;
    const SnapResult result = snap_to_mesh(surface, input.mesh, *input.closest_triangle, voxel, &origin, progress);
    EXPECT_EQ(result.moved_vertices, surface.vertices.size());
    EXPECT_FALSE(result.self_intersecting);
    ASSERT_EQ(surface.vertices.size(), input.mesh.vertices.size());
    for (size_t v = 0; v < surface.vertices.size(); ++v)
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(surface.vertices[v][k], input.mesh.vertices[v][k], 3e-7) << "vertex " << v;
    EXPECT_EQ(surface.triangles, input.mesh.triangles);
}

TEST(SnapToMesh, WithoutAFloatFrameVerticesKeepDoubles) {
    const OrientedInput input = sphere_input();
    Mesh surface = scaled(input.mesh, grown);
    Progress progress;
    snap_to_mesh(surface, input.mesh, *input.closest_triangle, voxel, nullptr, progress);
    for (size_t v = 0; v < surface.vertices.size(); ++v)
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(surface.vertices[v][k], input.mesh.vertices[v][k], 1e-9) << "vertex " << v;
}

TEST(SnapToMesh, InAFarFrameVerticesLandOnTheWorldFloatGrid) {
    const OrientedInput input = sphere_input();
    Mesh surface = scaled(input.mesh, grown);
    CentredFrame far;
    far.offset = {4000.0, -3000.0, 0.0};  // a float step of 2^-12 mm there
    Progress progress;
    const SnapResult result = snap_to_mesh(surface, input.mesh, *input.closest_triangle, voxel, &far, progress);
    EXPECT_EQ(result.moved_vertices, surface.vertices.size());
    EXPECT_FALSE(result.self_intersecting);
    EXPECT_TRUE(crossing_pairs(surface).empty());
    for (size_t v = 0; v < surface.vertices.size(); ++v)
        for (int k = 0; k < 3; ++k) {
            const double world = surface.vertices[v][k] + far.offset[k];
            EXPECT_EQ(nearest_float(world), world) << "vertex " << v;
            EXPECT_NEAR(surface.vertices[v][k], input.mesh.vertices[v][k], std::ldexp(1.0, -12)) << "vertex " << v;
        }
}

TEST(SnapToMesh, NothingWithinMaxDistanceMovesNothing) {
    const OrientedInput input = sphere_input();
    const Mesh before = scaled(input.mesh, grown);  // 0.1 mm out
    Mesh surface = before;
    Progress progress;
    const SnapResult result = snap_to_mesh(surface, input.mesh, *input.closest_triangle, 0.05, &origin, progress);
    EXPECT_EQ(result.moved_vertices, 0u);
    EXPECT_FALSE(result.self_intersecting);
    EXPECT_EQ(surface.vertices, before.vertices);
}

TEST(SnapToMesh, PieceFarFromTheInputStays) {
    const OrientedInput input = sphere_input();
    const Mesh far = test::make_box({20, 20, 20}, {21, 21, 21});
    Mesh surface = test::merged(scaled(input.mesh, grown), far);
    Progress progress;
    const SnapResult result = snap_to_mesh(surface, input.mesh, *input.closest_triangle, voxel, &origin, progress);
    EXPECT_EQ(result.moved_vertices, input.mesh.vertices.size());
    const size_t first = input.mesh.vertices.size();
    for (size_t v = 0; v < far.vertices.size(); ++v) EXPECT_EQ(surface.vertices[first + v], far.vertices[v]);
}

TEST(SnapToMesh, MovesThatWouldCutAFinAreUndone) {
    // A fin standing along the radius through r = 4.9 .. 5.06: the grown
    // sphere (r ≥ 5.08 on its faces) clears it, the snapped one (r ≤ 5)
    // would cut it. The fin faces sideways, so it does not move itself.
    const OrientedInput input = sphere_input();
    const double length = std::sqrt(1.0 + 0.09 + 0.04);
    const Vec3 u = {1.0 / length, 0.3 / length, 0.2 / length};
    const double t_length = std::sqrt(0.09 + 1.0);
    const Vec3 t = {-0.3 / t_length, 1.0 / t_length, 0.0};  // perpendicular to u
    const auto along = [&](double r, double s) {
        return Vec3{r * u[0] + s * t[0], r * u[1] + s * t[1], r * u[2] + s * t[2]};
    };
    Mesh fin;
    fin.vertices = {nearest_float(along(4.9, 0.0)), nearest_float(along(5.06, 0.0)), nearest_float(along(5.0, 0.3))};
    fin.triangles = {{0, 1, 2}};
    const Mesh before = test::merged(scaled(input.mesh, grown), fin);
    ASSERT_TRUE(crossing_pairs(before).empty());
    // Snapped without the safeguard, the sphere would cut the fin.
    ASSERT_FALSE(crossing_pairs(test::merged(input.mesh, fin)).empty());

    Mesh surface = before;
    Progress progress;
    const SnapResult result = snap_to_mesh(surface, input.mesh, *input.closest_triangle, voxel, &origin, progress);
    EXPECT_FALSE(result.self_intersecting);
    EXPECT_TRUE(crossing_pairs(surface).empty());
    EXPECT_TRUE(test::self_intersects(surface) == false);
    const size_t sphere_vertices = input.mesh.vertices.size();
    EXPECT_LT(result.moved_vertices, sphere_vertices);
    EXPECT_GT(result.moved_vertices, sphere_vertices - 20);
    // The fin stays; a vertex stays either where it was or on its input vertex.
    for (size_t v = 0; v < 3; ++v) EXPECT_EQ(surface.vertices[sphere_vertices + v], fin.vertices[v]);
    size_t kept = 0;
    for (size_t v = 0; v < sphere_vertices; ++v) {
        const bool stayed = surface.vertices[v] == before.vertices[v];
        kept += stayed;
        if (!stayed)
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(surface.vertices[v][k], input.mesh.vertices[v][k], 3e-7);
    }
    EXPECT_EQ(kept, sphere_vertices - result.moved_vertices);
    // The one opposite the fin went onto the input.
    size_t opposite = 0;
    double lowest = 1e300;
    for (size_t v = 0; v < sphere_vertices; ++v) {
        const Vec3& p = input.mesh.vertices[v];
        const double d = p[0] * u[0] + p[1] * u[1] + p[2] * u[2];
        if (d < lowest) lowest = d, opposite = v;
    }
    EXPECT_NE(surface.vertices[opposite], before.vertices[opposite]);
}

TEST(SnapToMesh, CancelledThrows) {
    const OrientedInput input = sphere_input();
    Mesh surface = scaled(input.mesh, grown);
    std::atomic<bool> cancel{true};
    Progress progress(nullptr, nullptr, &cancel);
    try {
        snap_to_mesh(surface, input.mesh, *input.closest_triangle, voxel, &origin, progress);
        ADD_FAILURE() << "not cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

}  // namespace
}  // namespace fabvdb::volume
