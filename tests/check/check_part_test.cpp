// check_part on parts whose answer is known by construction, each check on
// its pass and its fail side: plates thinner and thicker than the resin
// minimum (the thinnest figure within half a voxel of the plate, no thin
// region on a thick plate's edges), a pin of known diameter on a base, a
// square channel of known width through a block, a sphere with a sealed
// cavity (its volume against the construction's), the same part in mm and
// in inches, overhangs of a floating box, the build volume, the heat map
// files, the default voxel (a thin fin on a long part still seen), a
// pocket opening toward the vat (a cup) and toward the plate (none), and
// fins: a thin wall on a block is one, a thin panel in a frame, a
// thin-walled closed box and a block with rounded edges have none.
// Expected figures come from the shapes' dimensions.
#include "check/check_part.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "support/shapes.h"
#include "support/tube.h"
#include "support/temp_files.h"

namespace fabvdb::check {
namespace {

nlohmann::json run(const Mesh& mesh, const std::string& process = "sla", double voxel = 0.0,
                   const Vec3& up = {0, 0, 1}, const Vec3& build = {0, 0, 0}, const std::string& map = "") {
    CheckOptions options;
    options.profile = builtin_profile(process);
    options.voxel_size = voxel;
    options.up = up;
    options.build_volume = build;
    options.thickness_map = map;
    Progress progress;
    return check_part(mesh, options, progress);
}

std::string status(const nlohmann::json& report, const char* check) {
    return report["checks"][check]["status"].get<std::string>();
}

//! A box [lo, hi] rounded by `r` (the points within r of it): each face of
//! the box grown by r, a grid whose lines are `arc` apart in the rounded
//! band, projected onto the rounded surface; welded by position.
Mesh rounded_box(const Vec3& lo, const Vec3& hi, double r, int arc) {
    std::vector<double> coords[3];
    for (int k = 0; k < 3; ++k) {
        for (int s = 0; s < arc; ++s) coords[k].push_back(lo[k] - r + r * s / arc);
        for (int s = 0; s < 8; ++s) coords[k].push_back(lo[k] + (hi[k] - lo[k]) * s / 8);
        for (int s = 0; s <= arc; ++s) coords[k].push_back(hi[k] + r * s / arc);
    }
    Mesh mesh;
    std::map<Vec3, uint32_t> index;
    const auto vertex = [&](const Vec3& v) {
        Vec3 q, p;
        double length = 0.0;
        for (int k = 0; k < 3; ++k) {
            q[k] = std::clamp(v[k], lo[k], hi[k]);
            length += (v[k] - q[k]) * (v[k] - q[k]);
        }
        for (int k = 0; k < 3; ++k) p[k] = q[k] + r * (v[k] - q[k]) / std::sqrt(length);
        const auto [at, added] = index.emplace(p, uint32_t(mesh.vertices.size()));
        if (added) mesh.vertices.push_back(p);
        return at->second;
    };
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int a = (axis + 1) % 3, b = (axis + 2) % 3;
            const double plane = side ? coords[axis].back() : coords[axis].front();
            for (size_t i = 0; i + 1 < coords[a].size(); ++i)
                for (size_t j = 0; j + 1 < coords[b].size(); ++j) {
                    Vec3 corner[4];
                    const size_t di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
                    for (int c = 0; c < 4; ++c) {
                        corner[c][axis] = plane;
                        corner[c][a] = coords[a][i + di[c]];
                        corner[c][b] = coords[b][j + dj[c]];
                    }
                    // (a, b, axis) is right-handed: the quad's order faces +axis.
                    uint32_t v[4];
                    for (int c = 0; c < 4; ++c) v[c] = vertex(corner[c]);
                    if (side) {
                        mesh.triangles.push_back({v[0], v[1], v[2]});
                        mesh.triangles.push_back({v[0], v[2], v[3]});
                    } else {
                        mesh.triangles.push_back({v[0], v[2], v[1]});
                        mesh.triangles.push_back({v[0], v[3], v[2]});
                    }
                }
        }
    return mesh;
}

Mesh scaled(Mesh mesh, double factor) {
    for (Vec3& p : mesh.vertices)
        for (double& c : p) c *= factor;
    return mesh;
}

TEST(CheckPart, ThinAndThickPlates) {
    const double voxel = 0.08;
    const nlohmann::json thin = run(test::make_box({0, 0, 0}, {20, 15, 0.3}), "sla", voxel);
    EXPECT_EQ(status(thin, "wall_thickness"), "fail");
    EXPECT_EQ(thin["verdict"], "fail");
    EXPECT_NEAR(thin["checks"]["wall_thickness"]["min_thickness"].get<double>(), 0.3, 0.5 * voxel);
    // The whole plate is thin: both faces, about 2·20·15 mm².
    EXPECT_GT(thin["checks"]["wall_thickness"]["thin_area"].get<double>(), 0.9 * 600.0);

    const nlohmann::json thick = run(test::make_box({0, 0, 0}, {20, 15, 1.5}), "sla", voxel);
    EXPECT_EQ(status(thick, "wall_thickness"), "pass") << thick["checks"]["wall_thickness"].dump();
    EXPECT_EQ(thick["checks"]["wall_thickness"]["region_count"], 0);
    EXPECT_EQ(status(thick, "mesh"), "pass");
    EXPECT_EQ(thick["checks"]["mesh"]["repair_path"], "none");
    EXPECT_EQ(status(thick, "units"), "pass");
    EXPECT_EQ(status(thick, "trapped_volumes"), "pass");
    EXPECT_EQ(status(thick, "holes"), "pass");
    EXPECT_EQ(status(thick, "small_features"), "pass");
    EXPECT_EQ(thick["verdict"], "pass");

    // Between the minimum and the margin above it: a warning.
    const nlohmann::json close = run(test::make_box({0, 0, 0}, {20, 15, 0.58}), "sla", voxel);
    EXPECT_EQ(status(close, "wall_thickness"), "warn") << close["checks"]["wall_thickness"].dump();
}

TEST(CheckPart, PinOfKnownDiameter) {
    const double voxel = 0.06;
    const Mesh base = test::make_box({-5, -5, -2}, {5, 5, 0.5});
    Mesh thin_pin = test::make_tube(0.0, 0.15, 4.0, 64);  // 0.3 mm across, under the 0.5 mm minimum
    const nlohmann::json thin = run(test::merged(base, thin_pin), "sla", voxel);
    EXPECT_EQ(status(thin, "small_features"), "fail") << thin["checks"]["small_features"].dump();
    ASSERT_GE(thin["checks"]["small_features"]["pins"].size(), 1u);
    const nlohmann::json& pin = thin["checks"]["small_features"]["pins"][0];
    EXPECT_NEAR(pin["diameter"].get<double>(), 0.3, 0.5 * voxel);
    EXPECT_NEAR(pin["center"][0].get<double>(), 0.0, 0.3);
    EXPECT_NEAR(pin["center"][1].get<double>(), 0.0, 0.3);

    const Mesh thick_pin = test::make_tube(0.0, 0.5, 4.0, 64);  // 1 mm across
    const nlohmann::json thick = run(test::merged(base, thick_pin), "sla", voxel);
    EXPECT_EQ(status(thick, "small_features"), "pass") << thick["checks"]["small_features"].dump();
}

TEST(CheckPart, ChannelOfKnownWidth) {
    const double voxel = 0.05;
    // A block 6 x 6 x 8 with a square channel `w` wide along z, made of four
    // walls around it (overlapping shells: the solid is their union).
    const auto block = [](double w) {
        const double a = 3.0 - w / 2, b = 3.0 + w / 2;
        Mesh m = test::make_box({0, 0, 0}, {a, 6, 8});
        m = test::merged(m, test::make_box({b, 0, 0}, {6, 6, 8}));
        m = test::merged(m, test::make_box({0, 0, 0}, {6, a, 8}));
        return test::merged(m, test::make_box({0, b, 0}, {6, 6, 8}));
    };
    const nlohmann::json narrow = run(block(0.3), "sla", voxel);
    EXPECT_EQ(status(narrow, "holes"), "fail") << narrow["checks"]["holes"].dump();
    EXPECT_NEAR(narrow["checks"]["holes"]["min_diameter"].get<double>(), 0.3, 0.5 * voxel);
    const nlohmann::json wide = run(block(1.0), "sla", voxel);
    EXPECT_EQ(status(wide, "holes"), "pass") << wide["checks"]["holes"].dump();
}

TEST(CheckPart, SphereWithASealedCavity) {
    const Mesh hollow = test::merged(test::make_sphere({0, 0, 0}, 10.0, 4), test::flipped(test::make_sphere({0, 0, 0}, 6.0, 4)));
    const double cavity = -test::mesh_volume(test::flipped(test::make_sphere({0, 0, 0}, 6.0, 4)));
    const nlohmann::json resin = run(hollow, "sla", 0.2);
    EXPECT_EQ(status(resin, "trapped_volumes"), "fail");
    ASSERT_EQ(resin["checks"]["trapped_volumes"]["cavities"].size(), 1u);
    EXPECT_NEAR(resin["checks"]["trapped_volumes"]["cavities"][0]["volume"].get<double>(), cavity, 0.03 * cavity);
    EXPECT_NEAR(resin["checks"]["trapped_volumes"]["cavities"][0]["center"][0].get<double>(), 0.0, 0.2);
    const nlohmann::json fdm = run(hollow, "fdm", 0.2);
    EXPECT_EQ(status(fdm, "trapped_volumes"), "pass");
    EXPECT_EQ(fdm["checks"]["trapped_volumes"]["cavities"].size(), 1u);
    const nlohmann::json solid = run(test::make_sphere({0, 0, 0}, 10.0, 4), "sla", 0.2);
    EXPECT_EQ(status(solid, "trapped_volumes"), "pass");
}

TEST(CheckPart, SamePartInMillimetresAndInches) {
    const Mesh part = test::make_box({0, 0, 0}, {50, 30, 20});
    const nlohmann::json mm = run(part, "fdm");
    EXPECT_EQ(status(mm, "units"), "pass");
    EXPECT_EQ(mm["verdict"], "pass") << mm.dump();
    const nlohmann::json inches = run(scaled(part, 1.0 / 25.4), "fdm");
    EXPECT_EQ(status(inches, "units"), "warn");
    EXPECT_EQ(inches["checks"]["units"]["suggested_scale"], 25.4);
    EXPECT_EQ(inches["checks"]["units"]["readings"][0]["unit"], "in");
}

TEST(CheckPart, OverhangsAndBuildVolume) {
    const Mesh two = test::merged(test::make_box({0, 0, 0}, {10, 10, 10}), test::make_box({20, 0, 5}, {30, 10, 10}));
    const nlohmann::json fdm = run(two, "fdm", 0.25);
    EXPECT_EQ(status(fdm, "overhangs"), "warn");
    EXPECT_NEAR(fdm["checks"]["overhangs"]["area"].get<double>(), 100.0, 5.0);
    const nlohmann::json powder = run(two, "powder", 0.25);
    EXPECT_EQ(status(powder, "overhangs"), "pass");

    const Mesh box = test::make_box({0, 0, 0}, {50, 30, 20});
    EXPECT_EQ(status(run(box, "fdm", 0.5, {0, 0, 1}, {100, 100, 100}), "build_volume"), "pass");
    EXPECT_EQ(status(run(box, "fdm", 0.5, {0, 0, 1}, {30, 60, 50}), "build_volume"), "warn");
    EXPECT_EQ(status(run(box, "fdm", 0.5, {0, 0, 1}, {40, 40, 40}), "build_volume"), "fail");
    // Standing on its 30 x 20 side (up +x), the part is 50 tall.
    const nlohmann::json standing = run(box, "fdm", 0.5, {1, 0, 0}, {100, 100, 100});
    EXPECT_NEAR(standing["checks"]["build_volume"]["size"][2].get<double>(), 50.0, 1e-9);
    EXPECT_FALSE(run(box, "fdm", 0.5)["checks"].contains("build_volume"));
}

TEST(CheckPart, DefaultVoxelResolvesTheMinimumWall) {
    // The longest side / 400, kept between a quarter and a half of the
    // minimum wall (0.5 mm for resin, 0.8 mm for FDM).
    EXPECT_DOUBLE_EQ(run(test::make_box({0, 0, 0}, {20, 4, 4}))["voxel_size"].get<double>(), 0.125);
    EXPECT_DOUBLE_EQ(run(test::make_box({0, 0, 0}, {100, 4, 4}), "fdm")["voxel_size"].get<double>(), 0.25);
    // A 200 mm part: 0.5 mm voxels would be the resin minimum itself; a fin
    // of 0.3 mm on it is still seen at 0.25 mm: both its faces above the
    // block (2 x 10 x 9 mm^2) read thin.
    const Mesh fin = test::merged(test::make_box({0, 0, 0}, {200, 10, 3}), test::make_box({100.05, 0, 2}, {100.35, 10, 12}));
    const nlohmann::json long_part = run(fin);
    const nlohmann::json& walls = long_part["checks"]["wall_thickness"];
    EXPECT_DOUBLE_EQ(long_part["voxel_size"].get<double>(), 0.25);
    EXPECT_EQ(status(long_part, "wall_thickness"), "fail") << walls.dump();
    EXPECT_LT(walls["min_thickness"].get<double>(), 0.5);
    EXPECT_GT(walls["thin_area"].get<double>(), 0.8 * 180.0) << walls.dump();
}

TEST(CheckPart, ThicknessMapFiles) {
    test::TempDir dir;
    const std::string path = dir.file("walls.ply");
    const nlohmann::json report = run(test::make_box({0, 0, 0}, {10, 10, 1}), "sla", 0.1, {0, 0, 1}, {0, 0, 0}, path);
    const std::string ply = test::read_bytes(path);
    EXPECT_EQ(ply.rfind("ply\n", 0), 0u);
    EXPECT_NE(ply.find("property float quality"), std::string::npos);
    EXPECT_FALSE(test::read_bytes(dir.file("walls.png")).empty());
    EXPECT_EQ(report["checks"]["wall_thickness"]["map"]["legend"], dir.file("walls.png"));
}

TEST(CheckPart, CupsFacingTheVat) {
    // A 10 x 10 x 8 block with a 6 x 6 x 6 pocket open at the top (z = 8).
    Mesh pocket = test::make_box({0, 0, 0}, {2, 10, 8});
    pocket = test::merged(pocket, test::make_box({8, 0, 0}, {10, 10, 8}));
    pocket = test::merged(pocket, test::make_box({2, 0, 0}, {8, 2, 8}));
    pocket = test::merged(pocket, test::make_box({2, 8, 0}, {8, 10, 8}));
    const Mesh through = pocket;
    pocket = test::merged(pocket, test::make_box({2, 2, 0}, {8, 8, 2}));
    const double voxel = 0.25;
    const nlohmann::json vat = run(pocket, "sla", voxel, {0, 0, 1});
    const nlohmann::json& cups = vat["checks"]["cups"];
    EXPECT_EQ(status(vat, "cups"), "warn") << cups.dump();
    ASSERT_EQ(cups["cups"].size(), 1u);
    EXPECT_NEAR(cups["cups"][0]["volume"].get<double>(), 216.0, 36.0 * voxel);  // a layer of cells at most
    EXPECT_NEAR(cups["cup_volume"].get<double>(), cups["cups"][0]["volume"].get<double>(), 1e-9);
    EXPECT_NEAR(cups["cups"][0]["opening_center"][2].get<double>(), 8.0, voxel);
    EXPECT_DOUBLE_EQ(cups["cell"].get<double>(), voxel);
    EXPECT_EQ(vat["verdict"], "warn");
    EXPECT_EQ(status(run(pocket, "sla", voxel, {0, 0, -1}), "cups"), "pass");  // opens toward the plate
    EXPECT_EQ(status(run(through, "sla", voxel, {0, 0, 1}), "cups"), "pass");
    const nlohmann::json fdm = run(pocket, "fdm", voxel, {0, 0, 1});
    EXPECT_EQ(status(fdm, "cups"), "pass");
    EXPECT_TRUE(fdm["checks"]["cups"]["cell"].is_null());
    EXPECT_TRUE(fdm["checks"]["cups"]["cups"].empty());
}

TEST(CheckPart, FinsAndHeldWalls) {
    const double voxel = 0.06;
    // A 0.3 mm wall standing 4 mm on a block: held along its foot only.
    const Mesh fin = test::merged(test::make_box({0, 0, 0}, {10, 6, 2}), test::make_box({4.85, 1, 1.5}, {5.15, 5, 6}));
    const nlohmann::json on_block = run(fin, "sla", voxel);
    const nlohmann::json& features = on_block["checks"]["small_features"];
    EXPECT_EQ(status(on_block, "small_features"), "fail") << features.dump();
    ASSERT_EQ(features["fins"].size(), 1u) << features.dump();
    // Its thinnest reading lies where its end meets the block (a concave
    // corner the walk reads within a voxel), the minimum wall well above.
    EXPECT_NEAR(features["fins"][0]["min_thickness"].get<double>(), 0.3, voxel);
    EXPECT_NEAR(features["fins"][0]["center"][0].get<double>(), 5.0, 0.3);
    EXPECT_GT(features["fins"][0]["box"]["max"][2].get<double>(), 5.5);
    EXPECT_TRUE(features["pins"].empty());

    // The same 0.3 mm sheet as a panel held all round in a frame.
    Mesh frame = test::make_box({0, 0, 0}, {3, 10, 4});
    frame = test::merged(frame, test::make_box({7, 0, 0}, {10, 10, 4}));
    frame = test::merged(frame, test::make_box({3, 0, 0}, {7, 3, 4}));
    frame = test::merged(frame, test::make_box({3, 7, 0}, {7, 10, 4}));
    const nlohmann::json panel = run(test::merged(frame, test::make_box({3, 3, 1.85}, {7, 7, 2.15})), "sla", voxel);
    EXPECT_EQ(status(panel, "wall_thickness"), "fail");
    EXPECT_TRUE(panel["checks"]["small_features"]["fins"].empty()) << panel["checks"]["small_features"].dump();

    // A closed box of 0.3 mm walls: thin all over, a wall, no fin.
    const Mesh shell = test::merged(test::make_box({0, 0, 0}, {6, 5, 4}),
                                    test::flipped(test::make_box({0.3, 0.3, 0.3}, {5.7, 4.7, 3.7})));
    const nlohmann::json closed = run(shell, "sla", voxel);
    EXPECT_EQ(status(closed, "wall_thickness"), "fail");
    EXPECT_TRUE(closed["checks"]["small_features"]["fins"].empty()) << closed["checks"]["small_features"].dump();

    // A block with edges rounded to 0.2 mm (a fillet's ball is 0.4 mm, under
    // the 0.5 mm minimum): its edges read the block, no thin wall, no fin.
    const nlohmann::json rounded = run(rounded_box({0, 0, 0}, {8, 6, 3}, 0.2, 8), "sla", voxel);
    EXPECT_EQ(status(rounded, "wall_thickness"), "pass") << rounded["checks"]["wall_thickness"].dump();
    EXPECT_EQ(status(rounded, "small_features"), "pass") << rounded["checks"]["small_features"].dump();
    EXPECT_EQ(rounded["checks"]["mesh"]["repair_path"], "none");
}

TEST(CheckPart, OpenSheetFailsWithAVerdictForEveryCheck) {
    // An open box (no lid) encloses no volume: the check fails it, the mesh
    // check saying why, instead of refusing it as bad input; the build
    // volume, measured on the triangles, is still judged.
    const nlohmann::json report = run(test::make_open_box({0, 0, 0}, {20, 20, 10}), "sla", 0.0, {0, 0, 1},
                                      {250, 210, 220});
    EXPECT_EQ(report["verdict"], "fail");
    EXPECT_EQ(status(report, "mesh"), "fail");
    EXPECT_NE(report["checks"]["mesh"]["message"].get<std::string>().find("encloses no volume"), std::string::npos);
    EXPECT_TRUE(report["checks"]["mesh"]["no_solid"].is_string());
    EXPECT_EQ(status(report, "units"), "pass");
    EXPECT_EQ(status(report, "build_volume"), "pass");
    for (const char* name : {"wall_thickness", "small_features", "holes", "trapped_volumes", "overhangs", "cups"})
        EXPECT_EQ(status(report, name), "fail") << name;
    // The same box closed is measured.
    EXPECT_NE(run(test::make_box({0, 0, 0}, {20, 20, 10}))["checks"]["mesh"]["status"], "fail");
}

}  // namespace
}  // namespace fabvdb::check
