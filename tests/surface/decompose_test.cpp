// Mold decomposition acceptance on the shared sphere and torus: the output
// folder is read back and checked with code of its own
// (support/decomposition_checks.h: adjacency from the written triangles,
// connectivity, the overhang term evaluated from the written surface, the
// boundary length and turning), never with numbers the decomposition
// reported about itself alone. Boundary smoothing is compared with the same
// decomposition left unsmoothed. Two separate balls get parts of their own,
// every triangle owned; a thin plate, cast solid, is one part.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "io/mesh_io.h"
#include "surface/decompose.h"
#include "surface/decomposition_io.h"
#include "support/check_vec3.h"
#include "support/decomposition_checks.h"
#include "support/shapes.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;
using nlohmann::json;

struct Written {
    json doc;
    std::vector<Vec3> corners;  // outer vertices, then inner vertices
};

Written run_and_read_mesh(const Mesh& input, const std::string& folder, int smoothing_iterations = 10,
                          size_t low_res_triangles = 1500) {
    fabvdb::Progress progress;
    fabvdb::surface::DecomposeSettings settings;
    settings.shell.target_triangles = low_res_triangles;
    const fabvdb::BoundingBox box = fabvdb::bounding_box(input);
    settings.shell.thickness =
        0.03 * std::max({box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]});
    settings.decomposition.smoothing_iterations = smoothing_iterations;
    const auto result = fabvdb::surface::decompose_mesh(input, settings, {}, progress);
    fabvdb::surface::write_decomposition(folder, input, result.shell, result.terms, result.decomposition,
                                         settings.decomposition);
    Written w;
    w.doc = fabvdb::test::read_decomposition(folder + "/decomposition.json");
    for (const auto& v : w.doc["low_res_surface"]["vertices"]) w.corners.push_back(v.get<Vec3>());
    for (const auto& v : w.doc["low_res_surface"]["inner_vertices"]) w.corners.push_back(v.get<Vec3>());
    return w;
}

Written run_and_read(const std::string& mesh_name, const std::string& folder, int smoothing_iterations = 10) {
    fabvdb::Progress progress;
    const Mesh input = fabvdb::io::read_mesh(std::string(FABVDB_SHARED_DATA "/meshes/") + mesh_name, progress);
    return run_and_read_mesh(input, folder, smoothing_iterations);
}

using fabvdb::test::cross;
using fabvdb::test::dot;
using fabvdb::test::norm;
using fabvdb::test::sub;

std::vector<double> check_decomposition(const Written& w) { return fabvdb::test::check_decomposition(w.doc); }

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
    const double length = norm(mean);
    const double radius = norm(sub(w.corners[0], centre));
    size_t points = 0;
    for (const json& line : part["boundaries"])
        for (const json& p : line) {
            const Vec3 q = sub(p.get<Vec3>(), centre);
            EXPECT_LT(std::abs(dot(q, mean) / length), 0.3 * radius);
            ++points;
        }
    EXPECT_GT(points, 10u);
    EXPECT_LT(double(w.doc["total_moldability_energy"]), double(w.doc["gamma"]));
    std::filesystem::remove_all(folder);
}

TEST(Decompose, SeparateBallsGetPartsOfTheirOwn) {
    const std::string folder = std::filesystem::temp_directory_path() / "fabvdb_decompose_two_balls";
    const Mesh balls = fabvdb::test::merged(fabvdb::test::make_sphere({0, 0, 0}, 10.0, 3),
                                            fabvdb::test::make_sphere({30, 0, 0}, 6.0, 3));
    const Written w = run_and_read_mesh(balls, folder);
    // Every low-res triangle in a part (check_decomposition), and no part
    // spans both balls (parts are connected).
    const std::vector<double> areas = check_decomposition(w);
    EXPECT_GE(areas.size(), 2u);
    std::vector<int> side_of_part(areas.size(), -1);
    const auto triangles = w.doc["low_res_surface"]["triangles"];
    const auto part_of = w.doc["part_of_triangle"].get<std::vector<int>>();
    for (size_t t = 0; t < part_of.size(); ++t) {
        const int side = w.corners[triangles[t][0].get<uint32_t>()][0] > 15.0 ? 1 : 0;
        ASSERT_GE(part_of[t], 0);
        int& known = side_of_part[size_t(part_of[t])];
        if (known < 0) known = side;
        EXPECT_EQ(known, side) << "part " << part_of[t] << " spans both balls";
    }
    std::filesystem::remove_all(folder);
}

TEST(Decompose, ThinPlateIsOneSolidPart) {
    // 60 x 60 x 2 mm: thinner than 2ω (3.6 mm) everywhere, so it is cast
    // solid, and one two-piece mold along z casts it: one part, not two
    // slabs of 1 mm. ω becomes the plate's half thickness plus two voxels
    // (6000 low-res triangles: voxels of about 0.8 mm).
    const std::string folder = std::filesystem::temp_directory_path() / "fabvdb_decompose_plate";
    const Written w = run_and_read_mesh(fabvdb::test::make_box({-30, -30, -1}, {30, 30, 1}), folder, 10, 6000);
    EXPECT_TRUE(w.doc["solid"].get<bool>());
    ASSERT_EQ(w.doc["parts"].size(), 1u);
    check_decomposition(w);
    const Vec3 d = w.doc["parts"][0]["parting_direction"].get<Vec3>();
    EXPECT_GT(std::abs(d[2]), 0.99);
    EXPECT_LT(double(w.doc["shell_thickness"]), 3.5);
    EXPECT_GT(double(w.doc["shell_thickness"]), 1.0);
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

TEST(Decompose, SmoothingStraightensBoundariesKeepingPartsAndEnergy) {
    const std::string rough_folder = std::filesystem::temp_directory_path() / "fabvdb_decompose_torus_rough";
    const std::string smooth_folder = std::filesystem::temp_directory_path() / "fabvdb_decompose_torus_smooth";
    const Written rough = run_and_read("torus.obj", rough_folder, 0);
    const Written smooth = run_and_read("torus.obj", smooth_folder, 10);
    ASSERT_EQ(rough.doc["parts"].size(), smooth.doc["parts"].size());
    check_decomposition(smooth);
    EXPECT_EQ(rough.doc["part_of_triangle"], smooth.doc["part_of_triangle"]);
    const fabvdb::test::BoundaryMeasure before = fabvdb::test::measure_boundaries(rough.doc);
    const fabvdb::test::BoundaryMeasure after = fabvdb::test::measure_boundaries(smooth.doc);
    ASSERT_GT(before.vertices, 10u);
    EXPECT_LT(after.turning, 0.8 * before.turning) << "turning " << before.turning << " -> " << after.turning;
    EXPECT_LT(after.length, before.length) << "length " << before.length << " -> " << after.length;
    const double gamma = smooth.doc["gamma"];
    EXPECT_LT(double(smooth.doc["total_moldability_energy"]), gamma);
    // Moved vertices stay on the surface: every smoothed vertex is within a
    // small fraction of the shell thickness of the unsmoothed S_low (centroid
    // distance bound: the nearest written triangle's plane, within its circumradius).
    const auto faces = rough.doc["low_res_surface"]["triangles"].get<std::vector<std::array<uint32_t, 3>>>();
    const double omega = smooth.doc["shell_thickness"];
    const size_t v_count = rough.doc["low_res_surface"]["vertices"].size();
    for (size_t v = 0; v < v_count; ++v) {
        const Vec3& p = smooth.corners[v];
        double nearest = 1e300;
        for (const auto& f : faces) {
            const Vec3 a = rough.corners[f[0]], b = rough.corners[f[1]], c = rough.corners[f[2]];
            const Vec3 ab = sub(b, a), ac = sub(c, a);
            const Vec3 n = cross(ab, ac);
            const Vec3 centre{(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3};
            const double reach = std::sqrt(std::max({dot(sub(a, centre), sub(a, centre)), dot(sub(b, centre), sub(b, centre)),
                                                     dot(sub(c, centre), sub(c, centre))}));
            if (dot(sub(p, centre), sub(p, centre)) > reach * reach * 1.0001) continue;
            nearest = std::min(nearest, std::abs(dot(sub(p, a), n)) / norm(n));
        }
        EXPECT_LT(nearest, 1e-6 * omega + 1e-9) << "vertex " << v << " left the surface";
    }
    std::filesystem::remove_all(rough_folder);
    std::filesystem::remove_all(smooth_folder);
}

}  // namespace
