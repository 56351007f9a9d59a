//! STL reader (binary/ASCII sniffing, exact corner welding) and binary writer.
#include "io/stl_format.h"

#include <cctype>
#include <cmath>
#include <cstring>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/error.h"
#include "io/binary_io.h"
#include "io/input_file.h"
#include "io/output_file.h"
#include "io/polygon_fan.h"
#include "io/text_scanner.h"

namespace fabvdb::io {

namespace {

constexpr size_t header_bytes = 80;
constexpr size_t facet_bytes = 50;
constexpr size_t triangles_per_progress_update = 1 << 16;

//! Joins corners whose three coordinates have identical bit patterns.
class CornerWelder {
public:
    explicit CornerWelder(Mesh& mesh) : mesh_(mesh) {}

    uint32_t index_of(const Vec3& position) {
        Key key;
        std::memcpy(key.bits, position.data(), sizeof key.bits);
        const auto [it, inserted] = indices_.try_emplace(key, static_cast<uint32_t>(mesh_.vertices.size()));
        if (inserted) mesh_.vertices.push_back(position);
        return it->second;
    }

    void reserve(size_t corners) { indices_.reserve(corners); }

private:
    struct Key {
        uint64_t bits[3];
        bool operator==(const Key& other) const {
            return bits[0] == other.bits[0] && bits[1] == other.bits[1] && bits[2] == other.bits[2];
        }
    };
    struct KeyHash {
        size_t operator()(const Key& key) const {
            uint64_t h = key.bits[0] * 0x9E3779B97F4A7C15ull;
            h = (h ^ (h >> 29) ^ key.bits[1]) * 0xBF58476D1CE4E5B9ull;
            h = (h ^ (h >> 31) ^ key.bits[2]) * 0x94D049BB133111EBull;
            return static_cast<size_t>(h ^ (h >> 32));
        }
    };

    Mesh& mesh_;
    std::unordered_map<Key, uint32_t, KeyHash> indices_;
};

bool starts_with_solid(std::string_view bytes) {
    size_t i = 0;
    while (i < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[i]))) ++i;
    static constexpr std::string_view solid = "solid";
    if (bytes.size() - i < solid.size()) return false;
    for (size_t k = 0; k < solid.size(); ++k)
        if (std::tolower(static_cast<unsigned char>(bytes[i + k])) != solid[k]) return false;
    return true;
}

bool keyword_is(std::string_view token, std::string_view keyword) {
    if (token.size() != keyword.size()) return false;
    for (size_t k = 0; k < token.size(); ++k)
        if (std::tolower(static_cast<unsigned char>(token[k])) != keyword[k]) return false;
    return true;
}

Mesh read_binary(const std::string& bytes, const std::string& path, Progress& progress) {
    BinaryReader reader(bytes, path, /*big_endian=*/false);
    reader.skip(header_bytes, "the 80-byte header");
    uint64_t count = reader.read<uint32_t>("the triangle count");
    // A count of 0 before whole facets: the writer never filled it in.
    const uint64_t body = bytes.size() > header_bytes + 4 ? bytes.size() - (header_bytes + 4) : 0;
    if (count == 0 && body > 0 && body % facet_bytes == 0) count = body / facet_bytes;
    const uint64_t needed = header_bytes + 4 + uint64_t{facet_bytes} * count;
    if (needed > bytes.size())
        throw Error(FABVDB_ERR_BAD_INPUT, path + ": truncated binary STL: the header announces " +
                                              std::to_string(count) + " triangles (" + std::to_string(needed) +
                                              " bytes) but the file has " + std::to_string(bytes.size()) + " bytes");
    Mesh mesh;
    mesh.triangles.reserve(count);
    CornerWelder welder(mesh);
    welder.reserve(count / 2 + 3);
    for (uint64_t t = 0; t < count; ++t) {
        reader.skip(12, "a facet normal");
        Triangle triangle;
        for (uint32_t& corner : triangle) {
            Vec3 position;
            for (double& c : position) c = reader.read<float>("a vertex coordinate");
            corner = welder.index_of(position);
        }
        reader.skip(2, "a facet attribute");
        mesh.triangles.push_back(triangle);
        if (t % triangles_per_progress_update == 0) progress.update(static_cast<double>(reader.position()) / bytes.size());
    }
    return mesh;
}

Mesh read_ascii(const std::string& bytes, const std::string& path, Progress& progress) {
    TextScanner scanner(bytes, path, TextSyntax{}, progress);
    Mesh mesh;
    CornerWelder welder(mesh);
    std::vector<uint32_t> loop;
    auto expect_keyword = [&scanner](std::string_view keyword) {
        const std::string_view token = scanner.expect_token(std::string(keyword).c_str());
        if (!keyword_is(token, keyword))
            scanner.fail("expected '" + std::string(keyword) + "' but found '" + std::string(token.substr(0, 40)) + "'");
    };
    std::string_view token;
    while (scanner.next_token(token)) {
        if (!keyword_is(token, "solid"))
            scanner.fail("expected 'solid' but found '" + std::string(token.substr(0, 40)) + "'");
        scanner.next_line();  // the solid's name
        while (true) {
            token = scanner.expect_token("'facet' or 'endsolid'");
            if (keyword_is(token, "endsolid")) {
                scanner.next_line();
                break;
            }
            if (!keyword_is(token, "facet"))
                scanner.fail("expected 'facet' or 'endsolid' but found '" + std::string(token.substr(0, 40)) + "'");
            expect_keyword("normal");
            for (int k = 0; k < 3; ++k) scanner.parse_double(scanner.expect_token("a normal component"), "normal component");
            expect_keyword("outer");
            expect_keyword("loop");
            loop.clear();
            while (true) {
                token = scanner.expect_token("'vertex' or 'endloop'");
                if (keyword_is(token, "endloop")) break;
                if (!keyword_is(token, "vertex"))
                    scanner.fail("expected 'vertex' or 'endloop' but found '" + std::string(token.substr(0, 40)) + "'");
                Vec3 position;
                for (double& c : position) c = scanner.parse_double(scanner.expect_token("a coordinate"), "coordinate");
                loop.push_back(welder.index_of(position));
            }
            if (loop.size() < 3) scanner.fail("a facet loop with " + std::to_string(loop.size()) + " vertices");
            add_polygon_fan(mesh, loop.data(), loop.size());
            expect_keyword("endfacet");
        }
    }
    return mesh;
}

}  // namespace

Mesh read_stl(const std::string& path, Progress& progress) {
    const std::string bytes = read_file_bytes(path);
    if (bytes.size() >= header_bytes + 4) {
        BinaryReader reader(bytes, path, false);
        reader.skip(header_bytes, "the header");
        const uint64_t count = reader.read<uint32_t>("the triangle count");
        if (header_bytes + 4 + facet_bytes * count == bytes.size()) return read_binary(bytes, path, progress);
    }
    if (starts_with_solid(bytes) && std::memchr(bytes.data(), '\0', bytes.size()) == nullptr)
        return read_ascii(bytes, path, progress);
    if (bytes.size() < header_bytes + 4)
        throw Error(FABVDB_ERR_BAD_INPUT, path + ": neither an ASCII STL nor a binary STL (only " +
                                              std::to_string(bytes.size()) + " bytes, shorter than the 84-byte header)");
    return read_binary(bytes, path, progress);
}

void write_stl(const Mesh& mesh, const std::string& path) {
    if (mesh.triangles.size() > UINT32_MAX)
        throw Error(FABVDB_ERR_BAD_INPUT, path + ": too many triangles for a binary STL");
    write_file_atomically(path, [&mesh](std::ostream& out) {
        std::string header = "binary STL written by fabvdb";
        header.resize(header_bytes, ' ');
        out.write(header.data(), static_cast<std::streamsize>(header.size()));
        write_little_endian<uint32_t>(out, static_cast<uint32_t>(mesh.triangles.size()));
        char facet[facet_bytes];
        for (const Triangle& t : mesh.triangles) {
            const Vec3& a = mesh.vertices[t[0]];
            const Vec3& b = mesh.vertices[t[1]];
            const Vec3& c = mesh.vertices[t[2]];
            const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
            const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
            double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
            const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (double& x : n) x = length > 0 ? x / length : 0.0;
            char* at = facet;
            for (double x : n) at = store_little_endian<float>(at, static_cast<float>(x));
            for (uint32_t corner : t)
                for (double x : mesh.vertices[corner]) at = store_little_endian<float>(at, static_cast<float>(x));
            store_little_endian<uint16_t>(at, 0);
            out.write(facet, facet_bytes);
        }
    });
}

}  // namespace fabvdb::io
