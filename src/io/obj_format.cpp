//! OBJ reader (line records, relative indices, continuations) and writer.
#include "io/obj_format.h"

#include <vector>

#include "core/error.h"
#include "io/input_file.h"
#include "io/output_file.h"
#include "io/polygon_fan.h"
#include "io/text_scanner.h"

namespace fabvdb::io {

namespace {

uint32_t corner_index(const TextScanner& scanner, std::string_view token, size_t vertex_count) {
    const std::string_view position = token.substr(0, token.find('/'));
    const int64_t index = scanner.parse_integer(position, "face vertex index");
    if (index == 0) scanner.fail("face vertex index 0 (OBJ indices start at 1)");
    const int64_t resolved = index > 0 ? index - 1 : static_cast<int64_t>(vertex_count) + index;
    if (resolved < 0 || resolved > static_cast<int64_t>(UINT32_MAX) - 1)
        scanner.fail("face vertex index " + std::to_string(index) + " is out of range (" +
                     std::to_string(vertex_count) + " vertices so far)");
    return static_cast<uint32_t>(resolved);
}

}  // namespace

Mesh read_obj(const std::string& path, Progress& progress) {
    const std::string bytes = read_file_bytes(path);
    TextScanner scanner(bytes, path, TextSyntax{true, true}, progress);
    Mesh mesh;
    std::vector<uint32_t> corners;
    // Faces may name vertices defined further down; the largest index is checked at the end.
    uint32_t largest_index = 0;
    size_t largest_index_line = 0;
    std::string_view token;
    while (!scanner.at_end()) {
        if (scanner.token_in_line(token)) {
            if (token == "v") {
                Vec3 position;
                for (double& c : position)
                    c = scanner.parse_double(scanner.expect_token_in_line("a vertex coordinate"), "vertex coordinate");
                mesh.vertices.push_back(position);
            } else if (token == "f") {
                corners.clear();
                while (scanner.token_in_line(token)) corners.push_back(corner_index(scanner, token, mesh.vertices.size()));
                if (corners.size() < 3) scanner.fail("a face with " + std::to_string(corners.size()) + " vertices");
                for (uint32_t corner : corners)
                    if (corner >= largest_index) {
                        largest_index = corner;
                        largest_index_line = scanner.line();
                    }
                add_polygon_fan(mesh, corners.data(), corners.size());
            }
        }
        scanner.next_line();
    }
    if (!mesh.triangles.empty() && largest_index >= mesh.vertices.size())
        throw Error(FABVDB_ERR_BAD_INPUT, path + ": line " + std::to_string(largest_index_line) +
                                              ": face vertex index " + std::to_string(largest_index + 1) +
                                              " is out of range (the file has " +
                                              std::to_string(mesh.vertices.size()) + " vertices)");
    return mesh;
}

void write_obj(const Mesh& mesh, const std::string& path) {
    write_file_atomically(path, [&mesh](std::ostream& out) {
        out << "# written by fabvdb: " << mesh.vertices.size() << " vertices, " << mesh.triangles.size()
            << " triangles\n";
        for (const Vec3& p : mesh.vertices) {
            out << 'v';
            for (double c : p) {
                out << ' ';
                write_double(out, c);
            }
            out << '\n';
        }
        for (const Triangle& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    });
}

}  // namespace fabvdb::io
