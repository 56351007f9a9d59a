//! shell_from_mesh on solids with known geometry: a sphere of radius 20 as a
//! 2 mm shell gives a closed S_low on the sphere, outward unit normals, unit
//! areas summing to 4πr² · unit_scale², inner vertices 2 mm deep and no thin
//! feature, with the stats matching the shell; a plate 2.4 mm thick under a
//! 1.5 mm shell (< 2ω) is one thin segment; cast solid, no segment and ω the
//! sphere's radius (its depth plus two voxels, capped at half its extent).
//! No triangles (the message naming the input), a zero thickness and a
//! cancelled run are refused with their status.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "core/error.h"
#include "shell_shapes.h"
#include "support/check_vec3.h"
#include "surface/shell_from_mesh.h"

namespace {

using fabvdb::Vec3;
using fabvdb::surface::Shell;
using fabvdb::volume::LowResShellOptions;

using fabvdb::test::dot;
using fabvdb::test::norm;

Shell shell_of_mesh(const fabvdb::Mesh& mesh, const LowResShellOptions& options, nlohmann::json* stats) {
    fabvdb::Progress progress;
    return fabvdb::surface::shell_from_mesh(mesh, options, progress, stats);
}

LowResShellOptions shell_options(double thickness) {
    LowResShellOptions options;
    options.target_triangles = 2000;
    options.thickness = thickness;
    options.input_name = "test part";
    return options;
}

const double radius = 20.0;
fabvdb::Mesh sphere() { return fabvdb::test::make_sphere({0, 0, 0}, radius, 4); }

//! Expects `call` to throw Error(`status`) whose message contains `text`.
template <class Call>
void expect_error(Call call, fabvdb_status status, const std::string& text) {
    try {
        call();
        ADD_FAILURE() << "no exception";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), status) << e.what();
        EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
}

}  // namespace

TEST(ShellFromMesh, SphereShellLiesOnTheSphereWithInnerVerticesOmegaDeep) {
    nlohmann::json stats;
    const Shell shell = shell_of_mesh(sphere(), shell_options(2.0), &stats);
    EXPECT_FALSE(shell.solid);
    EXPECT_EQ(shell.thickness, 2.0);
    const double voxel = stats.at("voxel_size").get<double>();
    EXPECT_GT(voxel, 0.0);
    EXPECT_LE(voxel, 2.0 / 3.0 + 1e-12);
    ASSERT_GT(shell.triangle_count(), 500u);
    EXPECT_LT(shell.triangle_count(), 8000u);
    ASSERT_EQ(shell.inner.size(), shell.outer.vertices.size());
    for (size_t v = 0; v < shell.outer.vertices.size(); ++v) {
        EXPECT_NEAR(norm(shell.outer.vertices[v]), radius, 0.5 * voxel) << "vertex " << v;
        EXPECT_NEAR(norm(shell.inner[v]), radius - 2.0, voxel) << "inner vertex " << v;
    }
    // Outward unit normals; unit-cube areas of a sphere of diameter ~40.
    double area = 0;
    for (size_t t = 0; t < shell.triangle_count(); ++t) {
        const Vec3& n = shell.normal[t];
        EXPECT_NEAR(norm(n), 1.0, 1e-9);
        const Vec3& p = shell.outer.vertices[shell.outer.triangles[t][0]];
        EXPECT_GT(dot(n, p), 0.9 * radius) << "triangle " << t;
        area += shell.area[t];
        for (int u : shell.neighbor[t]) EXPECT_GE(u, 0);
    }
    EXPECT_NEAR(shell.unit_scale, 1.0 / (2 * radius), 0.05 / (2 * radius));
    const double sphere_area = 4 * M_PI * radius * radius * shell.unit_scale * shell.unit_scale;
    EXPECT_NEAR(area, sphere_area, 0.03 * sphere_area);
    for (int segment : shell.thin_segment) EXPECT_EQ(segment, -1);

    EXPECT_EQ(stats.at("low_res_triangles").get<size_t>(), shell.triangle_count());
    EXPECT_EQ(stats.at("low_res_vertices").get<size_t>(), shell.outer.vertices.size());
    EXPECT_EQ(stats.at("thin_segments").get<int>(), 0);
    EXPECT_EQ(stats.at("thin_triangles").get<size_t>(), 0u);
    EXPECT_GE(stats.at("half_band_voxels").get<int>(), int(std::ceil(4.0 / voxel)));
    EXPECT_TRUE(stats.at("timings").contains("thin_features"));
}

TEST(ShellFromMesh, ThinPlateIsOneThinSegment) {
    // 2.4 mm thick: under 2ω = 3 mm, so the plate is cast solid, never cut.
    nlohmann::json stats;
    const Shell shell = shell_of_mesh(fabvdb::test::make_box({0, 0, 0}, {30, 30, 2.4}), shell_options(1.5), &stats);
    size_t thin = 0;
    for (int segment : shell.thin_segment) {
        EXPECT_TRUE(segment == -1 || segment == 0) << segment;
        thin += segment == 0;
    }
    EXPECT_EQ(stats.at("thin_segments").get<int>(), 1);
    EXPECT_EQ(stats.at("thin_triangles").get<size_t>(), thin);
    EXPECT_GT(thin, shell.triangle_count() * 9 / 10);
    EXPECT_EQ(fabvdb::test::connected_pieces(shell, shell.thin_segment, 0), 1);
}

TEST(ShellFromMesh, SolidSphereHasNoThinSegmentAndOmegaIsItsRadius) {
    LowResShellOptions options = shell_options(0.0);
    options.solid = true;
    nlohmann::json stats;
    const Shell shell = shell_of_mesh(sphere(), options, &stats);
    EXPECT_TRUE(shell.solid);
    const double voxel = stats.at("voxel_size").get<double>();
    // The deepest point (r) plus two voxels, capped at half the longest side (r).
    EXPECT_NEAR(shell.thickness, radius, voxel);
    for (int segment : shell.thin_segment) EXPECT_EQ(segment, -1);
    EXPECT_EQ(stats.at("thin_segments").get<int>(), 0);
}

TEST(ShellFromMesh, StatsAreOptional) {
    const Shell shell = shell_of_mesh(fabvdb::test::make_box({0, 0, 0}, {20, 20, 20}), shell_options(2.0), nullptr);
    EXPECT_GT(shell.triangle_count(), 100u);
}

TEST(ShellFromMesh, RefusesNoTrianglesAZeroThicknessAndACancelledRun) {
    expect_error([] { shell_of_mesh(fabvdb::Mesh{}, shell_options(1.0), nullptr); }, FABVDB_ERR_BAD_INPUT,
                 "test part: the mesh has no triangles");
    expect_error([] { shell_of_mesh(sphere(), shell_options(0.0), nullptr); }, FABVDB_ERR_INVALID_ARGUMENT,
                 "thickness");
    std::atomic<bool> cancel{true};
    fabvdb::Progress cancelled(nullptr, nullptr, &cancel);
    expect_error([&] { fabvdb::surface::shell_from_mesh(sphere(), shell_options(1.0), cancelled, nullptr); },
                 FABVDB_ERR_CANCELLED, "");
}
