// The surface of a swept level set as an exact double height field: a ring
// standing on its side swept along tilted directions, and the same ring with
// a keep-out block carved from the middle of its columns (two inside runs per
// column); a column barely inside is noise and makes no shell; given the
// input's triangles, a sphere and a tilted cube come back on their input
// surface, the same when stored inside out. Checked by edge pairing, CGAL's
// self-intersection test and distances, and the test support's own ray
// casting, not by anything the mesher computed.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "support/cgal_mesh.h"
#include "support/plain_level_set.h"
#include "support/ray_cast.h"
#include "support/shapes.h"
#include "volume/double_height_field_mesh.h"
#include "volume/mesh_shells.h"
#include "volume/surface_ray_caster.h"
#include "volume/sweep.h"

namespace {

//! The mesh of a swept part whose kept runs hold `level_set`'s zero crossings.
fabvdb::Mesh part_mesh(const openvdb::FloatGrid& swept, fabvdb::Progress& progress,
                       const openvdb::FloatGrid* level_set) {
    fabvdb::volume::InputSurface input;
    input.level_set = level_set;
    return fabvdb::volume::double_height_field_mesh(swept, progress, &input);
}

using fabvdb::Mesh;
using fabvdb::Vec3;
using fabvdb::test::plain_level_set;

void expect_exact_double_height_field(const Mesh& mesh, const Vec3& d) {
    ASSERT_GT(mesh.triangles.size(), 500u);
    EXPECT_TRUE(fabvdb::test::closed_two_manifold(mesh));
    EXPECT_FALSE(fabvdb::test::self_intersects(mesh));
    EXPECT_GT(fabvdb::test::mesh_volume(mesh), 0.0);
    const auto check = fabvdb::test::check_double_height_field(mesh, d, 120);
    EXPECT_GT(check.lines, 3000u);
    EXPECT_EQ(check.lines_over_two, 0u) << "max crossings " << check.max_crossings;
    EXPECT_EQ(check.odd_lines, 0u);
}

//! Largest distance from the input's vertices and triangle centroids to
//! `mesh`, measured by CGAL's AABB tree.
double input_to_mesh_distance(const Mesh& input, const Mesh& mesh) {
    namespace cgal = fabvdb::test::cgal;
    const std::vector<cgal::Triangle3> triangles = cgal::triangles_of(mesh);
    cgal::Tree tree(triangles.begin(), triangles.end());
    tree.accelerate_distance_queries();
    std::vector<Vec3> samples = input.vertices;
    for (const auto& t : input.triangles) {
        const Vec3 &a = input.vertices[t[0]], &b = input.vertices[t[1]], &c = input.vertices[t[2]];
        samples.push_back({(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3});
    }
    double largest = 0;
    for (const Vec3& p : samples) largest = std::max(largest, std::sqrt(tree.squared_distance(cgal::point(p))));
    return largest;
}

//! Share of `mesh`'s vertices within `tolerance` of `input`'s surface
//! (CGAL's AABB tree).
double share_on_input(const Mesh& mesh, const Mesh& input, double tolerance) {
    namespace cgal = fabvdb::test::cgal;
    const std::vector<cgal::Triangle3> triangles = cgal::triangles_of(input);
    cgal::Tree tree(triangles.begin(), triangles.end());
    tree.accelerate_distance_queries();
    size_t on = 0;
    for (const Vec3& p : mesh.vertices) on += tree.squared_distance(cgal::point(p)) <= tolerance * tolerance;
    return double(on) / double(std::max<size_t>(mesh.vertices.size(), 1));
}

class DoubleHeightFieldMesh : public ::testing::TestWithParam<Vec3> {
protected:
    static void SetUpTestSuite() { openvdb::initialize(); }
};

TEST_P(DoubleHeightFieldMesh, SweptRingIsExact) {
    const Vec3 d = GetParam();
    fabvdb::Progress progress;
    fabvdb::volume::SweepStats stats;
    const Mesh ring = fabvdb::test::make_standing_torus(10.0, 3.0, 48, 24);
    auto swept = fabvdb::volume::sweep_double_height_field(*plain_level_set(ring, 0.4), d, {}, {}, progress, &stats);
    const Mesh mesh = fabvdb::volume::double_height_field_mesh(*swept, progress);
    expect_exact_double_height_field(mesh, d);
    // Same solid as the level set (its volume measured by OpenVDB; the
    // silhouette is cut flat within a voxel, here 2.5% of a thin tube), and it
    // contains the ring's tube.
    EXPECT_NEAR(fabvdb::test::mesh_volume(mesh), stats.volume_after, 0.03 * stats.volume_after);
    fabvdb::test::LineCaster caster(mesh, {0.31, 0.17, 0.93});
    for (int i = 0; i < 32; ++i) {
        const double u = 2 * M_PI * i / 32;
        EXPECT_TRUE(caster.inside({10 * std::cos(u), 0.0, 10 * std::sin(u)})) << "tube point " << i;
    }
}

INSTANTIATE_TEST_SUITE_P(Directions, DoubleHeightFieldMesh,
                         ::testing::Values(Vec3{0, 0, 1}, Vec3{0, 0, -1}, Vec3{1, 0, 0.3}, Vec3{0.3, -0.2, 1}));

TEST(DoubleHeightFieldMeshKeepOut, ColumnsWithTwoRunsKeepTheLongest) {
    openvdb::initialize();
    fabvdb::Progress progress;
    // A slab through the middle of a lying box splits its columns in two runs
    // of different lengths; the mesh keeps the longer (lower) one.
    const Mesh box = fabvdb::test::make_box({-6, -6, -6}, {6, 6, 6});
    const Mesh slab = fabvdb::test::make_box({-3, -3, 1}, {3, 3, 3});
    openvdb::FloatGrid::ConstPtr keep_out = plain_level_set(slab, 0.4);
    auto swept =
        fabvdb::volume::sweep_double_height_field(*plain_level_set(box, 0.4), {0, 0, 1}, {keep_out}, {}, progress);
    const Mesh mesh = fabvdb::volume::double_height_field_mesh(*swept, progress);
    expect_exact_double_height_field(mesh, {0, 0, 1});
    fabvdb::test::LineCaster caster(mesh, {0.01, 0.02, 1});
    EXPECT_TRUE(caster.inside({0.1, 0.1, -2}));
    EXPECT_FALSE(caster.inside({0.1, 0.1, 2}));
    EXPECT_FALSE(caster.inside({0.1, 0.1, 4.5}));
    EXPECT_TRUE(caster.inside({5, 5, 4.5}));
}

TEST(DoubleHeightFieldMeshKeepOut, ColumnsWithTwoRunsKeepTheOneHoldingTheKeptSurface) {
    openvdb::initialize();
    fabvdb::Progress progress;
    // Same split box; a kept surface (a small box) lies in the shorter, upper
    // runs of the columns through it: those columns keep their upper run,
    // the others still the longer lower one.
    const Mesh box = fabvdb::test::make_box({-6, -6, -6}, {6, 6, 6});
    const Mesh slab = fabvdb::test::make_box({-3, -3, 1}, {3, 3, 3});
    const Mesh kept = fabvdb::test::make_box({-1.5, -1.5, 4}, {1.5, 1.5, 5});
    openvdb::FloatGrid::ConstPtr keep_out = plain_level_set(slab, 0.4);
    auto swept =
        fabvdb::volume::sweep_double_height_field(*plain_level_set(box, 0.4), {0, 0, 1}, {keep_out}, {}, progress);
    const Mesh mesh = part_mesh(*swept, progress, plain_level_set(kept, 0.4).get());
    expect_exact_double_height_field(mesh, {0, 0, 1});
    fabvdb::test::LineCaster caster(mesh, {0.01, 0.02, 1});
    EXPECT_TRUE(caster.inside({0.1, 0.1, 4.5}));
    EXPECT_FALSE(caster.inside({0.1, 0.1, -2}));
    EXPECT_TRUE(caster.inside({2.5, 2.5, -2}));
    EXPECT_FALSE(caster.inside({2.5, 2.5, 4.5}));
    EXPECT_TRUE(caster.inside({5, 5, 4.5}));
}

// The input supplies the geometry: a sphere and a tilted cube, each already
// a double height field along d, meshed from their own level sets with the
// input's triangles given: the mesh is still an exact double height field,
// most of its vertices lie on the input, every input vertex and triangle
// centroid lies near it, and the input stored inside out gives the same mesh.
class DoubleHeightFieldMeshFromInput : public ::testing::TestWithParam<Vec3> {
protected:
    static void SetUpTestSuite() { openvdb::initialize(); }
};

TEST_P(DoubleHeightFieldMeshFromInput, InputLiesOnTheMesh) {
    const Vec3 d = GetParam();
    const double voxel = 0.5;
    Mesh cube = fabvdb::test::make_box({-4, -4, -4}, {4, 4, 4});
    const double c = std::cos(0.4), s = std::sin(0.4);
    for (Vec3& p : cube.vertices) p = {c * p[0] - s * p[1] + 0.13, s * p[0] + c * p[1] - 0.07, p[2] + 0.21};
    for (const Mesh& input : {fabvdb::test::make_sphere({0.1, -0.2, 0.3}, 6.0, 4), cube}) {
        fabvdb::Progress progress;
        const openvdb::FloatGrid::Ptr level_set = plain_level_set(input, voxel);
        auto swept = fabvdb::volume::sweep_double_height_field(*level_set, d, {}, {}, progress);
        const fabvdb::volume::SurfaceRayCaster rays(input);
        fabvdb::volume::InputSurface surface;
        surface.level_set = level_set.get();
        surface.mesh = &input;
        surface.rays = &rays;
        const Mesh mesh = fabvdb::volume::double_height_field_mesh(*swept, progress, &surface);
        expect_exact_double_height_field(mesh, d);
        // The column ends are the input's own crossings and the input's
        // silhouette vertices are on the contour: most vertices lie on the
        // input (the level set alone puts none of the sphere's there); the
        // surface between them is linear, within 0.3 of a voxel of the sphere
        // (0.4 with the columns alone); the cube's edges across cells are cut
        // by up to a voxel and a quarter.
        EXPECT_GT(share_on_input(mesh, input, 1e-3 * voxel), 0.85);
        EXPECT_LT(input_to_mesh_distance(input, mesh), (input.vertices.size() == 8 ? 1.25 : 0.3) * voxel);
        // Stored inside out, the same input gives the same mesh.
        Mesh inside_out = input;
        for (auto& t : inside_out.triangles) std::swap(t[1], t[2]);
        const fabvdb::volume::SurfaceRayCaster inside_out_rays(inside_out);
        surface.mesh = &inside_out;
        surface.rays = &inside_out_rays;
        surface.orientation = -1;
        const Mesh again = fabvdb::volume::double_height_field_mesh(*swept, progress, &surface);
        ASSERT_EQ(again.vertices.size(), mesh.vertices.size());
        for (size_t v = 0; v < mesh.vertices.size(); ++v)
            for (int k = 0; k < 3; ++k) ASSERT_NEAR(again.vertices[v][k], mesh.vertices[v][k], 1e-5) << "vertex " << v;
    }
}

INSTANTIATE_TEST_SUITE_P(Directions, DoubleHeightFieldMeshFromInput,
                         ::testing::Values(Vec3{0, 0, 1}, Vec3{1, 0, 0.3}, Vec3{0.3, -0.2, 1}));

//! A closed cone: base circle of `radius` at z = 0 around (cx, cy), apex at
//! height `height`, `segments` around.
Mesh make_cone(double cx, double cy, double radius, double height, int segments) {
    Mesh cone;
    cone.vertices.push_back({cx, cy, height});
    cone.vertices.push_back({cx, cy, 0});
    for (int s = 0; s < segments; ++s) {
        const double u = 2 * M_PI * s / segments;
        cone.vertices.push_back({cx + radius * std::cos(u), cy + radius * std::sin(u), 0});
    }
    for (int s = 0; s < segments; ++s) {
        const uint32_t a = uint32_t(2 + s), b = uint32_t(2 + (s + 1) % segments);
        cone.triangles.push_back({0, a, b});
        cone.triangles.push_back({1, b, a});
    }
    return cone;
}

TEST(DoubleHeightFieldMeshFromInput, ATipAlongDBetweenColumnsIsKept) {
    // Half-angle about 22°, the apex 0.37 and 0.21 of a voxel off the columns:
    // the columns around it end a voxel short of it; the mesh reaches it.
    openvdb::initialize();
    const double voxel = 0.5;
    const Mesh cone = make_cone(0.37 * voxel, 0.21 * voxel, 4.0, 10.0, 96);
    fabvdb::Progress progress;
    const openvdb::FloatGrid::Ptr level_set = plain_level_set(cone, voxel);
    auto swept = fabvdb::volume::sweep_double_height_field(*level_set, {0, 0, 1}, {}, {}, progress);
    const fabvdb::volume::SurfaceRayCaster rays(cone);
    fabvdb::volume::InputSurface surface;
    surface.level_set = level_set.get();
    surface.mesh = &cone;
    surface.rays = &rays;
    const Mesh mesh = fabvdb::volume::double_height_field_mesh(*swept, progress, &surface);
    expect_exact_double_height_field(mesh, {0, 0, 1});
    Mesh apex;
    apex.vertices = {cone.vertices[0]};
    EXPECT_LT(input_to_mesh_distance(apex, mesh), 0.05 * voxel);
}

TEST(DoubleHeightFieldMeshErrors, EmptyGridGivesNoMeshAndCancelIsHonoured) {
    openvdb::initialize();
    fabvdb::Progress progress;
    openvdb::FloatGrid empty;
    EXPECT_TRUE(fabvdb::volume::double_height_field_mesh(empty, progress).triangles.empty());
    // Active voxels, none inside: no column is inside.
    openvdb::FloatGrid outside(1.0f);
    outside.tree().setValueOn(openvdb::Coord(0, 0, 0), 0.5f);
    outside.tree().setValueOn(openvdb::Coord(0, 0, 1), 0.7f);
    EXPECT_TRUE(fabvdb::volume::double_height_field_mesh(outside, progress).triangles.empty());
    const Mesh ring = fabvdb::test::make_standing_torus(10.0, 3.0, 48, 24);
    auto swept = fabvdb::volume::sweep_double_height_field(*plain_level_set(ring, 0.5), {0, 0, 1}, {}, {}, progress);
    std::atomic<bool> cancel{true};
    fabvdb::Progress cancelled(nullptr, nullptr, &cancel);
    try {
        fabvdb::volume::double_height_field_mesh(*swept, cancelled);
        FAIL() << "expected cancellation";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

// One column barely inside (0.01 mm deep at 0.5 mm voxels) among outside
// neighbours would give a crumb far under an eighth of a voxel³: dropped,
// alone (the part vanished) or beside a ring.
void add_speck(openvdb::FloatGrid& grid, const openvdb::Coord& at) {
    for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dz = -1; dz <= 1; ++dz) grid.tree().setValueOn(at.offsetBy(dx, dy, dz), 0.5f);
    grid.tree().setValueOn(at, -0.01f);
}

TEST(DoubleHeightFieldMeshNoise, ASpeckColumnMakesNoShell) {
    openvdb::initialize();
    fabvdb::Progress progress;
    openvdb::FloatGrid speck(1.0f);
    speck.setTransform(openvdb::math::Transform::createLinearTransform(0.5));
    add_speck(speck, openvdb::Coord(0, 0, 0));
    EXPECT_TRUE(fabvdb::volume::double_height_field_mesh(speck, progress).triangles.empty());

    const Mesh ring = fabvdb::test::make_standing_torus(10.0, 3.0, 48, 24);
    auto swept = fabvdb::volume::sweep_double_height_field(*plain_level_set(ring, 0.5), {0, 0, 1}, {}, {}, progress);
    const Mesh alone = fabvdb::volume::double_height_field_mesh(*swept, progress);
    add_speck(*swept, openvdb::Coord(60, 60, 0));
    const Mesh with_speck = fabvdb::volume::double_height_field_mesh(*swept, progress);
    EXPECT_EQ(fabvdb::volume::split_shells(with_speck).size(), 1u);
    EXPECT_EQ(with_speck.triangles.size(), alone.triangles.size());
    expect_exact_double_height_field(with_speck, {0, 0, 1});
}

}  // namespace

