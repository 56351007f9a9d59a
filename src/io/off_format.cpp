//! OFF reader (header variants, comments, face colours) and writer.
#include "io/off_format.h"

#include <algorithm>
#include <vector>

#include "io/input_file.h"
#include "io/output_file.h"
#include "io/polygon_fan.h"
#include "io/text_scanner.h"

namespace fabvdb::io {

namespace {

bool is_off_keyword(std::string_view token) {
    for (std::string_view prefix : {"", "C", "N", "CN", "NC", "ST", "STC", "STN", "STCN", "STNC"})
        if (token.size() == prefix.size() + 3 && token.substr(0, prefix.size()) == prefix &&
            token.substr(prefix.size()) == "OFF")
            return true;
    return false;
}

}  // namespace

Mesh read_off(const std::string& path, Progress& progress) {
    const std::string bytes = read_file_bytes(path);
    TextScanner scanner(bytes, path, TextSyntax{true, false}, progress);
    if (!scanner.skip_blank_lines()) scanner.fail("no OFF header");
    const std::string_view keyword = scanner.expect_token_in_line("the OFF keyword");
    if (!is_off_keyword(keyword))
        scanner.fail("expected the 'OFF' keyword but found '" + std::string(keyword.substr(0, 40)) + "'");
    std::string_view token;
    if (!scanner.token_in_line(token)) {
        scanner.next_line();
        if (!scanner.skip_blank_lines()) scanner.fail("file ends before the vertex and face counts");
        token = scanner.expect_token_in_line("the vertex count");
    }
    const int64_t vertex_count = scanner.parse_integer(token, "vertex count");
    const int64_t face_count = scanner.parse_integer(scanner.expect_token_in_line("the face count"), "face count");
    if (vertex_count < 0 || vertex_count > int64_t{UINT32_MAX} || face_count < 0)
        scanner.fail("invalid counts " + std::to_string(vertex_count) + " vertices, " + std::to_string(face_count) +
                     " faces");
    scanner.next_line();

    Mesh mesh;
    // Each vertex takes at least 6 bytes ("0 0 0\n"), each face at least 8: never reserve past the file.
    const size_t remaining = bytes.size() - scanner.position();
    mesh.vertices.reserve(std::min<size_t>(static_cast<size_t>(vertex_count), remaining / 6));
    mesh.triangles.reserve(std::min<size_t>(static_cast<size_t>(face_count), remaining / 8));
    for (int64_t v = 0; v < vertex_count; ++v) {
        if (!scanner.skip_blank_lines())
            scanner.fail("file ends after " + std::to_string(v) + " of " + std::to_string(vertex_count) + " vertices");
        Vec3 position;
        for (double& c : position)
            c = scanner.parse_double(scanner.expect_token_in_line("a vertex coordinate"), "vertex coordinate");
        mesh.vertices.push_back(position);
        scanner.next_line();
    }
    std::vector<uint32_t> corners;
    for (int64_t f = 0; f < face_count; ++f) {
        if (!scanner.skip_blank_lines())
            scanner.fail("file ends after " + std::to_string(f) + " of " + std::to_string(face_count) + " faces");
        const int64_t count = scanner.parse_integer(scanner.expect_token_in_line("a face's corner count"),
                                                    "face corner count");
        if (count < 3) scanner.fail("a face with " + std::to_string(count) + " corners");
        corners.clear();
        for (int64_t k = 0; k < count; ++k) {
            const int64_t index = scanner.parse_integer(scanner.expect_token("a face corner"), "face corner");
            if (index < 0 || index >= vertex_count)
                scanner.fail("face corner " + std::to_string(index) + " is out of range (" +
                             std::to_string(vertex_count) + " vertices)");
            corners.push_back(static_cast<uint32_t>(index));
        }
        add_polygon_fan(mesh, corners.data(), corners.size());
        scanner.next_line();
    }
    return mesh;
}

void write_off(const Mesh& mesh, const std::string& path) {
    write_file_atomically(path, [&mesh](std::ostream& out) {
        out << "OFF\n" << mesh.vertices.size() << ' ' << mesh.triangles.size() << " 0\n";
        for (const Vec3& p : mesh.vertices) {
            for (int k = 0; k < 3; ++k) {
                if (k) out << ' ';
                write_double(out, p[k]);
            }
            out << '\n';
        }
        for (const Triangle& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    });
}

}  // namespace fabvdb::io
