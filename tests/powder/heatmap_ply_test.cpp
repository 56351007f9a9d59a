// Heat maps: vertex values as area-weighted means of their triangles'
// patches (worked by hand on two triangles of areas 1 and 3; 0 on an unused
// vertex); the PLY read back byte by byte: header, positions, viridis ends
// and middle, clamping, values, faces turned over (and by io's PLY reader);
// low = high; the colours as data; mismatched sizes are INVALID_ARGUMENT; an
// unwritable path is IO and leaves no file.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/progress.h"
#include "io/mesh_io.h"
#include "powder/heatmap_ply.h"
#include "support/temp_files.h"

namespace {

using fabvdb::Mesh;
using fabvdb::powder::CavityPatches;
using fabvdb::powder::vertex_values;
using fabvdb::powder::write_heatmap_ply;

//! Triangle 0 (0, 1, 2) of area 1 and triangle 1 (1, 3, 2) of area 3, sharing
//! the edge 1–2; vertex 4 is used by none.
Mesh two_triangles() {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {6, 1, 0}, {9, 9, 9}};
    mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
    return mesh;
}

CavityPatches one_patch_per_triangle() {
    CavityPatches patches;
    patches.patch_of_triangle = {0, 1};
    patches.area = {1.0, 3.0};
    return patches;
}

template <class T>
T take(const std::string& bytes, size_t& at) {
    T value;
    std::memcpy(&value, bytes.data() + at, sizeof(T));
    at += sizeof(T);
    return value;
}

fabvdb::Error failure(const std::function<void()>& run) {
    try {
        run();
    } catch (const fabvdb::Error& e) {
        return e;
    }
    ADD_FAILURE() << "no error";
    return fabvdb::Error(FABVDB_OK, "");
}

}  // namespace

TEST(HeatmapPly, VertexValuesAreAreaWeightedMeans) {
    const Mesh mesh = two_triangles();
    const std::vector<double> values = vertex_values(mesh, one_patch_per_triangle(), {1.0, 5.0});
    ASSERT_EQ(values.size(), 5u);
    EXPECT_NEAR(values[0], 1.0, 1e-9);
    EXPECT_NEAR(values[3], 5.0, 1e-9);
    // Shared corners: (1·1 + 3·5) / 4.
    EXPECT_NEAR(values[1], 4.0, 1e-9);
    EXPECT_NEAR(values[2], 4.0, 1e-9);
    EXPECT_EQ(values[4], 0.0);
    // One patch over both triangles: every used corner has its value.
    CavityPatches one;
    one.patch_of_triangle = {0, 0};
    one.area = {4.0};
    const auto same = vertex_values(mesh, one, {-2.5});
    for (int v = 0; v < 4; ++v) EXPECT_NEAR(same[size_t(v)], -2.5, 1e-9);
}

TEST(HeatmapPly, VertexValuesRefuseMismatchedInputs) {
    const Mesh mesh = two_triangles();
    const fabvdb::Error few = failure([&] { vertex_values(mesh, one_patch_per_triangle(), {1.0}); });
    EXPECT_EQ(few.status(), FABVDB_ERR_INVALID_ARGUMENT);
    CavityPatches short_map = one_patch_per_triangle();
    short_map.patch_of_triangle.pop_back();
    EXPECT_EQ(failure([&] { vertex_values(mesh, short_map, {1.0, 2.0}); }).status(), FABVDB_ERR_INVALID_ARGUMENT);
}

TEST(HeatmapPly, WritesABinaryPlyWithViridisColoursAndValues) {
    fabvdb::test::TempDir dir;
    const std::string path = dir.file("heat.ply");
    const Mesh mesh = two_triangles();
    // low 0, high 4: 0 → viridis(0), 2 → viridis(0.5), 4 → viridis(1), −1 and 7 clamp.
    const std::vector<double> values{0.0, 2.0, 4.0, -1.0, 7.0};
    write_heatmap_ply(mesh, values, 0.0, 4.0, "residual powder", path);
    EXPECT_EQ(fabvdb::test::entry_count(dir.path()), 1);
    const std::string bytes = fabvdb::test::read_bytes(path);
    const std::string header_end = "end_header\n";
    const size_t body = bytes.find(header_end);
    ASSERT_NE(body, std::string::npos);
    const std::string header = bytes.substr(0, body + header_end.size());
    EXPECT_EQ(header.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u) << header;
    EXPECT_NE(header.find("comment fabvdb heat map: residual powder\n"), std::string::npos) << header;
    EXPECT_NE(header.find("element vertex 5\n"), std::string::npos) << header;
    EXPECT_NE(header.find("element face 2\n"), std::string::npos) << header;
    EXPECT_NE(header.find("property float x\nproperty float y\nproperty float z\nproperty uchar red\n"
                          "property uchar green\nproperty uchar blue\nproperty float quality\n"),
              std::string::npos)
        << header;
    EXPECT_NE(header.find("property list uchar int vertex_indices\n"), std::string::npos) << header;
    // 5 vertices of 3 floats, 3 bytes and a float; 2 faces of a count and 3 ints.
    ASSERT_EQ(bytes.size(), header.size() + 5 * (12 + 3 + 4) + 2 * (1 + 12));

    // Viridis at 0, 0.5 and 1 (matplotlib's stops × 255, rounded).
    const uint8_t expected_rgb[5][3] = {{68, 1, 84}, {33, 145, 140}, {253, 231, 37}, {68, 1, 84}, {253, 231, 37}};
    size_t at = header.size();
    for (size_t v = 0; v < 5; ++v) {
        for (int k = 0; k < 3; ++k) EXPECT_EQ(take<float>(bytes, at), float(mesh.vertices[v][k])) << "vertex " << v;
        for (int k = 0; k < 3; ++k) EXPECT_EQ(take<uint8_t>(bytes, at), expected_rgb[v][k]) << "vertex " << v;
        EXPECT_EQ(take<float>(bytes, at), float(values[v])) << "vertex " << v;
    }
    // Faces turned over: (a, b, c) is written (a, c, b).
    const int32_t faces[2][3] = {{0, 2, 1}, {1, 2, 3}};
    for (const auto& face : faces) {
        EXPECT_EQ(take<uint8_t>(bytes, at), 3);
        for (int32_t corner : face) EXPECT_EQ(take<int32_t>(bytes, at), corner);
    }
    EXPECT_EQ(at, bytes.size());
    // The project's own PLY reader takes it, extra properties and all.
    fabvdb::Progress progress;
    const Mesh back = fabvdb::io::read_mesh(path, progress);
    EXPECT_EQ(back.vertices, mesh.vertices);
    EXPECT_EQ(back.triangles, (std::vector<fabvdb::Triangle>{{0, 2, 1}, {1, 2, 3}}));
}

TEST(HeatmapPly, FacesKeptAsGivenOnRequest) {
    // An outer surface (fabvdb check's thickness map) keeps its orientation.
    fabvdb::test::TempDir dir;
    const std::string path = dir.file("outer.ply");
    const Mesh mesh = two_triangles();
    write_heatmap_ply(mesh, {0.0, 1.0, 2.0, 3.0, 4.0}, 0.0, 4.0, "wall thickness", path, false);
    fabvdb::Progress progress;
    EXPECT_EQ(fabvdb::io::read_mesh(path, progress).triangles, mesh.triangles);
}

TEST(HeatmapPly, AnEmptyRangeStillColours) {
    // low = high: the span becomes 1, so the value at low is viridis(0) and one above it viridis(1).
    fabvdb::test::TempDir dir;
    const std::string path = dir.file("flat.ply");
    Mesh mesh = two_triangles();
    write_heatmap_ply(mesh, {3.0, 3.0, 4.0, 3.5, 3.0}, 3.0, 3.0, "flat", path);
    const std::string bytes = fabvdb::test::read_bytes(path);
    size_t at = bytes.find("end_header\n") + 11;
    const uint8_t expected_rgb[5][3] = {{68, 1, 84}, {68, 1, 84}, {253, 231, 37}, {33, 145, 140}, {68, 1, 84}};
    for (size_t v = 0; v < 5; ++v) {
        at += 12;
        for (int k = 0; k < 3; ++k) EXPECT_EQ(take<uint8_t>(bytes, at), expected_rgb[v][k]) << "vertex " << v;
        at += 4;
    }
}

TEST(HeatmapPly, ColoursAsDataAreViridisOverTheRange) {
    // The same stops as the files: 0 → viridis(0), 2 → viridis(0.5), 4 → viridis(1) over [0, 4], clamped.
    using Rgb = std::array<uint8_t, 3>;
    EXPECT_EQ(fabvdb::powder::heatmap_colours({0.0, 2.0, 4.0, -1.0, 7.0}, 0.0, 4.0),
              (std::vector<Rgb>{{68, 1, 84}, {33, 145, 140}, {253, 231, 37}, {68, 1, 84}, {253, 231, 37}}));
    EXPECT_EQ(fabvdb::powder::heatmap_colours({3.0, 4.0}, 3.0, 3.0), (std::vector<Rgb>{{68, 1, 84}, {253, 231, 37}}));
    EXPECT_TRUE(fabvdb::powder::heatmap_colours({}, 0.0, 1.0).empty());
}

TEST(HeatmapPly, RefusesMismatchedValuesAndUnwritablePaths) {
    fabvdb::test::TempDir dir;
    const Mesh mesh = two_triangles();
    const std::string path = dir.file("heat.ply");
    EXPECT_EQ(failure([&] { write_heatmap_ply(mesh, {1, 2, 3}, 0, 1, "x", path); }).status(),
              FABVDB_ERR_INVALID_ARGUMENT);
    EXPECT_EQ(fabvdb::test::entry_count(dir.path()), 0);
    const std::string nowhere = dir.file("missing/heat.ply");
    const fabvdb::Error e = failure([&] { write_heatmap_ply(mesh, {0, 0, 0, 0, 0}, 0, 1, "x", nowhere); });
    EXPECT_EQ(e.status(), FABVDB_ERR_IO);
    EXPECT_EQ(fabvdb::test::entry_count(dir.path()), 0);
    // An existing file is replaced whole.
    fabvdb::test::write_bytes(path, "old");
    write_heatmap_ply(mesh, {0, 0, 0, 0, 0}, 0, 1, "x", path);
    EXPECT_EQ(fabvdb::test::read_bytes(path).rfind("ply\n", 0), 0u);
    EXPECT_EQ(fabvdb::test::entry_count(dir.path()), 1);
}
