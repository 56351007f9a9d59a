// The inspection of every shared mesh against the table of
// ../shared/data/meshes/README.md, transcribed below: counts, topology, and
// the notes (genus, duplicate and zero-area triangles, unreferenced vertices,
// counts after welding, orientation). Two self-intersection counts differ from
// the table, whose float test misjudged them; the tests below prove each
// difference with exact arithmetic:
// - teapot.obj: the table says 157, the exact count is 161. Ten pairs touch in
//   a single point (edges in the plane z = 0 that cross); a float test loses
//   some of these to rounding.
// - wallhole.obj: the table says 22, the exact count is 29. The 7 more pairs
//   involve one of the file's 11 zero-area triangles, which a float
//   triangle-triangle test cannot see; without them the count is the table's.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include "io/mesh_io.h"
#include "surface/inspect.h"
#include "surface/self_intersections.h"

namespace {

using fabvdb::Mesh;
using nlohmann::json;

constexpr long unstated = -1;

struct TableRow {
    const char* file;
    long vertices, triangles;
    bool closed;
    long components, boundary_edges, boundary_loops, non_manifold_edges, non_manifold_vertices;
    long self_intersecting_pairs;  // as the table gives it
    // From the notes column (unstated: not checked). "No defects found" is read
    // as no duplicate, degenerate or inconsistently oriented triangles.
    long genus, duplicate_triangles, degenerate_triangles, unreferenced_vertices;
    // After welding bit-identical positions: duplicate positions, boundary edges,
    // non-manifold edges, components.
    long duplicate_positions, welded_boundary_edges, welded_non_manifold_edges, welded_components;
};

// clang-format off
const TableRow table[] = {
    // file                         V      T    closed C  BE  L  NME NMV SI  genus dup deg unref  dupV  wBE wNME wC
    {"bunny.off",                   3485,  6966, true, 1, 0,  0, 0,  0,  0,  0,    0,  0,  0,     unstated, unstated, unstated, unstated},
    {"stanford-bunny.obj",         35947, 69451, false, 1, 223, 5, 0, 0, 0, unstated, unstated, unstated, 1113, unstated, unstated, unstated, unstated},
    {"bunny_trimesh_broken.ply",    8171, 16301, false, 1, 123, 5, 150, 0, 0, unstated, 87, unstated, 25, unstated, unstated, unstated, unstated},
    {"kitten.obj",                  9447, 18894, true, 1, 0,  0, 0,  0,  0,  1,    0,  0,  0,     unstated, unstated, unstated, unstated},
    {"fertility.off",               4494,  9000, true, 1, 0,  0, 0,  0,  0,  4,    0,  0,  0,     unstated, unstated, unstated, unstated},
    {"armadillo_29k.obj",          14587, 29170, true, 1, 0,  0, 0,  0,  0,  0,    0,  0,  0,     unstated, unstated, unstated, unstated},
    {"armadillo_86k.obj",          43243, 86482, true, 1, 0,  0, 0,  0,  0,  0,    0,  0,  0,     unstated, unstated, unstated, unstated},
    {"max-planck_decimated.obj",    5272, 10540, true, 1, 0,  0, 0,  0,  0,  0,    0,  0,  0,     unstated, unstated, unstated, unstated},
    {"airplane.obj",                7017, 10796, true, 1, 0,  0, 0,  0,  0,  0,    unstated, unstated, 1617, unstated, unstated, unstated, unstated},
    {"torus.obj",                   2304,  4608, true, 1, 0,  0, 0,  0,  0,  1,    0,  0,  0,     unstated, unstated, unstated, unstated},
    {"sphere.obj",                   642,  1280, true, 1, 0,  0, 0,  0,  0,  0,    0,  0,  0,     unstated, unstated, unstated, unstated},
    {"spot.obj",                    2930,  5856, true, 1, 0,  0, 0,  0,  0,  0,    0,  0,  0,     unstated, unstated, unstated, unstated},
    {"cow.obj",                     2903,  5804, true, 1, 0,  0, 0,  1,  71, unstated, unstated, unstated, unstated, unstated, unstated, unstated, unstated},
    {"elephant.obj",                6034, 12064, true, 1, 0,  0, 0,  0,  0,  0,    0,  0,  0,     unstated, unstated, unstated, unstated},
    {"dragon_20k.obj",             10002, 20000, true, 1, 0,  0, 0,  0,  18, 0,    unstated, unstated, unstated, unstated, unstated, unstated, unstated},
    {"fandisk.obj",                 6475, 12946, true, 1, 0,  0, 0,  0,  0,  0,    0,  0,  0,     unstated, unstated, unstated, unstated},
    {"rocker-arm.obj",             10044, 20088, true, 1, 0,  0, 0,  0,  0,  1,    0,  0,  0,     unstated, unstated, unstated, unstated},
    {"teapot.obj",                  3644,  6320, false, 4, 1036, 10, 0, 38, 157, unstated, unstated, unstated, unstated, 403, 160, 0, 3},
    {"camelhead.off",              11381, 22704, false, 1, 56, 1, 0, 0,  3,  unstated, unstated, unstated, unstated, unstated, unstated, unstated, unstated},
    {"3holes.off",                  3596,  7200, true, 1, 0,  0, 0,  0,  0,  3,    0,  0,  0,     unstated, unstated, unstated, unstated},
    {"cube_no_bottom.obj",            25,    40, false, 1, 8, 1, 0,  0,  0,  unstated, unstated, unstated, unstated, unstated, unstated, unstated, unstated},
    {"non_manifold_face_graph.off",   24,    21, false, 3, 21, 3, 0, 0,  0,  unstated, unstated, unstated, unstated, 3, 20, 1, 1},
    {"quads_to_stitch.off",           20,    16, false, 2, 20, 2, 0, 0,  0,  unstated, unstated, unstated, unstated, 5, 12, 0, 1},
    {"cube_with_fold.ply",            26,    48, true, 1, 0,  0, 0,  0,  3,  0,    unstated, unstated, unstated, unstated, unstated, unstated, unstated},
    {"degenerated.obj",                7,    24, false, 1, 0, 0, 6,  0,  0,  unstated, 12, unstated, unstated, unstated, unstated, unstated, unstated},
    {"joined_tetrahedra.obj",          5,     8, false, 1, 0, 0, 3,  0,  0,  unstated, 1, unstated, unstated, unstated, unstated, unstated, unstated},
    {"wallhole.obj",                  92,    66, false, 13, 92, 13, 0, 0, 22, unstated, unstated, 11, unstated, 57, 0, 1, 1},
    {"multibody.stl",                 20,    32, true, 2, 0,  0, 0,  0,  0,  0,    unstated, unstated, unstated, unstated, unstated, unstated, unstated},
};
// clang-format on

std::string shared_mesh(const std::string& file) { return std::string(FABVDB_SHARED_DATA "/meshes/") + file; }

Mesh read(const std::string& file) {
    fabvdb::Progress progress;
    return fabvdb::io::read_mesh(shared_mesh(file), progress);
}

json inspect(const Mesh& mesh) {
    fabvdb::Progress progress;
    return fabvdb::surface::inspect_mesh(mesh, progress);
}

void expect_stated(long expected, const json& value, const char* what) {
    if (expected != unstated) EXPECT_EQ(value.get<long>(), expected) << what;
}

class SharedMeshTable : public ::testing::TestWithParam<TableRow> {};

TEST_P(SharedMeshTable, InspectionAgreesWithTheTable) {
    const TableRow& row = GetParam();
    const json r = inspect(read(row.file));
    EXPECT_EQ(r["vertices"].get<long>(), row.vertices);
    EXPECT_EQ(r["triangles"].get<long>(), row.triangles);
    EXPECT_EQ(r["closed"].get<bool>(), row.closed);
    EXPECT_EQ(r["components"].get<long>(), row.components);
    EXPECT_EQ(r["boundary_edges"].get<long>(), row.boundary_edges);
    EXPECT_EQ(r["boundary_loops"].get<long>(), row.boundary_loops);
    EXPECT_EQ(r["non_manifold_edges"].get<long>(), row.non_manifold_edges);
    EXPECT_EQ(r["non_manifold_vertices"].get<long>(), row.non_manifold_vertices);
    // teapot and wallhole: the exact counts differ, see their own tests below.
    if (std::string(row.file) != "teapot.obj" && std::string(row.file) != "wallhole.obj")
        EXPECT_EQ(r["self_intersecting_pairs"].get<long>(), row.self_intersecting_pairs);
    if (row.genus != unstated)
        EXPECT_EQ(r["genus"].get<long>(), row.genus);
    else if (!row.closed || row.non_manifold_vertices > 0)
        EXPECT_TRUE(r["genus"].is_null());
    expect_stated(row.duplicate_triangles, r["duplicate_triangles"], "duplicate triangles");
    expect_stated(row.degenerate_triangles, r["degenerate_triangles"], "degenerate triangles");
    expect_stated(row.unreferenced_vertices, r["unreferenced_vertices"], "unreferenced vertices");
    if (row.duplicate_positions != unstated)
        EXPECT_EQ(r["vertices"].get<long>() - r["welded"]["vertices"].get<long>(), row.duplicate_positions);
    expect_stated(row.welded_boundary_edges, r["welded"]["boundary_edges"], "welded boundary edges");
    expect_stated(row.welded_non_manifold_edges, r["welded"]["non_manifold_edges"], "welded non-manifold edges");
    expect_stated(row.welded_components, r["welded"]["components"], "welded components");
    EXPECT_EQ(r["volume"].is_null(), !row.closed);
    if (row.duplicate_triangles == 0 && row.degenerate_triangles == 0 && std::string(row.file) != "multibody.stl")
        EXPECT_TRUE(r["consistently_oriented"].get<bool>());
}

INSTANTIATE_TEST_SUITE_P(Meshes, SharedMeshTable, ::testing::ValuesIn(table), [](const auto& info) {
    std::string name = info.param.file;
    std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
    return name;
});

TEST(SharedMeshNotes, MultibodyHasMixedWindingAndOneInsideOutShell) {
    const json r = inspect(read("multibody.stl"));
    EXPECT_EQ(r["inconsistent_edges"], 12);
    EXPECT_FALSE(r["consistently_oriented"].get<bool>());
    EXPECT_EQ(r["negative_volume_shells"], 1);
    EXPECT_EQ(r["genus"], 0);
}

using K = CGAL::Epeck;
using Pairs = std::vector<std::pair<uint32_t, uint32_t>>;

K::Point_3 exact_point(const Mesh& mesh, uint32_t v) {
    return {mesh.vertices[v][0], mesh.vertices[v][1], mesh.vertices[v][2]};
}

K::Triangle_3 exact_triangle(const Mesh& mesh, uint32_t t) {
    const auto& c = mesh.triangles[t];
    return {exact_point(mesh, c[0]), exact_point(mesh, c[1]), exact_point(mesh, c[2])};
}

Pairs pairs_of(const Mesh& mesh) {
    fabvdb::Progress progress;
    return fabvdb::surface::self_intersecting_pairs(mesh, progress);
}

TEST(SharedMeshNotes, TeapotHasTenSinglePointContactsTheFloatTableMissedSomeOf) {
    const Mesh mesh = read("teapot.obj");
    const Pairs pairs = pairs_of(mesh);
    EXPECT_EQ(pairs.size(), 161u);
    // Every pair reported is a true intersection (exact constructions), and
    // exactly ten meet in a single point.
    size_t single_points = 0;
    for (const auto& [i, j] : pairs) {
        const auto meet = CGAL::intersection(exact_triangle(mesh, i), exact_triangle(mesh, j));
        ASSERT_TRUE(meet) << i << " " << j;
        if (const K::Point_3* point = boost::get<K::Point_3>(&*meet)) {
            ++single_points;
            EXPECT_EQ(point->z(), 0);  // the plane of symmetry, where the patches' edges cross
        }
    }
    EXPECT_EQ(single_points, 10u);
    // The table's 157 lies between the count without those point contacts and ours.
    EXPECT_LE(pairs.size() - single_points, 157u);
    EXPECT_GE(pairs.size(), 157u);
}

TEST(SharedMeshNotes, WallholeCountsTheTablesPairsPlusThoseWithZeroAreaTriangles) {
    const Mesh mesh = read("wallhole.obj");
    const json r = inspect(mesh);
    EXPECT_EQ(r["self_intersecting_pairs"], 29);
    EXPECT_EQ(r["self_intersecting_pairs_degenerate"], 7);
    EXPECT_EQ(r["self_intersecting_pairs"].get<long>() - r["self_intersecting_pairs_degenerate"].get<long>(), 22);

    // All pairs, by brute force with CGAL's exact-construction kernel on
    // the corners' hull (a collapsed triangle as its longest side).
    auto hull_meets = [&](uint32_t s, uint32_t t) {
        auto as_segment = [&](uint32_t u) {
            const auto& c = mesh.triangles[u];
            K::Segment_3 longest(exact_point(mesh, c[0]), exact_point(mesh, c[1]));
            for (const K::Segment_3& side : {K::Segment_3(exact_point(mesh, c[1]), exact_point(mesh, c[2])),
                                             K::Segment_3(exact_point(mesh, c[0]), exact_point(mesh, c[2]))})
                if (side.squared_length() > longest.squared_length()) longest = side;
            return longest;
        };
        const bool flat_s = exact_triangle(mesh, s).is_degenerate(), flat_t = exact_triangle(mesh, t).is_degenerate();
        if (flat_s && flat_t) return CGAL::do_intersect(as_segment(s), as_segment(t));
        if (flat_s) return CGAL::do_intersect(as_segment(s), exact_triangle(mesh, t));
        if (flat_t) return CGAL::do_intersect(exact_triangle(mesh, s), as_segment(t));
        return CGAL::do_intersect(exact_triangle(mesh, s), exact_triangle(mesh, t));
    };
    auto share_position = [&](uint32_t s, uint32_t t) {
        for (uint32_t u : mesh.triangles[s])
            for (uint32_t v : mesh.triangles[t])
                if (mesh.vertices[u] == mesh.vertices[v]) return true;
        return false;
    };
    Pairs expected;
    for (uint32_t s = 0; s < mesh.triangles.size(); ++s)
        for (uint32_t t = s + 1; t < mesh.triangles.size(); ++t)
            if (!share_position(s, t) && hull_meets(s, t)) expected.push_back({s, t});
    EXPECT_EQ(pairs_of(mesh), expected);
}

}  // namespace
