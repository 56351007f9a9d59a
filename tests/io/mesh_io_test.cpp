// Reading every shared test mesh gives the vertex and triangle counts of the
// table in its README; format dispatch by extension; the bad inputs every
// format must reject cleanly; progress and cancellation while reading.
#include "io/mesh_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "io/io_test_files.h"

namespace {

struct TableRow {
    std::string file;
    size_t vertices = 0;
    size_t triangles = 0;
};

size_t parse_count(std::string cell) {
    std::string digits;
    for (char c : cell)
        if (c >= '0' && c <= '9') digits += c;
    return std::stoul(digits);
}

//! The rows of the table in the shared meshes README (file, Vertices, Triangles).
std::vector<TableRow> shared_mesh_table() {
    std::ifstream readme(FABVDB_SHARED_DATA "/meshes/README.md");
    std::vector<TableRow> rows;
    std::string line;
    while (std::getline(readme, line)) {
        if (line.rfind("| `", 0) != 0) continue;
        std::vector<std::string> cells;
        std::stringstream stream(line.substr(1));
        std::string cell;
        while (std::getline(stream, cell, '|')) cells.push_back(cell);
        TableRow row;
        const size_t open = cells[0].find('`');
        row.file = cells[0].substr(open + 1, cells[0].find('`', open + 1) - open - 1);
        row.vertices = parse_count(cells[3]);
        row.triangles = parse_count(cells[4]);
        rows.push_back(row);
    }
    return rows;
}

}  // namespace

TEST(MeshIo, SharedMeshesHaveTheTableCounts) {
    const std::vector<TableRow> rows = shared_mesh_table();
    ASSERT_EQ(rows.size(), 28u);
    for (const TableRow& row : rows) {
        SCOPED_TRACE(row.file);
        fabvdb::Progress progress;
        const fabvdb::Mesh mesh = fabvdb::io::read_mesh(FABVDB_SHARED_DATA "/meshes/" + row.file, progress);
        EXPECT_EQ(mesh.vertices.size(), row.vertices);
        EXPECT_EQ(mesh.triangles.size(), row.triangles);
    }
}

TEST(MeshIo, FormatComesFromTheExtensionInAnyCase) {
    using fabvdb::io::MeshFormat;
    EXPECT_EQ(fabvdb::io::format_from_path("a/b.STL"), MeshFormat::stl);
    EXPECT_EQ(fabvdb::io::format_from_path("b.Obj"), MeshFormat::obj);
    EXPECT_EQ(fabvdb::io::format_from_path("x.y/b.ply"), MeshFormat::ply);
    EXPECT_EQ(fabvdb::io::format_from_path("b.off"), MeshFormat::off);
    EXPECT_EQ(fabvdb::io::format_from_path("b.3MF"), MeshFormat::threemf);
}

TEST(MeshIo, UnknownExtensionListsTheKnownOnes) {
    for (const char* path : {"model.dae", "dir.stl/model", "model"}) {
        try {
            fabvdb::io::format_from_path(path);
            ADD_FAILURE() << path;
        } catch (const fabvdb::Error& e) {
            EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT);
            const std::string message = e.what();
            EXPECT_NE(message.find(path), std::string::npos) << message;
            EXPECT_NE(message.find(".stl, .obj, .ply, .off, .3mf"), std::string::npos) << message;
        }
    }
}

namespace {

const char* const extensions[] = {"stl", "obj", "ply", "off", "3mf"};

}  // namespace

TEST(MeshIoBadInput, EmptyFileOfEveryFormat) {
    fabvdb::test::TempDir dir;
    for (const char* extension : extensions)
        fabvdb::test::expect_read_error(fabvdb::test::write_bytes(dir.file(std::string("empty.") + extension), ""),
                                        FABVDB_ERR_BAD_INPUT, "empty file");
}

TEST(MeshIoBadInput, MissingPathAndDirectoryAreIoErrors) {
    fabvdb::test::TempDir dir;
    for (const char* extension : extensions) {
        fabvdb::test::expect_read_error(dir.file(std::string("missing.") + extension), FABVDB_ERR_IO,
                                        "No such file");
        const std::string folder = dir.file(std::string("folder.") + extension);
        std::filesystem::create_directory(folder);
        fabvdb::test::expect_read_error(folder, FABVDB_ERR_IO, "is a directory");
    }
}

TEST(MeshIoBadInput, ZeroTrianglesInEveryFormat) {
    fabvdb::test::TempDir dir;
    using fabvdb::test::write_bytes;
    const std::string no_triangles = "no triangles";
    fabvdb::test::expect_read_error(write_bytes(dir.file("points.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\n"),
                                    FABVDB_ERR_BAD_INPUT, no_triangles);
    fabvdb::test::expect_read_error(write_bytes(dir.file("points.off"), "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"),
                                    FABVDB_ERR_BAD_INPUT, no_triangles);
    fabvdb::test::expect_read_error(
        write_bytes(dir.file("points.ply"), "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                            "property float y\nproperty float z\nend_header\n0 0 0\n"),
        FABVDB_ERR_BAD_INPUT, no_triangles);
    fabvdb::test::expect_read_error(write_bytes(dir.file("nothing.stl"), "solid empty\nendsolid empty\n"),
                                    FABVDB_ERR_BAD_INPUT, no_triangles);
    fabvdb::test::expect_read_error(FABVDB_TEST_DATA_DIR "/io/no_triangles.3mf", FABVDB_ERR_BAD_INPUT, no_triangles);
}

TEST(MeshIoBadInput, NonFiniteCoordinatesInEveryTextFormat) {
    fabvdb::test::TempDir dir;
    using fabvdb::test::write_bytes;
    const std::string defect = "vertex 2 has a non-finite coordinate";
    fabvdb::test::expect_read_error(write_bytes(dir.file("nan.obj"), "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"),
                                    FABVDB_ERR_BAD_INPUT, defect);
    fabvdb::test::expect_read_error(
        write_bytes(dir.file("inf.off"), "OFF\n3 1 0\n0 0 0\n1 -inf 0\n0 1 0\n3 0 1 2\n"), FABVDB_ERR_BAD_INPUT,
        defect);
    fabvdb::test::expect_read_error(
        write_bytes(dir.file("inf.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                         "property float y\nproperty float z\nelement face 1\n"
                                         "property list uchar int vertex_indices\nend_header\n"
                                         "0 0 0\n1 0 inf\n0 1 0\n3 0 1 2\n"),
        FABVDB_ERR_BAD_INPUT, defect);
    fabvdb::test::expect_read_error(write_bytes(dir.file("huge.obj"), "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n"),
                                    FABVDB_ERR_BAD_INPUT, "line 2: vertex coordinate '1e999' is out of range");
}

TEST(MeshIoBadInput, NothingIsWrittenForAnInvalidMesh) {
    fabvdb::test::TempDir dir;
    fabvdb::Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 3}};
    for (const char* extension : extensions) {
        const std::string path = dir.file(std::string("bad.") + extension);
        EXPECT_THROW(fabvdb::io::write_mesh(mesh, path), fabvdb::Error);
        EXPECT_FALSE(std::filesystem::exists(path)) << path;
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

namespace {

int cancel_at_half(void* user, const char*, double fraction) {
    auto* fractions = static_cast<std::vector<double>*>(user);
    fractions->push_back(fraction);
    return fraction >= 0.5;
}

}  // namespace

TEST(MeshIo, ReadingReportsProgressAndCanBeCancelled) {
    std::vector<double> fractions;
    fabvdb::Progress progress(cancel_at_half, &fractions, nullptr);
    try {
        fabvdb::io::read_mesh(FABVDB_SHARED_DATA "/meshes/armadillo_86k.obj", progress);
        ADD_FAILURE() << "the read was not cancelled";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED) << e.what();
    }
    ASSERT_GE(fractions.size(), 3u);
    EXPECT_GE(fractions.back(), 0.5);
    EXPECT_LT(fractions.back(), 1.0);
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
}

TEST(MeshIoBadInput, EveryTruncationOfAValidFileIsReadOrCleanlyRejected) {
    fabvdb::test::TempDir dir;
    const std::string sources[] = {FABVDB_SHARED_DATA "/meshes/multibody.stl",
                                   FABVDB_SHARED_DATA "/meshes/cube_with_fold.ply",
                                   FABVDB_SHARED_DATA "/meshes/bunny_trimesh_broken.ply",
                                   FABVDB_SHARED_DATA "/meshes/quads_to_stitch.off",
                                   FABVDB_SHARED_DATA "/meshes/wallhole.obj",
                                   FABVDB_TEST_DATA_DIR "/io/transformed_components.3mf"};
    for (const std::string& source : sources) {
        std::ifstream in(source, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        ASSERT_FALSE(bytes.empty()) << source;
        const std::string path = dir.file("cut" + source.substr(source.rfind('.')));
        int rejected = 0;
        for (size_t step = 0; step < 64; ++step) {
            const size_t length = bytes.size() * step / 64;
            fabvdb::test::write_bytes(path, bytes.substr(0, length));
            try {
                fabvdb::test::read(path);
            } catch (const fabvdb::Error& e) {
                EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT) << source << " cut at " << length << ": " << e.what();
                ++rejected;
            }
        }
        EXPECT_GT(rejected, 0) << source;
    }
}
