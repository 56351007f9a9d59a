// Mold decomposition acceptance on the shared sphere and torus: the output
// folder is read back and checked with code of its own (adjacency from the
// written triangles, breadth-first connectivity, the overhang term evaluated
// from the written surface), never with numbers the decomposition reported
// about itself alone.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "io/mesh_io.h"
#include "surface/decompose.h"
#include "surface/decomposition_io.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;
using nlohmann::json;

struct Written {
    json doc;
    std::vector<Vec3> corners;  // outer vertices, then inner vertices
};

Written run_and_read(const std::string& mesh_name, const std::string& folder) {
    fabvdb::Progress progress;
    const Mesh input = fabvdb::io::read_mesh(std::string(FABVDB_SHARED_DATA "/meshes/") + mesh_name, progress);
    fabvdb::surface::DecomposeSettings settings;
    settings.shell.target_triangles = 1500;
    const fabvdb::BoundingBox box = fabvdb::bounding_box(input);
    settings.shell.thickness =
        0.03 * std::max({box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]});
    const auto result = fabvdb::surface::decompose_mesh(input, settings, {}, progress);
    fabvdb::surface::write_decomposition(folder, input, result.shell, result.terms, result.decomposition,
                                         settings.decomposition);
    Written w;
    std::ifstream in(folder + "/decomposition.json");
    in >> w.doc;
    for (const auto& v : w.doc["low_res_surface"]["vertices"]) w.corners.push_back(v.get<Vec3>());
    for (const auto& v : w.doc["low_res_surface"]["inner_vertices"]) w.corners.push_back(v.get<Vec3>());
    return w;
}

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 crs(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dt(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

//! Number of connected pieces of `triangles` (corner triples) joined across shared edges.
size_t pieces(const std::vector<std::array<uint32_t, 3>>& triangles) {
    std::map<std::pair<uint32_t, uint32_t>, std::vector<size_t>> by_edge;
    for (size_t i = 0; i < triangles.size(); ++i)
        for (int k = 0; k < 3; ++k)
            by_edge[std::minmax(triangles[i][k], triangles[i][(k + 1) % 3])].push_back(i);
    std::vector<int> seen(triangles.size(), 0);
    size_t count = 0;
    for (size_t s = 0; s < triangles.size(); ++s) {
        if (seen[s]) continue;
        ++count;
        std::vector<size_t> stack{s};
        seen[s] = 1;
        while (!stack.empty()) {
            const size_t i = stack.back();
            stack.pop_back();
            for (int k = 0; k < 3; ++k)
                for (size_t j : by_edge[std::minmax(triangles[i][k], triangles[i][(k + 1) % 3])])
                    if (!seen[j]) {
                        seen[j] = 1;
                        stack.push_back(j);
                    }
        }
    }
    return count;
}

//! The checks every decomposition must pass; returns the part areas (mm²).
std::vector<double> check_decomposition(const Written& w) {
    const json& doc = w.doc;
    const auto all = doc["low_res_surface"]["triangles"].get<std::vector<std::array<uint32_t, 3>>>();
    std::vector<int> owner(all.size(), -1);
    std::vector<double> areas;
    const double s = doc["unit_scale"];
    const double draft = double(doc["draft_degrees"]) * M_PI / 180.0;
    for (const json& part : doc["parts"]) {
        const int id = part["id"];
        std::vector<std::array<uint32_t, 3>> prisms;
        double area = 0;
        for (uint32_t t : part["prisms"].get<std::vector<uint32_t>>()) {
            EXPECT_EQ(owner[t], -1) << "triangle " << t << " in two parts";
            owner[t] = id;
            prisms.push_back(all[t]);
            const Vec3 c = crs(sub(w.corners[all[t][1]], w.corners[all[t][0]]),
                               sub(w.corners[all[t][2]], w.corners[all[t][0]]));
            area += 0.5 * std::sqrt(dt(c, c));
        }
        areas.push_back(area);
        EXPECT_EQ(pieces(prisms), 1u) << "part " << id << " is not connected";
        // M⁺ and M⁻ each one connected piece; overhang recomputed from the written surface.
        const auto surface = part["surface"]["triangles"].get<std::vector<std::array<uint32_t, 3>>>();
        const auto upper = part["surface"]["upper"].get<std::vector<int>>();
        const auto kind = part["surface"]["kind"].get<std::vector<int>>();
        std::vector<std::array<uint32_t, 3>> top, bottom;
        const Vec3 d = part["parting_direction"].get<Vec3>();
        double overhang = 0;
        for (size_t i = 0; i < surface.size(); ++i) {
            (upper[i] ? top : bottom).push_back(surface[i]);
            if (kind[i] == 1) continue;  // inner triangles are invisible
            const auto& f = surface[i];
            const Vec3 c = crs(sub(w.corners[f[1]], w.corners[f[0]]), sub(w.corners[f[2]], w.corners[f[0]]));
            const double twice = std::sqrt(dt(c, c));
            if (twice == 0) continue;
            const double facing = dt(c, d) / twice * (upper[i] ? 1 : -1);
            const double theta = std::acos(std::max(-1.0, std::min(1.0, facing)));
            if (theta > M_PI / 2 - draft)
                overhang += -std::cos(std::min(theta + draft, M_PI)) * 0.5 * twice * s * s * std::abs(facing);
        }
        EXPECT_LE(pieces(top), 1u) << "M+ of part " << id;
        EXPECT_LE(pieces(bottom), 1u) << "M- of part " << id;
        EXPECT_NEAR(overhang, double(part["overhang_energy"]), 1e-9 + 1e-6 * overhang) << "part " << id;
    }
    for (size_t t = 0; t < owner.size(); ++t) EXPECT_GE(owner[t], 0) << "triangle " << t << " in no part";
    return areas;
}

TEST(Decompose, SphereSplitsInTwoHalvesNearAGreatCircle) {
    const std::string folder = std::filesystem::temp_directory_path() / "fabvdb_decompose_sphere";
    const Written w = run_and_read("sphere.obj", folder);
    ASSERT_EQ(w.doc["parts"].size(), 2u);
    const std::vector<double> areas = check_decomposition(w);
    EXPECT_GT(std::min(areas[0], areas[1]) / std::max(areas[0], areas[1]), 0.8);
    // The boundary lies near a plane through the centre: its points are close
    // to the plane normal to the line between the two parts' centroids.
    Vec3 centre{0, 0, 0};
    for (const Vec3& p : w.doc["low_res_surface"]["vertices"].get<std::vector<Vec3>>())
        for (int k = 0; k < 3; ++k) centre[k] += p[k] / double(w.doc["low_res_surface"]["vertices"].size());
    const json& part = w.doc["parts"][0];
    const auto all = w.doc["low_res_surface"]["triangles"].get<std::vector<std::array<uint32_t, 3>>>();
    Vec3 mean{0, 0, 0};
    for (uint32_t t : part["prisms"].get<std::vector<uint32_t>>())
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j) mean[k] += w.corners[all[t][j]][k] - centre[k];
    const double length = std::sqrt(dt(mean, mean));
    const double radius = std::sqrt(dt(sub(w.corners[0], centre), sub(w.corners[0], centre)));
    size_t points = 0;
    for (const json& line : part["boundaries"])
        for (const json& p : line) {
            const Vec3 q = sub(p.get<Vec3>(), centre);
            EXPECT_LT(std::abs(dt(q, mean) / length), 0.3 * radius);
            ++points;
        }
    EXPECT_GT(points, 10u);
    EXPECT_LT(double(w.doc["total_moldability_energy"]), double(w.doc["gamma"]));
    std::filesystem::remove_all(folder);
}

TEST(Decompose, TorusSplitsInTwoMoldableParts) {
    const std::string folder = std::filesystem::temp_directory_path() / "fabvdb_decompose_torus";
    const Written w = run_and_read("torus.obj", folder);
    EXPECT_EQ(w.doc["parts"].size(), 2u);
    check_decomposition(w);
    EXPECT_LT(double(w.doc["total_moldability_energy"]), double(w.doc["gamma"]));
    EXPECT_TRUE(std::filesystem::is_regular_file(folder + "/decomposition.ply"));
    EXPECT_TRUE(std::filesystem::is_regular_file(folder + "/deformation.ply"));
    std::filesystem::remove_all(folder);
}

}  // namespace
