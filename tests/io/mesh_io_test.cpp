// Reading every shared test mesh gives the vertex and triangle counts of the
// table in its README; format dispatch by extension.
#include "io/mesh_io.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <vector>

#include "core/error.h"

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
