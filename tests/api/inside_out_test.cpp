// Inside-out and mirrored inputs give the same model, through the C API
// (fabvdb.h) only: every shared mesh and a set of corpus meshes (dirty ones
// with crossing and overlapping shells, CAD parts of several bodies),
// scaled to 40 mm, each also turned inside out (every triangle reversed)
// and mirrored (x negated: a mirror image stored inside out). For each of
// repair, hollow, drain and decompose (its S_low), a variant must end as the
// original did: the same status when the original is refused; else the
// same model — the enclosed volume within a voxel's worth (the output's
// area × the voxel) and every point of the original's output (mirrored back
// for the mirrored variant; 2000 area samples) within 2.5 voxels of the
// variant's output and back (drain: 99% of them, its holes may open
// elsewhere on a mirror image). Measured with CGAL and the divergence
// theorem, not with the library's figures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "fabvdb.h"
#include "support/cgal_mesh.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;

const char* const kShared[] = {"3holes.off",        "airplane.obj",       "armadillo_29k.obj",
                               "armadillo_86k.obj", "bunny.off",          "bunny_trimesh_broken.ply",
                               "camelhead.off",     "cow.obj",            "cube_no_bottom.obj",
                               "cube_with_fold.ply", "degenerated.obj",   "dragon_20k.obj",
                               "elephant.obj",      "fandisk.obj",        "fertility.off",
                               "joined_tetrahedra.obj", "kitten.obj",     "max-planck_decimated.obj",
                               "multibody.stl",     "non_manifold_face_graph.off", "quads_to_stitch.off",
                               "rocker-arm.obj",    "sphere.obj",         "spot.obj",
                               "stanford-bunny.obj", "teapot.obj",        "torus.obj",
                               "wallhole.obj"};
const char* const kCorpus[] = {"suzanne.obj",   "mat_test.obj",        "Spider_ascii.stl", "fs-lever.stl",
                               "latch_x2.stl",  "pcb_din_clip_x3.stl", "rabbit.obj",       "3DSMaxExport.STL",
                               "regr01.obj",    "african_head.obj"};

struct Context {
    fabvdb_ctx* ctx = nullptr;
    Context() { fabvdb_ctx_new(&ctx); }
    ~Context() { fabvdb_ctx_free(ctx); }
};

Mesh mesh_of(const fabvdb_mesh* handle) {
    Mesh mesh;
    const double* v = fabvdb_mesh_vertices(handle);
    const uint32_t* t = fabvdb_mesh_triangles(handle);
    for (size_t i = 0; i < fabvdb_mesh_vertex_count(handle); ++i) mesh.vertices.push_back({v[3 * i], v[3 * i + 1], v[3 * i + 2]});
    for (size_t i = 0; i < fabvdb_mesh_triangle_count(handle); ++i) mesh.triangles.push_back({t[3 * i], t[3 * i + 1], t[3 * i + 2]});
    return mesh;
}

fabvdb_mesh* handle_of(fabvdb_ctx* ctx, const Mesh& mesh) {
    std::vector<double> v;
    std::vector<uint32_t> t;
    for (const Vec3& p : mesh.vertices) v.insert(v.end(), p.begin(), p.end());
    for (const auto& tri : mesh.triangles) t.insert(t.end(), tri.begin(), tri.end());
    fabvdb_mesh* out = nullptr;
    EXPECT_EQ(fabvdb_mesh_new(ctx, v.data(), mesh.vertices.size(), t.data(), mesh.triangles.size(), &out), FABVDB_OK);
    return out;
}

//! The model read and scaled about the origin so that its longest side is 40 mm.
std::optional<Mesh> read_scaled(fabvdb_ctx* ctx, const std::string& path) {
    fabvdb_mesh* read = nullptr;
    if (fabvdb_mesh_read(ctx, path.c_str(), &read) != FABVDB_OK) return std::nullopt;
    Mesh mesh = mesh_of(read);
    fabvdb_mesh_free(read);
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (const auto& t : mesh.triangles)
        for (uint32_t i : t)
            for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], mesh.vertices[i][k]), hi[k] = std::max(hi[k], mesh.vertices[i][k]);
    const double longest = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    if (!(longest > 0)) return std::nullopt;
    for (Vec3& p : mesh.vertices)
        for (double& x : p) x *= 40.0 / longest;
    return mesh;
}

Mesh inside_out(Mesh mesh) {
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
    return mesh;
}

Mesh mirrored(Mesh mesh) {
    for (Vec3& p : mesh.vertices) p[0] = -p[0];
    return mesh;
}

double volume(const Mesh& mesh) {
    double six = 0;
    for (const auto& t : mesh.triangles) {
        const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
        six += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    return six / 6;
}

double area(const Mesh& mesh) {
    double sum = 0;
    for (const auto& t : mesh.triangles) {
        const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
        const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        sum += 0.5 * std::hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
    }
    return sum;
}

//! Distances from 2000 area samples of `from` to `to`, sorted.
std::vector<double> distances(const Mesh& from, const Mesh& to) {
    const auto triangles = fabvdb::test::cgal::triangles_of(to);
    fabvdb::test::cgal::Tree tree(triangles.begin(), triangles.end());
    tree.accelerate_distance_queries();
    std::vector<double> cumulative;
    double total = 0;
    for (const auto& t : from.triangles) {
        Mesh one{from.vertices, {t}};
        total += area(one);
        cumulative.push_back(total);
    }
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<double> out;
    for (int i = 0; i < 2000; ++i) {
        const size_t k = size_t(std::upper_bound(cumulative.begin(), cumulative.end(), unit(random) * total) -
                                cumulative.begin());
        const auto& t = from.triangles[std::min(k, from.triangles.size() - 1)];
        double u = unit(random), v = unit(random);
        if (u + v > 1) u = 1 - u, v = 1 - v;
        Vec3 p;
        for (int c = 0; c < 3; ++c)
            p[c] = from.vertices[t[0]][c] + u * (from.vertices[t[1]][c] - from.vertices[t[0]][c]) +
                   v * (from.vertices[t[2]][c] - from.vertices[t[0]][c]);
        out.push_back(std::sqrt(tree.squared_distance(fabvdb::test::cgal::point(p))));
    }
    std::sort(out.begin(), out.end());
    return out;
}

//! A command's outcome: its status and, when it succeeded, its solid and
//! the length a voxel stands for.
struct Outcome {
    fabvdb_status status = FABVDB_OK;
    std::string message;
    Mesh solid;
    double voxel = 0;
};

using Command = Outcome (*)(fabvdb_ctx*, const fabvdb_mesh*);

//! The outcome of a command that returned `status` and made `out` (freed
//! here), whose voxel is `voxel`.
Outcome outcome_of(fabvdb_ctx* ctx, fabvdb_status status, fabvdb_mesh* out, double voxel) {
    Outcome o;
    o.status = status;
    if (status == FABVDB_OK) o.solid = mesh_of(out);
    o.message = fabvdb_last_error(ctx);
    o.voxel = voxel;
    fabvdb_mesh_free(out);
    return o;
}

Outcome repair(fabvdb_ctx* ctx, const fabvdb_mesh* mesh) {
    fabvdb_volume_options options;
    fabvdb_volume_options_init(&options);
    options.resolution = 64;
    fabvdb_mesh* out = nullptr;
    const fabvdb_status status = fabvdb_mesh_repair(ctx, mesh, &options, &out, nullptr);
    return outcome_of(ctx, status, out, 40.0 / 64);
}

Outcome hollow(fabvdb_ctx* ctx, const fabvdb_mesh* mesh) {
    fabvdb_hollow_options options;
    fabvdb_hollow_options_init(&options);
    options.wall = 3.0;
    fabvdb_mesh* out = nullptr;
    const fabvdb_status status = fabvdb_mesh_hollow(ctx, mesh, &options, &out, nullptr);
    return outcome_of(ctx, status, out, 0.75);
}

Outcome drain(fabvdb_ctx* ctx, const fabvdb_mesh* mesh) {
    fabvdb_drain_options options;
    fabvdb_drain_options_init(&options);
    options.wall = 3.0;
    options.hole_count = 1;
    options.patch_count = 100;
    const double turns[] = {0, 0, -1, 0, 0, 1, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0};
    options.orientations = turns;
    options.orientation_count = 6;
    fabvdb_mesh* out = nullptr;
    const fabvdb_status status = fabvdb_mesh_drain(ctx, mesh, &options, &out, nullptr);
    return outcome_of(ctx, status, out, 0.75);
}

//! S_low, the surface the parts are cut from; its voxel is its mean edge.
Outcome decompose(fabvdb_ctx* ctx, const fabvdb_mesh* mesh) {
    fabvdb_decompose_options options;
    fabvdb_decompose_options_init(&options);
    options.low_res_triangles = 800;
    options.smoothing_iterations = 0;
    options.parts = 2;
    Outcome o;
    fabvdb_decomposition* session = nullptr;
    o.status = fabvdb_decomposition_new(ctx, mesh, &options, &session);
    o.message = fabvdb_last_error(ctx);
    if (o.status == FABVDB_OK) {
        const double* v = fabvdb_decomposition_vertices(session);
        const uint32_t* t = fabvdb_decomposition_triangles(session);
        for (size_t i = 0; i < fabvdb_decomposition_vertex_count(session); ++i)
            o.solid.vertices.push_back({v[3 * i], v[3 * i + 1], v[3 * i + 2]});
        double edges = 0;
        for (size_t i = 0; i < fabvdb_decomposition_triangle_count(session); ++i) {
            o.solid.triangles.push_back({t[3 * i], t[3 * i + 1], t[3 * i + 2]});
            for (int k = 0; k < 3; ++k) {
                const Vec3 &a = o.solid.vertices[t[3 * i + k]], &b = o.solid.vertices[t[3 * i + (k + 1) % 3]];
                edges += std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
            }
        }
        o.voxel = edges / double(3 * std::max<size_t>(1, o.solid.triangles.size()));
    }
    fabvdb_decomposition_free(session);
    return o;
}

void same_model(Command command, bool holes_may_move) {
    Context context;
    std::vector<std::string> paths;
    for (const char* name : kShared) paths.push_back(std::string(FABVDB_SHARED_DATA "/meshes/") + name);
    for (const char* name : kCorpus) paths.push_back(std::string(FABVDB_SHARED_DATA "/corpus/") + name);
    for (const std::string& path : paths) {
        SCOPED_TRACE(path);
        const std::optional<Mesh> input = read_scaled(context.ctx, path);
        ASSERT_TRUE(input.has_value()) << fabvdb_last_error(context.ctx);
        std::optional<Outcome> original;
        for (int variant = 0; variant < 3; ++variant) {
            SCOPED_TRACE(variant == 0 ? "as given" : variant == 1 ? "inside out" : "mirrored");
            const Mesh given = variant == 0 ? *input : variant == 1 ? inside_out(*input) : mirrored(*input);
            fabvdb_mesh* handle = handle_of(context.ctx, given);
            Outcome outcome = command(context.ctx, handle);
            fabvdb_mesh_free(handle);
            if (variant == 0) {
                original = std::move(outcome);
                continue;
            }
            ASSERT_EQ(outcome.status, original->status) << outcome.message << " / as given: " << original->message;
            if (outcome.status != FABVDB_OK) continue;
            const Mesh expected = variant == 2 ? inside_out(mirrored(original->solid)) : original->solid;
            const double h = original->voxel;
            EXPECT_NEAR(volume(outcome.solid), volume(expected), h * area(expected));
            const std::vector<double> there = distances(expected, outcome.solid);
            const std::vector<double> back = distances(outcome.solid, expected);
            const size_t at = holes_may_move ? there.size() * 99 / 100 : there.size() - 1;
            EXPECT_LE(there[at], 2.5 * h) << "the original's output far from the variant's";
            EXPECT_LE(back[at], 2.5 * h) << "the variant's output far from the original's";
        }
    }
}

TEST(InsideOut, Repair) { same_model(repair, false); }
TEST(InsideOut, Hollow) { same_model(hollow, false); }
TEST(InsideOut, Drain) { same_model(drain, true); }
TEST(InsideOut, Decompose) { same_model(decompose, false); }

}  // namespace
