//! A heat map as a coloured PLY (see heatmap_ply.h).
#include "powder/heatmap_ply.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>

#include "core/atomic_output.h"
#include "core/colour_map.h"
#include "core/error.h"

namespace fabvdb::powder {

namespace {

template <class T>
void put(std::string& out, T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    out.append(bytes, sizeof(T));  // the project targets little-endian hosts
}

}  // namespace

std::vector<double> vertex_values(const Mesh& surface, const CavityPatches& patches,
                                  const std::vector<double>& per_patch) {
    if (per_patch.size() != patches.size() || patches.patch_of_triangle.size() != surface.triangles.size())
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the heat map's values do not match its patches");
    std::vector<double> sum(surface.vertices.size(), 0.0), weight(surface.vertices.size(), 0.0);
    for (size_t t = 0; t < surface.triangles.size(); ++t) {
        const double area = triangle_area(surface, surface.triangles[t]) + 1e-12;
        const double value = per_patch[patches.patch_of_triangle[t]];
        for (uint32_t corner : surface.triangles[t]) {
            sum[corner] += area * value;
            weight[corner] += area;
        }
    }
    for (size_t i = 0; i < sum.size(); ++i) sum[i] = weight[i] > 0 ? sum[i] / weight[i] : 0.0;
    return sum;
}

std::vector<std::array<uint8_t, 3>> heatmap_colours(const std::vector<double>& vertex_value, double low, double high) {
    const double span = high > low ? high - low : 1.0;
    std::vector<std::array<uint8_t, 3>> colours(vertex_value.size());
    for (size_t i = 0; i < vertex_value.size(); ++i) colours[i] = viridis((vertex_value[i] - low) / span);
    return colours;
}

void write_heatmap_ply(const Mesh& surface, const std::vector<double>& vertex_value, double low, double high,
                       const std::string& description, const std::string& path, bool reverse_faces) {
    if (vertex_value.size() != surface.vertices.size())
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the heat map's values do not match its vertices");
    const std::vector<std::array<uint8_t, 3>> colours = heatmap_colours(vertex_value, low, high);
    std::string out = "ply\nformat binary_little_endian 1.0\ncomment fabvdb heat map: " + description + "\n";
    out += "comment colours: viridis from " + std::to_string(low) + " to " + std::to_string(high) + "\n";
    out += "element vertex " + std::to_string(surface.vertices.size()) + "\n";
    out += "property float x\nproperty float y\nproperty float z\n";
    out += "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty float quality\n";
    out += "element face " + std::to_string(surface.triangles.size()) + "\n";
    out += "property list uchar int vertex_indices\nend_header\n";
    for (size_t i = 0; i < surface.vertices.size(); ++i) {
        for (int k = 0; k < 3; ++k) put(out, float(surface.vertices[i][k]));
        for (uint8_t channel : colours[i]) put(out, channel);
        put(out, float(vertex_value[i]));
    }
    for (const Triangle& t : surface.triangles) {
        put(out, uint8_t(3));
        put(out, int32_t(t[0]));
        put(out, int32_t(t[reverse_faces ? 2 : 1]));
        put(out, int32_t(t[reverse_faces ? 1 : 2]));
    }
    AtomicOutput output(path);
    {
        std::ofstream file(output.temp_path(), std::ios::binary);
        file.write(out.data(), std::streamsize(out.size()));
        if (!file) throw Error(FABVDB_ERR_IO, path + ": cannot write the heat map");
    }
    output.commit();
}

}  // namespace fabvdb::powder
