//! decomposition_io: JSON document, colour PLY files (binary little endian),
//! polylines chained from edge sets, folder swapped in by rename.
#include "surface/decomposition_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>


#include "core/atomic_output.h"
#include "core/error.h"
#include "surface/moldability_energy.h"
#include "surface/nearest_outer_triangles.h"
#include "core/vec3_ops.h"

namespace fabvdb::surface {

namespace {

using Edge = std::pair<uint32_t, uint32_t>;

//! Chains undirected edges into polylines (open chains first, from vertices of
//! degree ≠ 2, then closed loops, which repeat their first vertex).
std::vector<std::vector<uint32_t>> chain_edges(const std::vector<Edge>& edges) {
    std::map<uint32_t, std::vector<size_t>> at;
    for (size_t e = 0; e < edges.size(); ++e) {
        at[edges[e].first].push_back(e);
        at[edges[e].second].push_back(e);
    }
    std::vector<char> used(edges.size(), 0);
    std::vector<std::vector<uint32_t>> chains;
    const auto walk = [&](uint32_t start) {
        std::vector<uint32_t> chain{start};
        uint32_t v = start;
        for (;;) {
            size_t next = edges.size();
            for (size_t e : at[v])
                if (!used[e]) {
                    next = e;
                    break;
                }
            if (next == edges.size()) break;
            used[next] = 1;
            v = edges[next].first == v ? edges[next].second : edges[next].first;
            chain.push_back(v);
        }
        chains.push_back(std::move(chain));
    };
    for (const auto& [v, list] : at)
        if (list.size() != 2)
            while (std::any_of(list.begin(), list.end(), [&](size_t e) { return !used[e]; })) walk(v);
    for (size_t e = 0; e < edges.size(); ++e)
        if (!used[e]) walk(edges[e].first);
    return chains;
}

std::vector<std::vector<Vec3>> polylines(const Shell& shell, const std::vector<Edge>& edges) {
    std::vector<std::vector<Vec3>> lines;
    for (const auto& chain : chain_edges(edges)) {
        std::vector<Vec3> line;
        for (uint32_t id : chain) line.push_back(corner_position(shell, id));
        lines.push_back(std::move(line));
    }
    return lines;
}

std::array<uint8_t, 3> part_colour(size_t part) {
    // Golden-angle hues: neighbouring ids get distinct colours.
    const double hue = std::fmod(double(part) * 137.508, 360.0) / 60.0;
    const double x = 1.0 - std::abs(std::fmod(hue, 2.0) - 1.0);
    double r = 0, g = 0, b = 0;
    switch (int(hue)) {
        case 0: r = 1, g = x; break;
        case 1: r = x, g = 1; break;
        case 2: g = 1, b = x; break;
        case 3: g = x, b = 1; break;
        case 4: r = x, b = 1; break;
        default: r = 1, b = x; break;
    }
    const auto level = [](double c) { return uint8_t(std::lround(60 + 195 * c)); };
    return {level(r), level(g), level(b)};
}

//! Blue (0) to red (1) through green.
std::array<uint8_t, 3> heat_colour(double value) {
    value = std::clamp(value, 0.0, 1.0);
    const double r = std::clamp(2.0 * value - 0.5, 0.0, 1.0);
    const double g = 1.0 - std::abs(2.0 * value - 1.0);
    const double b = std::clamp(1.5 - 2.0 * value, 0.0, 1.0);
    return {uint8_t(std::lround(255 * r)), uint8_t(std::lround(255 * g)), uint8_t(std::lround(255 * b))};
}

void write_colour_ply(const std::string& path, const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                      const std::vector<std::array<uint8_t, 3>>& colours, const std::vector<float>* values) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw Error(FABVDB_ERR_IO, path + ": cannot write");
    out << "ply\nformat binary_little_endian 1.0\ncomment written by fabvdb decompose\n"
        << "element vertex " << vertices.size() << "\nproperty float x\nproperty float y\nproperty float z\n"
        << "element face " << triangles.size() << "\nproperty list uchar int vertex_indices\n"
        << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
        << (values ? "property float deformation\n" : "") << "end_header\n";
    for (const Vec3& p : vertices) {
        const float xyz[3] = {float(p[0]), float(p[1]), float(p[2])};
        out.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
    }
    for (size_t t = 0; t < triangles.size(); ++t) {
        const uint8_t three = 3;
        const int32_t index[3] = {int32_t(triangles[t][0]), int32_t(triangles[t][1]), int32_t(triangles[t][2])};
        out.write(reinterpret_cast<const char*>(&three), 1);
        out.write(reinterpret_cast<const char*>(index), sizeof index);
        out.write(reinterpret_cast<const char*>(colours[t].data()), 3);
        if (values) out.write(reinterpret_cast<const char*>(&(*values)[t]), sizeof(float));
    }
    if (!out) throw Error(FABVDB_ERR_IO, path + ": write failed");
}

void write_parts_ply(const std::string& path, const Mesh& input, const Shell& shell,
                     const Decomposition& decomposition) {
    const std::vector<uint32_t> nearest = nearest_outer_triangles(input, shell.outer);
    const std::vector<char> upper = outer_upper(shell, decomposition);
    std::vector<std::array<uint8_t, 3>> colours(input.triangles.size());
    for (size_t t = 0; t < input.triangles.size(); ++t) {
        auto colour = part_colour(size_t(decomposition.part_of_triangle[nearest[t]]));
        if (!upper[nearest[t]])
            for (auto& channel : colour) channel = uint8_t(channel * 0.55);
        colours[t] = colour;
    }
    write_colour_ply(path, input.vertices, input.triangles, colours, nullptr);
}

void write_deformation_ply(const std::string& path, const Shell& shell, const MoldabilityTerms& terms,
                           const Decomposition& decomposition, const DecompositionOptions& options) {
    const std::vector<float> density = deformation_density(shell, terms, decomposition, options);
    const double highest = density.empty() ? 0.0 : double(*std::max_element(density.begin(), density.end()));
    std::vector<std::array<uint8_t, 3>> colours(density.size());
    for (size_t t = 0; t < density.size(); ++t) colours[t] = heat_colour(highest > 0 ? density[t] / highest : 0.0);
    write_colour_ply(path, shell.outer.vertices, shell.outer.triangles, colours, &density);
}

}  // namespace

std::vector<char> outer_upper(const Shell& shell, const Decomposition& decomposition) {
    std::vector<char> upper(shell.triangle_count(), 1);
    for (const PartMolding& part : decomposition.parts)
        for (size_t i = 0; i < part.surface.size(); ++i)
            if (part.surface.kind[i] == PartSurface::outer) upper[part.surface.source[i]] = part.upper[i];
    return upper;
}

std::vector<float> deformation_density(const Shell& shell, const MoldabilityTerms& terms,
                                       const Decomposition& decomposition, const DecompositionOptions& options) {
    std::vector<double> share(shell.triangle_count(), 0.0);
    for (const PartMolding& part : decomposition.parts)
        moldability_energy(terms, part.surface, part.upper, part.direction, options.weights, &share);
    std::vector<float> density(shell.triangle_count());
    for (size_t t = 0; t < share.size(); ++t) density[t] = float(share[t] / std::max(shell.area[t], 1e-30));
    return density;
}

PartLines part_lines(const Shell& shell, const Decomposition& decomposition, size_t p) {
    const PartMolding& part = decomposition.parts[p];
    const PartSurface& s = part.surface;
    // Parting line: the edges shared by an M⁺ and an M⁻ triangle (found along
    // the surface's adjacency: linear, the studio asks after every edit);
    // part boundary: the outer edges of the prisms whose neighbour is in
    // another part.
    std::vector<Edge> parting, boundary;
    for (uint32_t i = 0; i < s.size(); ++i)
        for (uint32_t j : s.adjacent(i)) {
            if (j < i || part.upper[i] == part.upper[j]) continue;
            for (int k = 0; k < 3; ++k) {
                const uint32_t a = s.corners[i][k], b = s.corners[i][(k + 1) % 3];
                const auto& c = s.corners[j];
                const bool has_a = c[0] == a || c[1] == a || c[2] == a, has_b = c[0] == b || c[1] == b || c[2] == b;
                if (has_a && has_b) {
                    parting.push_back(std::minmax(a, b));
                    break;
                }
            }
        }
    std::sort(parting.begin(), parting.end());
    parting.erase(std::unique(parting.begin(), parting.end()), parting.end());
    for (size_t i = 0; i < s.size(); ++i) {
        if (s.kind[i] != PartSurface::outer) continue;
        const uint32_t t = s.source[i];
        for (int k = 0; k < 3; ++k)
            if (decomposition.part_of_triangle[shell.neighbor[t][k]] != int(p)) {
                const Triangle& f = shell.outer.triangles[t];
                boundary.push_back(std::minmax(f[k], f[(k + 1) % 3]));
            }
    }
    return {polylines(shell, parting), polylines(shell, boundary)};
}

nlohmann::json decomposition_document(const Shell& shell, const MoldabilityTerms& terms,
                                      const Decomposition& decomposition, const DecompositionOptions& options) {
    nlohmann::json doc;
    doc["format"] = "fabvdb decomposition";
    doc["version"] = 1;
    doc["gamma"] = options.gamma;
    doc["units"] = "mm; energies and the *_unit areas are in the unit-cube-scaled frame (lengths × unit_scale)";
    doc["unit_scale"] = shell.unit_scale;
    doc["shell_thickness"] = shell.thickness;
    doc["solid"] = shell.solid;
    doc["draft_degrees"] = terms.draft * 180.0 / M_PI;
    doc["weights"] = {{"w_H", options.weights.overhang},
                      {"w_L", options.weights.overlap},
                      {"w_O", options.overlap_weight}};
    doc["total_moldability_energy"] = decomposition.total_energy();
    doc["low_res_surface"] = {{"vertices", shell.outer.vertices},
                              {"triangles", shell.outer.triangles},
                              {"inner_vertices", shell.inner},
                              {"thin_segment", shell.thin_segment},
                              {"corner_ids", "a surface corner id v < vertices.size() is vertices[v]; "
                                             "otherwise inner_vertices[v - vertices.size()]"}};
    doc["part_of_triangle"] = decomposition.part_of_triangle;
    nlohmann::json parts = nlohmann::json::array();
    for (size_t p = 0; p < decomposition.parts.size(); ++p) {
        const PartMolding& part = decomposition.parts[p];
        const PartSurface& s = part.surface;
        std::vector<uint32_t> prisms;
        double area = 0, area_unit = 0;
        for (size_t i = 0; i < s.size(); ++i)
            if (s.kind[i] == PartSurface::outer) {
                prisms.push_back(s.source[i]);
                area_unit += s.area[i];
            }
        area = area_unit / (shell.unit_scale * shell.unit_scale);
        const PartLines lines = part_lines(shell, decomposition, p);
        std::vector<int> kinds(s.kind.begin(), s.kind.end());
        std::vector<int> upper(part.upper.begin(), part.upper.end());
        parts.push_back({{"id", p},
                         {"parting_direction", terms.directions.directions[part.direction]},
                         {"moldability_energy", part.energy.total},
                         {"overhang_energy", part.energy.overhang},
                         {"overlap_energy", part.energy.overlap},
                         {"area", area},
                         {"area_unit", area_unit},
                         {"prisms", prisms},
                         {"surface",
                          {{"triangles", s.corners},
                           {"kind", kinds},
                           {"kind_names", {"outer", "inner", "side"}},
                           {"upper", upper}}},
                         {"parting_lines", lines.parting},
                         {"boundaries", lines.boundaries}});
    }
    doc["parts"] = std::move(parts);
    return doc;
}

void write_decomposition(const std::string& folder, const Mesh& input, const Shell& shell,
                         const MoldabilityTerms& terms, const Decomposition& decomposition,
                         const DecompositionOptions& options) {
    AtomicOutput output(folder, AtomicOutput::Kind::folder);
    const std::string json_path = output.temp_path() + "/decomposition.json";
    std::ofstream json(json_path);
    json << decomposition_document(shell, terms, decomposition, options).dump(1) << "\n";
    if (!json) throw Error(FABVDB_ERR_IO, json_path + ": write failed");
    json.close();
    write_parts_ply(output.temp_path() + "/decomposition.ply", input, shell, decomposition);
    write_deformation_ply(output.temp_path() + "/deformation.ply", shell, terms, decomposition, options);
    output.commit();
}

}  // namespace fabvdb::surface
