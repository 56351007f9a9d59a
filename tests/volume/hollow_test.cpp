// Hollowing: checked on the output mesh with code that shares nothing with
// the hollowing (CGAL surface mesh, components, self-intersection, AABB
// distances from samples on every cavity triangle to the outer triangles).
#include "volume/hollow.h"

#include <gtest/gtest.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <random>
#include <tuple>

#include "core/error.h"
#include "io/mesh_io.h"
#include "support/cgal_mesh.h"
#include "support/shapes.h"

namespace fabvdb::volume {
namespace {

using test::cgal::Kernel;
using test::cgal::Point;
using test::cgal::SurfaceMesh;
using test::cgal::Tree;
using test::cgal::Triangle3;

//! The output split by component: outer shells (positive volume), cavity
//! shells (negative), each as CGAL triangles; plus whether it is one closed,
//! manifold, non-self-intersecting surface.
struct Inspected {
    bool manifold = true, closed = false, self_intersecting = true;
    bool cavity_self_intersecting = true, cavity_touches_outer = true;
    std::vector<Triangle3> outer, cavity;
    double outer_volume = 0, cavity_volume = 0;  // cavity_volume > 0
    int outer_shells = 0, cavity_shells = 0;
};

Inspected inspect(const Mesh& mesh) {
    Inspected result;
    SurfaceMesh surface = test::cgal::surface_mesh_of(mesh, &result.manifold);
    if (!result.manifold) return result;
    result.closed = CGAL::is_closed(surface);
    result.self_intersecting = CGAL::Polygon_mesh_processing::does_self_intersect(surface);
    auto component = surface.add_property_map<SurfaceMesh::Face_index, std::size_t>("f:component", 0).first;
    const std::size_t count = CGAL::Polygon_mesh_processing::connected_components(surface, component);
    std::vector<double> volume(count, 0.0);
    for (auto f : surface.faces()) {
        auto h = surface.halfedge(f);
        const Point a = surface.point(surface.source(h)), b = surface.point(surface.target(h)),
                    c = surface.point(surface.target(surface.next(h)));
        volume[component[f]] += CGAL::scalar_product(a - CGAL::ORIGIN, CGAL::cross_product(b - CGAL::ORIGIN, c - CGAL::ORIGIN)) / 6.0;
    }
    for (auto f : surface.faces()) {
        auto h = surface.halfedge(f);
        const Triangle3 triangle(surface.point(surface.source(h)), surface.point(surface.target(h)),
                                 surface.point(surface.target(surface.next(h))));
        (volume[component[f]] > 0 ? result.outer : result.cavity).push_back(triangle);
    }
    for (double v : volume) {
        (v > 0 ? result.outer_volume : result.cavity_volume) += std::abs(v);
        ++(v > 0 ? result.outer_shells : result.cavity_shells);
    }

    SurfaceMesh cavity_surface;
    std::map<SurfaceMesh::Vertex_index, SurfaceMesh::Vertex_index> copied;
    const auto copy = [&](SurfaceMesh::Vertex_index v) {
        auto [it, added] = copied.emplace(v, SurfaceMesh::Vertex_index());
        if (added) it->second = cavity_surface.add_vertex(surface.point(v));
        return it->second;
    };
    for (auto f : surface.faces()) {
        if (volume[component[f]] > 0) continue;
        auto h = surface.halfedge(f);
        cavity_surface.add_face(copy(surface.source(h)), copy(surface.target(h)), copy(surface.target(surface.next(h))));
    }
    result.cavity_self_intersecting = CGAL::Polygon_mesh_processing::does_self_intersect(cavity_surface);
    Tree outer_tree(result.outer.begin(), result.outer.end());
    result.cavity_touches_outer = false;
    for (const Triangle3& t : result.cavity) result.cavity_touches_outer |= outer_tree.do_intersect(t);
    return result;
}

//! Distances from samples of every cavity triangle (corners, edge midpoints,
//! centroid) to the outer triangles, sorted.
std::vector<double> wall_samples(const Inspected& shells) {
    Tree tree(shells.outer.begin(), shells.outer.end());
    tree.accelerate_distance_queries();
    std::vector<double> distances;
    for (const Triangle3& t : shells.cavity) {
        const Point samples[] = {t[0], t[1], t[2], CGAL::midpoint(t[0], t[1]), CGAL::midpoint(t[1], t[2]),
                                 CGAL::midpoint(t[2], t[0]), CGAL::centroid(t[0], t[1], t[2])};
        for (const Point& p : samples) distances.push_back(std::sqrt(tree.squared_distance(p)));
    }
    std::sort(distances.begin(), distances.end());
    return distances;
}

//! Closed shells; the cavity crosses neither itself nor the outer surface;
//! nothing crosses at all (a clean input's own surface or a repaired one).
void expect_valid_shells(const Inspected& shells, const std::string& what) {
    EXPECT_TRUE(shells.manifold) << what;
    EXPECT_TRUE(shells.closed) << what;
    EXPECT_FALSE(shells.cavity_self_intersecting) << what;
    EXPECT_FALSE(shells.cavity_touches_outer) << what;
    EXPECT_FALSE(shells.self_intersecting) << what;
}

HollowOptions options_with(double wall, double voxel, double closing = 0.0) {
    HollowOptions options;
    options.wall = wall;
    options.voxel_size = voxel;
    options.closing = closing;
    return options;
}

TEST(Hollow, SphereShellVolumeAndWall) {
    const double radius = 20.0, wall = 3.0;
    const Mesh sphere = test::make_sphere({0, 0, 0}, radius, 5);
    Progress progress;
    const HollowOptions options = options_with(wall, 0.0);
    const HollowResult result = hollow(sphere, options, progress);
    EXPECT_EQ(result.outer_surface, "input");
    const Inspected shells = inspect(result.mesh);
    expect_valid_shells(shells, "sphere");
    const double expected = 4.0 / 3.0 * M_PI * (std::pow(radius, 3) - std::pow(radius - wall, 3));
    EXPECT_NEAR(shells.outer_volume - shells.cavity_volume, expected, 0.01 * expected);
    ASSERT_EQ(result.cavity_volumes.size(), 1u);
    const std::vector<double> walls = wall_samples(shells);
    ASSERT_FALSE(walls.empty());
    EXPECT_GE(walls.front(), wall - result.voxel_size);
    EXPECT_NEAR(walls[walls.size() / 2], wall, result.voxel_size);
    // The snap makes the wall exact far below the voxel size.
    EXPECT_NEAR(walls[walls.size() / 2], wall, 0.05);
}

TEST(Hollow, BoxWallAtClosingZeroAndClosingRoundsTheCavity) {
    const Mesh box = test::make_box({0, 0, 0}, {40, 30, 25});
    Progress progress;
    const HollowResult sharp = hollow(box, options_with(3.0, 1.0), progress);
    const Inspected sharp_shells = inspect(sharp.mesh);
    expect_valid_shells(sharp_shells, "box");
    const std::vector<double> walls = wall_samples(sharp_shells);
    EXPECT_GE(walls.front(), 3.0 - 1.0);
    EXPECT_NEAR(walls[walls.size() / 2], 3.0, 1.0);
    EXPECT_NEAR(sharp_shells.cavity_volume, 34.0 * 24.0 * 19.0, 0.02 * 34.0 * 24.0 * 19.0);

    const HollowResult rounded = hollow(box, options_with(3.0, 1.0, 4.0), progress);
    const Inspected rounded_shells = inspect(rounded.mesh);
    expect_valid_shells(rounded_shells, "box with closing");
    EXPECT_GE(wall_samples(rounded_shells).front(), 3.0 - 1.0);
    EXPECT_LT(rounded_shells.cavity_volume, sharp_shells.cavity_volume);
}

TEST(Hollow, ThinFinStaysSolidThickBodyIsHollow) {
    // A 30 mm cube with a 2 mm fin (thinner than 2 × 3 mm wall) sticking out of it.
    const Mesh part = test::merged(test::make_box({0, 0, 0}, {30, 30, 30}), test::make_box({29, 10, 5}, {60, 12, 25}));
    Progress progress;
    const HollowResult result = hollow(part, options_with(3.0, 0.5), progress);
    EXPECT_EQ(result.outer_surface, "resolved");  // two overlapping boxes: their union
    const Inspected shells = inspect(result.mesh);
    expect_valid_shells(shells, "fin");
    ASSERT_EQ(result.cavity_volumes.size(), 1u);
    EXPECT_GT(shells.cavity_volume, 0.8 * 24.0 * 24.0 * 24.0);
    for (const Triangle3& t : shells.cavity)
        for (int k = 0; k < 3; ++k) EXPECT_LT(t[k].x(), 30.0 - 2.0) << "cavity in the fin";
}

// A slab thicker than twice the wall but nowhere thicker than twice the wall
// plus the closing has no core to open a cavity from: it stays solid,
// without error, its surface untouched. A little thicker, it has its cavity:
// the core (30 x 30 x 2 mm, at 5 mm from the outside) grown by the closing,
// of volume V + A r + M r^2 + 4/3 pi r^3 by Steiner's formula (r = 2 mm);
// within 10%: the extracted cavity lies a fifth of a voxel inside it (4.8%
// less volume at 0.5 mm voxels, 2.5% at 0.25 mm).
TEST(Hollow, SlabTooThinForTheClosingStaysSolid) {
    Progress progress;
    const Mesh thin = test::make_box({0, 0, 0}, {40, 40, 8});
    const HollowResult solid = hollow(thin, options_with(3.0, 0.5, 2.0), progress);
    EXPECT_EQ(solid.outer_surface, "input");
    EXPECT_TRUE(solid.cavity_volumes.empty());
    EXPECT_TRUE(solid.filled_cavity_volumes.empty());
    EXPECT_EQ(solid.mesh.triangles.size(), thin.triangles.size());
    EXPECT_NEAR(solid.volume_shell, 40.0 * 40.0 * 8.0, 1e-6);
    ASSERT_EQ(solid.warnings.size(), 1u);
    EXPECT_NE(solid.warnings[0].find("no cavity"), std::string::npos) << solid.warnings[0];
    const Inspected solid_shells = inspect(solid.mesh);
    expect_valid_shells(solid_shells, "thin slab");
    EXPECT_EQ(solid_shells.cavity_shells, 0);
    EXPECT_NEAR(solid_shells.outer_volume, 40.0 * 40.0 * 8.0, 1e-6);

    const HollowResult hollowed = hollow(test::make_box({0, 0, 0}, {40, 40, 12}), options_with(3.0, 0.5, 2.0), progress);
    ASSERT_EQ(hollowed.cavity_volumes.size(), 1u);
    EXPECT_TRUE(hollowed.warnings.empty());
    const Inspected shells = inspect(hollowed.mesh);
    expect_valid_shells(shells, "thick slab");
    EXPECT_EQ(shells.cavity_shells, 1);
    EXPECT_GE(wall_samples(shells).front(), 3.0 - 0.5);
    const double r = 2.0, core_volume = 30.0 * 30.0 * 2.0, core_area = 2.0 * (30.0 * 30.0 + 2.0 * 30.0 * 2.0),
                 core_mean_width = M_PI * (30.0 + 30.0 + 2.0);
    const double expected = core_volume + core_area * r + core_mean_width * r * r + 4.0 / 3.0 * M_PI * r * r * r;
    EXPECT_NEAR(shells.cavity_volume, expected, 0.1 * expected);
}

//! Whether `outer` is the exact boundary of the union of the closed shells
//! `a` and `b` (within `tolerance` mm), measured on the shells alone: every
//! corner of `outer` lies on a shell and inside neither; every sample of a
//! shell outside the other lies on `outer`, every sample inside it is away
//! from `outer` by at least its depth in the other shell.
void expect_union_surface(const Mesh& a, const Mesh& b, const std::vector<Triangle3>& outer, double tolerance) {
    using Side = CGAL::Side_of_triangle_mesh<SurfaceMesh, Kernel>;
    struct Shell {
        std::vector<Triangle3> triangles;
        SurfaceMesh surface;
        std::unique_ptr<Tree> tree;
        std::unique_ptr<Side> side;
    };
    Shell shells[2];
    for (int s = 0; s < 2; ++s) {
        const Mesh& mesh = s == 0 ? a : b;
        shells[s].surface = test::cgal::surface_mesh_of(mesh);
        shells[s].triangles = test::cgal::triangles_of(mesh);
        shells[s].tree = std::make_unique<Tree>(shells[s].triangles.begin(), shells[s].triangles.end());
        shells[s].tree->accelerate_distance_queries();
        shells[s].side = std::make_unique<Side>(shells[s].surface);
    }
    // How deep p lies inside shell s (0 outside or on it).
    const auto depth_in = [&](int s, const Point& p) {
        return (*shells[s].side)(p) == CGAL::ON_BOUNDED_SIDE ? std::sqrt(shells[s].tree->squared_distance(p)) : 0.0;
    };
    Tree outer_tree(outer.begin(), outer.end());
    outer_tree.accelerate_distance_queries();
    int on_union = 0, inside = 0;
    for (const Triangle3& t : outer)
        for (int k = 0; k < 3; ++k) {
            const double on_a = std::sqrt(shells[0].tree->squared_distance(t[k]));
            const double on_b = std::sqrt(shells[1].tree->squared_distance(t[k]));
            EXPECT_LE(std::min(on_a, on_b), tolerance) << "output corner off both shells";
            EXPECT_LE(std::max(depth_in(0, t[k]), depth_in(1, t[k])), tolerance) << "output corner inside a shell";
        }
    for (int s = 0; s < 2; ++s)
        for (const Triangle3& t : shells[s].triangles)
            for (const auto& [wa, wb] : {std::pair{1.0 / 3, 1.0 / 3}, {0.6, 0.2}, {0.2, 0.6}, {0.2, 0.2}}) {
                const Point p = CGAL::barycenter(t[0], wa, t[1], wb, t[2], 1.0 - wa - wb);
                const double depth = depth_in(1 - s, p);
                const double off_outer = std::sqrt(outer_tree.squared_distance(p));
                if (depth > tolerance) {
                    ++inside;
                    EXPECT_GE(off_outer, depth - tolerance) << "output surface inside the other shell";
                } else if (std::sqrt(shells[1 - s].tree->squared_distance(p)) > tolerance) {
                    ++on_union;
                    EXPECT_LE(off_outer, tolerance) << "union surface missing from the output";
                }
            }
    EXPECT_GT(on_union, 0);
    EXPECT_GT(inside, 0);
}

// Overlapping closed shells (closed, oriented, manifold, only crossing each
// other) keep the exact surface of their union, cut out of their own
// triangles, instead of a voxelized copy; the clean-input path runs on it.
TEST(Hollow, CrossingShellsKeepTheExactSurfaceOfTheirUnion) {
    const Mesh ball = test::make_sphere({0, 0, 0}, 15, 3), other = test::make_sphere({13.3, 2.7, 1.9}, 11, 3);
    const Mesh slab = test::make_box({-20.3, -6.1, -5.3}, {9.7, 5.9, 4.4});
    for (const auto& [first, second, what] :
         {std::tuple{&ball, &other, "two balls"}, std::tuple{&ball, &slab, "ball and slab"}}) {
        Progress progress;
        const HollowResult result = hollow(test::merged(*first, *second), options_with(2.0, 0.5), progress);
        EXPECT_EQ(result.outer_surface, "resolved") << what;
        const Inspected shells = inspect(result.mesh);
        expect_valid_shells(shells, what);
        EXPECT_EQ(shells.outer_shells, 1) << what;
        ASSERT_FALSE(shells.cavity.empty()) << what;
        EXPECT_GE(wall_samples(shells).front(), 2.0 - 0.5) << what;
        SCOPED_TRACE(what);
        expect_union_surface(*first, *second, shells.outer, 1e-6);
    }
}

// A part made of many overlapping shells, every third stored inside out,
// and the same part wholly inside out: the outer surface encloses the union
// of the boxes (lattice cells, counted exactly), within a voxel's worth of
// its area, and lies on it, whichever path made it (fidelity gate).
TEST(Hollow, ManyOverlappingShellsSomeInsideOutKeepTheirUnion) {
    Mesh part;
    std::vector<std::array<int, 6>> boxes;  // x0 y0 z0 x1 y1 z1, mm
    for (int i = 0; i < 40; ++i) boxes.push_back({i, (i * 7) % 5, 0, i + 4, (i * 7) % 5 + 6, 6 + (i % 3) * 2});
    for (size_t i = 0; i < boxes.size(); ++i) {
        const auto& b = boxes[i];
        const Mesh box = test::make_box({double(b[0]), double(b[1]), double(b[2])},
                                        {double(b[3]), double(b[4]), double(b[5])});
        part = test::merged(part, i % 3 == 2 ? test::flipped(box) : box);
    }
    double union_volume = 0;
    for (int x = 0; x < 44; ++x)
        for (int y = 0; y < 11; ++y)
            for (int z = 0; z < 10; ++z)
                union_volume += std::any_of(boxes.begin(), boxes.end(), [&](const std::array<int, 6>& b) {
                    return x >= b[0] && x < b[3] && y >= b[1] && y < b[4] && z >= b[2] && z < b[5];
                });
    const Mesh inside_out = test::flipped(part);
    for (const Mesh* input : std::vector<const Mesh*>{&part, &inside_out}) {
        Progress progress;
        const HollowResult result = hollow(*input, options_with(1.0, 0.25), progress);
        const Inspected shells = inspect(result.mesh);
        expect_valid_shells(shells, result.outer_surface.c_str());
        EXPECT_EQ(shells.outer_shells, 1);
        double area = 0;
        for (const Triangle3& t : shells.outer) area += std::sqrt(t.squared_area());
        EXPECT_NEAR(shells.outer_volume, union_volume, 0.25 * area) << result.outer_surface;
        EXPECT_TRUE(result.outer_surface == "input" || result.fidelity.passed) << result.fidelity.defect;
    }
}

TEST(Hollow, SmallCavitiesAreFilled) {
    const Mesh two = test::merged(test::make_sphere({0, 0, 0}, 15, 4), test::make_sphere({40, 0, 0}, 5, 4));
    Progress progress;
    HollowOptions options = options_with(2.0, 0.5);
    const HollowResult all = hollow(two, options, progress);
    EXPECT_EQ(inspect(all.mesh).cavity.empty(), false);
    EXPECT_EQ(all.cavity_volumes.size(), 2u);
    options.min_cavity_volume = 4.0 / 3.0 * M_PI * 27.0 + 50.0;  // more than the small cavity (r ~ 3)
    const HollowResult filled = hollow(two, options, progress);
    EXPECT_EQ(filled.cavity_volumes.size(), 1u);
    EXPECT_EQ(filled.filled_cavity_volumes.size(), 1u);
    const Inspected shells = inspect(filled.mesh);
    expect_valid_shells(shells, "filled");
    for (const Triangle3& t : shells.cavity) EXPECT_LT(t[0].x(), 20.0);
}

//! A mesh file scaled so that the longest side of its triangles' bounding box
//! is `size` mm (its low corner at the origin).
Mesh read_fitted(const std::string& path, double size, Progress& progress) {
    Mesh mesh = io::read_mesh(path, progress);
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (const Triangle& t : mesh.triangles)
        for (uint32_t v : t)
            for (int k = 0; k < 3; ++k) {
                lo[k] = std::min(lo[k], mesh.vertices[v][k]);
                hi[k] = std::max(hi[k], mesh.vertices[v][k]);
            }
    const double scale = size / std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    for (Vec3& p : mesh.vertices)
        for (int k = 0; k < 3; ++k) p[k] = (p[k] - lo[k]) * scale;
    return mesh;
}

// Parts a little over twice the wall thick (thin void slivers, whose two sides
// cannot both take the exact wall) at the default voxel: the wall is never
// thinner than 3 mm - 0.22 mm (PrusaSlicer's voxel) and its median is exact.
TEST(Hollow, ThinPartsKeepTheFullWallAtClosingZero) {
    for (const char* name : {"rocker-arm.obj", "fertility.off"}) {
        Progress progress;
        HollowOptions options = options_with(3.0, 0.0);
        options.input_name = name;
        const HollowResult result =
            hollow(read_fitted(FABVDB_SHARED_DATA "/meshes/" + std::string(name), 60.0, progress), options, progress);
        const Inspected shells = inspect(result.mesh);
        expect_valid_shells(shells, name);
        ASSERT_FALSE(shells.cavity.empty()) << name;
        const std::vector<double> walls = wall_samples(shells);
        EXPECT_GE(walls.front(), 3.0 - 0.22) << name;
        EXPECT_NEAR(walls[walls.size() / 2], 3.0, 0.1) << name;
    }
}

// A dirty input goes through the repair, which leaves voxel-sized specks
// (solid and void shells of a few triangles) where the input's surfaces
// cross; kept, one floated in the wall 0.98 mm from the cavity. Every shell of
// the output is a real solid or void. The input: dragon_20k (18 crossing
// triangle pairs), with one corner of one triangle unwelded (a copy of its
// vertex), so that it is not a manifold by its indices and is repaired
// rather than resolved.
TEST(Hollow, DirtyInputLeavesNoSpecksInTheWall) {
    Progress progress;
    HollowOptions options = options_with(3.0, 0.0, 2.0);
    options.input_name = "dragon_20k.obj";
    Mesh dragon = read_fitted(FABVDB_SHARED_DATA "/meshes/dragon_20k.obj", 100.0, progress);
    dragon.vertices.push_back(dragon.vertices[dragon.triangles[0][0]]);
    dragon.triangles[0][0] = uint32_t(dragon.vertices.size() - 1);
    const HollowResult result = hollow(dragon, options, progress);
    EXPECT_EQ(result.outer_surface, "repaired");
    const Inspected shells = inspect(result.mesh);
    expect_valid_shells(shells, "dragon_20k");
    EXPECT_EQ(shells.outer_shells, 1);
    EXPECT_EQ(shells.cavity_shells, int(result.cavity_volumes.size()));
    ASSERT_FALSE(shells.cavity.empty());
    EXPECT_GE(wall_samples(shells).front(), 3.0 - 0.22);
}

TEST(Hollow, SharedMeshesHollowIntoClosedDisjointShells) {
    const std::string folder = FABVDB_SHARED_DATA "/meshes/";
    // The refusals: triangles that enclose no volume. Parts nowhere thicker
    // than twice the wall at this scale (multibody.stl) come back solid.
    const std::map<std::string, fabvdb_status> refused = {
        {"degenerated.obj", FABVDB_ERR_BAD_INPUT},
        {"quads_to_stitch.off", FABVDB_ERR_BAD_INPUT},
        {"non_manifold_face_graph.off", FABVDB_ERR_BAD_INPUT}};
    int hollowed = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() == ".md") continue;
        Progress progress;
        // Scaled to 40 mm so one coarse setting fits all.
        const Mesh mesh = read_fitted(entry.path().string(), 40.0, progress);
        HollowOptions options = options_with(1.5, 0.75);
        options.input_name = name;
        const auto expected = refused.find(name);
        try {
            const HollowResult result = hollow(mesh, options, progress);
            EXPECT_TRUE(expected == refused.end()) << name << " hollowed";
            const Inspected shells = inspect(result.mesh);
            expect_valid_shells(shells, name);
            if (!shells.cavity.empty()) EXPECT_GE(wall_samples(shells).front(), 1.5 - 0.75) << name;
            ++hollowed;
        } catch (const Error& e) {
            ASSERT_TRUE(expected != refused.end()) << name << ": " << e.what();
            EXPECT_EQ(e.status(), expected->second) << name << ": " << e.what();
        }
    }
    EXPECT_EQ(hollowed, 25);
}

//! The struts of the srs net (the gyroid's labyrinth skeleton) in a cell of
//! side 1, from its crystallographic description: Wyckoff positions 8a of
//! I4_132 (x, x, x with x = 1/8, its three screw images, and those moved by
//! the body centring), each joined to its 3 nearest nodes.
std::vector<std::pair<Point, Point>> srs_struts() {
    std::vector<Point> nodes;
    for (const Point& p : {Point(1, 1, 1), Point(3, 7, 5), Point(7, 5, 3), Point(5, 3, 7)}) {
        nodes.emplace_back(p.x() / 8, p.y() / 8, p.z() / 8);
        nodes.emplace_back(std::fmod(p.x() / 8 + 0.5, 1.0), std::fmod(p.y() / 8 + 0.5, 1.0),
                           std::fmod(p.z() / 8 + 0.5, 1.0));
    }
    std::vector<std::pair<Point, Point>> struts;
    for (const Point& a : nodes)
        for (const Point& b : nodes)
            for (int i = -1; i <= 1; ++i)
                for (int j = -1; j <= 1; ++j)
                    for (int k = -1; k <= 1; ++k) {
                        const Point c(b.x() + i, b.y() + j, b.z() + k);
                        if (std::abs(std::sqrt(CGAL::squared_distance(a, c)) - std::sqrt(2.0) / 4) < 1e-9)
                            struts.emplace_back(a, c);  // each strut twice: harmless for distances
                    }
    return struts;
}

TEST(Hollow, GyroidInfillJoinsTheWallAndKeepsOneOpenCavity) {
    const double radius = 14.0, wall = 2.0, cell = 8.0, strut = 1.6, voxel = 0.4;
    const Mesh sphere = test::make_sphere({0, 0, 0}, radius, 5);
    Progress progress;
    const Inspected plain = inspect(hollow(sphere, options_with(wall, voxel), progress).mesh);
    HollowOptions options = options_with(wall, voxel);
    options.infill = {cell, strut};
    const HollowResult result = hollow(sphere, options, progress);
    const Inspected filled = inspect(result.mesh);
    expect_valid_shells(filled, "gyroid infill");
    // One solid (every strut joined to the wall) around one void (the void is
    // one connected surface: powder and resin drain from all of it).
    EXPECT_EQ(filled.outer_shells, 1);
    EXPECT_EQ(filled.cavity_shells, 1);
    EXPECT_EQ(result.cavity_volumes.size(), 1u);
    EXPECT_GE(wall_samples(filled).front(), wall - voxel);

    // The infill volume against a Monte Carlo estimate of struts of that
    // diameter inside the plain cavity (taken as the ball of its volume).
    const double cavity_radius = std::cbrt(3.0 * plain.cavity_volume / (4.0 * M_PI));
    const auto struts = srs_struts();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(-cavity_radius, cavity_radius);
    int inside = 0, in_strut = 0;
    while (inside < 40000) {
        const Point p(uniform(random), uniform(random), uniform(random));
        if (CGAL::squared_distance(p, Point(0, 0, 0)) > cavity_radius * cavity_radius) continue;
        ++inside;
        const Point unit(p.x() / cell - std::floor(p.x() / cell), p.y() / cell - std::floor(p.y() / cell),
                         p.z() / cell - std::floor(p.z() / cell));
        double nearest = 1e9;
        for (const auto& [a, b] : struts)
            for (int i = -1; i <= 1; ++i)
                for (int j = -1; j <= 1; ++j)
                    for (int k = -1; k <= 1; ++k) {
                        const Kernel::Vector_3 shift(i, j, k);
                        nearest = std::min(nearest, CGAL::squared_distance(unit + shift, Kernel::Segment_3(a, b)));
                    }
        in_strut += std::sqrt(nearest) * cell < strut / 2;
    }
    const double expected = plain.cavity_volume * in_strut / inside;
    const double infill = plain.cavity_volume - filled.cavity_volume;
    EXPECT_GT(expected, 0.05 * plain.cavity_volume);
    EXPECT_NEAR(infill, expected, 0.08 * expected);
}

// A wall thicker than half the part leaves no room for a cavity anywhere:
// the part comes back as it was, solid, with a warning (a farm's batch needs
// the part, not an error).
TEST(Hollow, PartTooThinForAnyCavityComesBackSolid) {
    const Mesh sphere = test::make_sphere({0, 0, 0}, 10, 3);
    Progress progress;
    HollowOptions options = options_with(12.0, 1.0);
    options.input_name = "sphere";
    const HollowResult result = hollow(sphere, options, progress);
    EXPECT_EQ(result.outer_surface, "input");
    EXPECT_TRUE(result.cavity_volumes.empty());
    EXPECT_EQ(result.mesh.vertices, sphere.vertices);
    EXPECT_EQ(result.mesh.triangles, sphere.triangles);
    EXPECT_NEAR(result.volume_shell, test::mesh_volume(sphere), 1e-9 * test::mesh_volume(sphere));
    ASSERT_EQ(result.warnings.size(), 1u);
    EXPECT_NE(result.warnings[0].find("sphere: wall 12 mm"), std::string::npos) << result.warnings[0];
    EXPECT_NE(result.warnings[0].find("returned solid"), std::string::npos) << result.warnings[0];
}

TEST(Hollow, BadParameters) {
    const Mesh sphere = test::make_sphere({0, 0, 0}, 10, 3);
    Progress progress;
    const auto status_of = [&](const HollowOptions& options) {
        try {
            hollow(sphere, options, progress);
        } catch (const Error& e) {
            return e.status();
        }
        return FABVDB_OK;
    };
    EXPECT_EQ(status_of(options_with(0.0, 0.5)), FABVDB_ERR_INVALID_ARGUMENT);
    EXPECT_EQ(status_of(options_with(-1.0, 0.5)), FABVDB_ERR_INVALID_ARGUMENT);
    EXPECT_EQ(status_of(options_with(2.0, 0.5, -1.0)), FABVDB_ERR_INVALID_ARGUMENT);
    HollowOptions lattice = options_with(2.0, 0.5);
    lattice.infill = {8.0, 2.5};  // struts wider than a quarter of the cell
    EXPECT_EQ(status_of(lattice), FABVDB_ERR_INVALID_ARGUMENT);
    lattice.infill = {8.0, 0.0};
    EXPECT_EQ(status_of(lattice), FABVDB_ERR_INVALID_ARGUMENT);
    HollowOptions tight = options_with(2.0, 0.001);
    tight.memory_budget_bytes = 64u << 20;
    EXPECT_EQ(status_of(tight), FABVDB_ERR_OUT_OF_BUDGET);
}

TEST(Hollow, CancelReturnsNoResult) {
    const Mesh sphere = test::make_sphere({0, 0, 0}, 20, 4);
    for (int cancel_at_call : {1, 3, 6}) {
        struct Counter {
            int calls = 0, cancel_at = 0;
        } counter{0, cancel_at_call};
        Progress progress(
            [](void* user, const char*, double) {
                auto* c = static_cast<Counter*>(user);
                return ++c->calls >= c->cancel_at ? 1 : 0;
            },
            &counter, nullptr);
        try {
            hollow(sphere, options_with(3.0, 0.5), progress);
            ADD_FAILURE() << "not cancelled at call " << cancel_at_call;
        } catch (const Error& e) {
            EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
        }
    }
}

}  // namespace
}  // namespace fabvdb::volume
