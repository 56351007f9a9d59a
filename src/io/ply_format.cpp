//! PLY reader (header, then one generic element walk over an ASCII or binary
//! value source) and binary little-endian writer.
#include "io/ply_format.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "core/error.h"
#include "io/binary_io.h"
#include "io/input_file.h"
#include "io/output_file.h"
#include "io/polygon_fan.h"
#include "io/text_scanner.h"

namespace fabvdb::io {

namespace {

enum class ScalarType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };
enum class Encoding { ascii, binary_little_endian, binary_big_endian };

struct Property {
    std::string name;
    ScalarType type = ScalarType::float32;
    bool is_list = false;
    ScalarType count_type = ScalarType::uint8;
};

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> properties;
};

struct Header {
    Encoding encoding = Encoding::ascii;
    std::vector<Element> elements;
    size_t data_start = 0;
};

constexpr size_t items_per_progress_update = 1 << 15;

std::optional<ScalarType> scalar_type_named(std::string_view name) {
    static const std::pair<std::string_view, ScalarType> names[] = {
        {"char", ScalarType::int8},     {"int8", ScalarType::int8},       {"uchar", ScalarType::uint8},
        {"uint8", ScalarType::uint8},   {"short", ScalarType::int16},     {"int16", ScalarType::int16},
        {"ushort", ScalarType::uint16}, {"uint16", ScalarType::uint16},   {"int", ScalarType::int32},
        {"int32", ScalarType::int32},   {"uint", ScalarType::uint32},     {"uint32", ScalarType::uint32},
        {"float", ScalarType::float32}, {"float32", ScalarType::float32}, {"double", ScalarType::float64},
        {"float64", ScalarType::float64}};
    for (const auto& [text, type] : names)
        if (text == name) return type;
    return std::nullopt;
}

size_t scalar_size(ScalarType type) {
    switch (type) {
        case ScalarType::int8:
        case ScalarType::uint8: return 1;
        case ScalarType::int16:
        case ScalarType::uint16: return 2;
        case ScalarType::int32:
        case ScalarType::uint32:
        case ScalarType::float32: return 4;
        case ScalarType::float64: return 8;
    }
    return 8;
}

bool is_integer_type(ScalarType type) { return type != ScalarType::float32 && type != ScalarType::float64; }

Header read_header(const std::string& bytes, const std::string& path, Progress& progress) {
    TextScanner scanner(bytes, path, TextSyntax{}, progress);
    Header header;
    std::string_view token;
    if (!scanner.token_in_line(token) || token != "ply") scanner.fail("not a PLY file (no 'ply' magic line)");
    scanner.next_line();
    bool has_format = false;
    while (true) {
        if (scanner.at_end()) scanner.fail("the header has no 'end_header' line");
        if (!scanner.token_in_line(token)) {
            scanner.next_line();
            continue;
        }
        if (token == "end_header") {
            scanner.next_line();
            break;
        }
        if (token == "comment" || token == "obj_info") {
        } else if (token == "format") {
            const std::string_view encoding = scanner.expect_token_in_line("the encoding");
            if (encoding == "ascii") header.encoding = Encoding::ascii;
            else if (encoding == "binary_little_endian") header.encoding = Encoding::binary_little_endian;
            else if (encoding == "binary_big_endian") header.encoding = Encoding::binary_big_endian;
            else scanner.fail("unknown PLY encoding '" + std::string(encoding.substr(0, 40)) + "'");
            has_format = true;
        } else if (token == "element") {
            Element element;
            element.name = std::string(scanner.expect_token_in_line("the element name"));
            const int64_t count = scanner.parse_integer(scanner.expect_token_in_line("the element count"), "element count");
            if (count < 0) scanner.fail("negative count for element '" + element.name + "'");
            element.count = static_cast<uint64_t>(count);
            header.elements.push_back(std::move(element));
        } else if (token == "property") {
            if (header.elements.empty()) scanner.fail("a property before any element");
            Property property;
            std::string_view type_name = scanner.expect_token_in_line("the property type");
            if (type_name == "list") {
                property.is_list = true;
                const std::string_view count_name = scanner.expect_token_in_line("the list count type");
                const auto count_type = scalar_type_named(count_name);
                if (!count_type || !is_integer_type(*count_type))
                    scanner.fail("invalid list count type '" + std::string(count_name.substr(0, 40)) + "'");
                property.count_type = *count_type;
                type_name = scanner.expect_token_in_line("the list item type");
            }
            const auto type = scalar_type_named(type_name);
            if (!type) scanner.fail("unknown property type '" + std::string(type_name.substr(0, 40)) + "'");
            property.type = *type;
            property.name = std::string(scanner.expect_token_in_line("the property name"));
            header.elements.back().properties.push_back(std::move(property));
        } else {
            scanner.fail("unknown header line '" + std::string(token.substr(0, 40)) + "'");
        }
        scanner.next_line();
    }
    if (!has_format) scanner.fail("the header has no 'format' line");
    header.data_start = scanner.position();
    return header;
}

//! Values of the binary encodings.
class BinarySource {
public:
    BinarySource(std::string_view body, const std::string& path, bool big_endian) : reader_(body, path, big_endian) {}

    double value(ScalarType type) {
        switch (type) {
            case ScalarType::int8: return reader_.read<int8_t>("a property value");
            case ScalarType::uint8: return reader_.read<uint8_t>("a property value");
            case ScalarType::int16: return reader_.read<int16_t>("a property value");
            case ScalarType::uint16: return reader_.read<uint16_t>("a property value");
            case ScalarType::int32: return reader_.read<int32_t>("a property value");
            case ScalarType::uint32: return reader_.read<uint32_t>("a property value");
            case ScalarType::float32: return reader_.read<float>("a property value");
            case ScalarType::float64: return reader_.read<double>("a property value");
        }
        return 0.0;
    }
    void skip(ScalarType type, uint64_t count) {
        if (count > reader_.remaining() / scalar_size(type)) reader_.fail_truncated("a list");
        reader_.skip(static_cast<size_t>(count) * scalar_size(type), "a list");
    }
    //! The fewest bytes an item of `element` can take.
    static size_t minimum_item_bytes(const Element& element) {
        size_t bytes = 0;
        for (const Property& p : element.properties) bytes += scalar_size(p.is_list ? p.count_type : p.type);
        return bytes;
    }
    size_t remaining() const { return reader_.remaining(); }
    double fraction() const { return static_cast<double>(reader_.position()) / std::max<size_t>(reader_.size(), 1); }

private:
    BinaryReader reader_;
};

//! Values of the ASCII encoding: whitespace-separated numbers.
class AsciiSource {
public:
    AsciiSource(std::string_view body, const std::string& path, Progress& progress)
        : scanner_(body, path, TextSyntax{}, progress), size_(body.size()) {}

    double value(ScalarType) { return scanner_.parse_double(scanner_.expect_token("a property value"), "property value"); }
    void skip(ScalarType type, uint64_t count) {
        for (uint64_t i = 0; i < count; ++i) value(type);
    }
    static size_t minimum_item_bytes(const Element& element) { return 2 * element.properties.size(); }
    size_t remaining() const { return size_ - scanner_.position(); }
    double fraction() const { return static_cast<double>(scanner_.position()) / std::max<size_t>(size_, 1); }

private:
    TextScanner scanner_;
    size_t size_;
};

//! Walks the elements of the body, collecting positions, faces and strips.
class ElementReader {
public:
    ElementReader(const std::string& path, Progress& progress) : path_(path), progress_(progress) {}

    template <typename Source>
    Mesh read(const std::vector<Element>& elements, Source& source) {
        for (const Element& element : elements) {
            if (element.properties.empty()) continue;
            if (element.name == "vertex") read_vertices(element, source);
            else if (element.name == "face") read_polygons(element, source, false);
            else if (element.name == "tristrips") read_polygons(element, source, true);
            else skip_items(element, source);
        }
        return std::move(mesh_);
    }

private:
    [[noreturn]] void fail(const Element& element, uint64_t item, const std::string& defect) const {
        throw Error(FABVDB_ERR_BAD_INPUT,
                    path_ + ": " + element.name + " " + std::to_string(item) + ": " + defect);
    }

    template <typename Source>
    void tick(uint64_t item, Source& source) {
        if (item % items_per_progress_update == 0) progress_.update(source.fraction());
    }

    template <typename Source>
    uint64_t list_count(const Element& element, uint64_t item, const Property& property, Source& source) {
        const double count = source.value(property.count_type);
        if (!(count >= 0) || count != std::floor(count) || count > 4294967295.0)
            fail(element, item, "invalid list length in '" + property.name + "'");
        return static_cast<uint64_t>(count);
    }

    template <typename Source>
    void skip_property(const Element& element, uint64_t item, const Property& property, Source& source) {
        if (property.is_list) source.skip(property.type, list_count(element, item, property, source));
        else source.value(property.type);
    }

    template <typename Source>
    void skip_items(const Element& element, Source& source) {
        for (uint64_t item = 0; item < element.count; ++item) {
            for (const Property& property : element.properties) skip_property(element, item, property, source);
            tick(item, source);
        }
    }

    //! Positions from the scalar x, y, z properties; other properties are skipped.
    template <typename Source>
    void read_vertices(const Element& element, Source& source) {
        int coordinate_of[3] = {-1, -1, -1};
        std::vector<int> axis(element.properties.size(), -1);
        for (size_t i = 0; i < element.properties.size(); ++i) {
            const Property& p = element.properties[i];
            for (int k = 0; k < 3; ++k)
                if (p.name == std::string(1, static_cast<char>('x' + k)) && !p.is_list) {
                    axis[i] = k;
                    coordinate_of[k] = static_cast<int>(i);
                }
        }
        for (int k = 0; k < 3; ++k)
            if (coordinate_of[k] < 0)
                throw Error(FABVDB_ERR_BAD_INPUT, path_ + ": the vertex element has no scalar '" +
                                                      std::string(1, static_cast<char>('x' + k)) + "' property");
        if (mesh_.vertices.size() + element.count > UINT32_MAX)
            throw Error(FABVDB_ERR_BAD_INPUT, path_ + ": too many vertices (" + std::to_string(element.count) + ")");
        mesh_.vertices.reserve(mesh_.vertices.size() +
                               std::min<uint64_t>(element.count, source.remaining() /
                                                                     std::max<size_t>(Source::minimum_item_bytes(element), 1)));
        for (uint64_t item = 0; item < element.count; ++item) {
            Vec3 position{0, 0, 0};
            for (size_t i = 0; i < element.properties.size(); ++i) {
                if (axis[i] >= 0) position[axis[i]] = source.value(element.properties[i].type);
                else skip_property(element, item, element.properties[i], source);
            }
            mesh_.vertices.push_back(position);
            tick(item, source);
        }
    }

    //! Faces (fan-triangulated) or triangle strips from the element's
    //! `vertex_indices` (or `vertex_index`) list; other properties are skipped.
    template <typename Source>
    void read_polygons(const Element& element, Source& source, bool strips) {
        int list = -1;
        for (size_t i = 0; i < element.properties.size() && list < 0; ++i)
            for (const char* name : {"vertex_indices", "vertex_index"})
                if (element.properties[i].is_list && element.properties[i].name == name) list = static_cast<int>(i);
        if (list < 0)
            throw Error(FABVDB_ERR_BAD_INPUT, path_ + ": the " + element.name + " element has no vertex_indices list");
        std::vector<int64_t> corners;
        for (uint64_t item = 0; item < element.count; ++item) {
            for (size_t i = 0; i < element.properties.size(); ++i) {
                const Property& property = element.properties[i];
                if (static_cast<int>(i) != list) {
                    skip_property(element, item, property, source);
                    continue;
                }
                const uint64_t count = list_count(element, item, property, source);
                if (count > source.remaining()) fail(element, item, "list longer than the rest of the file");
                corners.clear();
                for (uint64_t k = 0; k < count; ++k) {
                    const double index = source.value(property.type);
                    const bool restart = strips && (index == -1.0 || index == 4294967295.0);
                    if (!restart && (!(index >= 0) || index != std::floor(index) || index > 4294967294.0))
                        fail(element, item, "invalid vertex index " + std::to_string(index));
                    corners.push_back(static_cast<int64_t>(index));
                }
                if (strips) add_strips(corners);
                else add_polygon(element, item, corners);
            }
            tick(item, source);
        }
    }

    void add_polygon(const Element& element, uint64_t item, const std::vector<int64_t>& corners) {
        if (corners.size() < 3) fail(element, item, "a face with " + std::to_string(corners.size()) + " corners");
        polygon_.assign(corners.begin(), corners.end());
        add_polygon_fan(mesh_, polygon_.data(), polygon_.size());
    }

    //! Strips separated by -1; triangle i of a strip is (s[i], s[i+1], s[i+2]),
    //! with the first two swapped for odd i; triangles with a repeated corner
    //! (the joints between strips) are dropped.
    void add_strips(const std::vector<int64_t>& indices) {
        size_t start = 0;
        for (size_t i = 0; i < indices.size(); ++i) {
            if (indices[i] < 0) {
                start = i + 1;
                continue;
            }
            if (i < start + 2) continue;
            const auto a = static_cast<uint32_t>(indices[i - 2]);
            const auto b = static_cast<uint32_t>(indices[i - 1]);
            const auto c = static_cast<uint32_t>(indices[i]);
            if (a == b || b == c || a == c) continue;
            if ((i - start) % 2 == 0) mesh_.triangles.push_back({a, b, c});
            else mesh_.triangles.push_back({b, a, c});
        }
    }

    const std::string& path_;
    Progress& progress_;
    Mesh mesh_;
    std::vector<uint32_t> polygon_;
};

}  // namespace

Mesh read_ply(const std::string& path, Progress& progress) {
    const std::string bytes = read_file_bytes(path);
    const Header header = read_header(bytes, path, progress);
    const std::string_view body = std::string_view(bytes).substr(header.data_start);
    ElementReader reader(path, progress);
    if (header.encoding == Encoding::ascii) {
        AsciiSource source(body, path, progress);
        return reader.read(header.elements, source);
    }
    BinarySource source(body, path, header.encoding == Encoding::binary_big_endian);
    return reader.read(header.elements, source);
}

void write_ply(const Mesh& mesh, const std::string& path) {
    write_file_atomically(path, [&mesh](std::ostream& out) {
        out << "ply\nformat binary_little_endian 1.0\ncomment written by fabvdb\n"
            << "element vertex " << mesh.vertices.size() << "\nproperty double x\nproperty double y\nproperty double z\n"
            << "element face " << mesh.triangles.size() << "\nproperty list uchar uint vertex_indices\nend_header\n";
        for (const Vec3& p : mesh.vertices)
            for (double c : p) write_little_endian<double>(out, c);
        for (const Triangle& t : mesh.triangles) {
            write_little_endian<uint8_t>(out, 3);
            for (uint32_t corner : t) write_little_endian<uint32_t>(out, corner);
        }
    });
}

}  // namespace fabvdb::io
