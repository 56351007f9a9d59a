//! decomposition_io on a sphere shell split into hemispheres: part_lines'
//! boundaries and parting lines are exactly the edges found here from the
//! triangle adjacency (between parts; between M⁺ and M⁻ surface triangles),
//! chained into closed loops; outer_upper follows the cut of a sphere cast
//! as one solid part; the deformation density integrates over the area to
//! the weighted energy (zero for a box along its axis); the document passes
//! the independent checks of support/decomposition_checks with the areas
//! measured here; write_decomposition replaces an older folder with the
//! three files (PLY sizes, colours by part and side, heat colours at the
//! extremes) and refuses a folder whose parent is missing, naming it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <sstream>

#include <sys/stat.h>

#include "core/error.h"
#include "shell_shapes.h"
#include "support/decomposition_checks.h"
#include "support/hemisphere_parts.h"
#include "support/temp_files.h"
#include "surface/decomposition_io.h"
#include "surface/moldability_terms.h"

namespace {

using fabvdb::Vec3;
using fabvdb::surface::Decomposition;
using fabvdb::surface::DecompositionOptions;
using fabvdb::surface::MoldabilityTerms;
using fabvdb::surface::PartSurface;
using fabvdb::surface::Shell;
using Edge = std::pair<uint32_t, uint32_t>;

//! A shell, its terms and a decomposition of it by hand-chosen parts and directions.
struct Decomposed {
    Decomposed(Shell s, std::vector<int> part_of_triangle, const std::vector<Vec3>& directions, double draft_degrees,
               const fabvdb::surface::MoldabilityWeights& weights = {})
        : shell(std::move(s)) {
        terms = fabvdb::surface::compute_moldability_terms(shell, draft_degrees * M_PI / 180.0, progress);
        std::vector<int> direction_ids;
        for (const Vec3& d : directions)
            direction_ids.push_back(fabvdb::test::nearest_direction(terms.directions.directions, d));
        decomposition.part_of_triangle = std::move(part_of_triangle);
        decomposition.parts =
            fabvdb::surface::parting_lines(shell, terms, decomposition.part_of_triangle, direction_ids, weights);
    }
    Shell shell;
    fabvdb::Progress progress;
    MoldabilityTerms terms;
    Decomposition decomposition;
};

Shell hollow_sphere() { return fabvdb::test::shell_of(fabvdb::test::make_sphere({0, 0, 0}, 20.0, 2), 1.0); }

Shell solid_sphere() {
    Shell shell = hollow_sphere();
    shell.solid = true;
    return shell;
}

//! Hemispheres along ±z (each cap moldable along its own pole).
Decomposed hemispheres_along_their_poles() {
    Shell shell = hollow_sphere();
    std::vector<int> parts = fabvdb::test::hemisphere_parts(shell);
    return Decomposed(std::move(shell), std::move(parts), {{0, 0, 1}, {0, 0, -1}}, 2.0);
}

//! Hemispheres along +x and +y: poor directions, so the parts have energy and
//! both M⁺ and M⁻ on their outer side.
Decomposed hemispheres_sideways(const fabvdb::surface::MoldabilityWeights& weights = {}) {
    Shell shell = hollow_sphere();
    std::vector<int> parts = fabvdb::test::hemisphere_parts(shell);
    return Decomposed(std::move(shell), std::move(parts), {{1, 0, 0}, {0, 1, 0}}, 0.0, weights);
}

//! The corner id of every outer and inner vertex position (all distinct on a sphere shell).
std::map<Vec3, uint32_t> corner_ids(const Shell& shell) {
    std::map<Vec3, uint32_t> id;
    const uint32_t outer = uint32_t(shell.outer.vertices.size());
    for (uint32_t v = 0; v < outer; ++v) id[shell.outer.vertices[v]] = v;
    for (uint32_t v = 0; v < shell.inner.size(); ++v) id[shell.inner[v]] = outer + v;
    return id;
}

//! The segments of `lines` as corner-id edges; every line must be a closed loop.
std::multiset<Edge> loop_segments(const Shell& shell, const std::vector<std::vector<Vec3>>& lines) {
    const std::map<Vec3, uint32_t> id = corner_ids(shell);
    std::multiset<Edge> segments;
    for (const auto& line : lines) {
        EXPECT_GE(line.size(), 4u);
        EXPECT_EQ(line.front(), line.back()) << "an open polyline";
        for (size_t i = 0; i + 1 < line.size(); ++i) {
            const auto a = id.find(line[i]), b = id.find(line[i + 1]);
            EXPECT_TRUE(a != id.end() && b != id.end()) << "a point that is no shell corner";
            if (a != id.end() && b != id.end()) segments.insert(std::minmax(a->second, b->second));
        }
    }
    return segments;
}

//! The S_low edges whose two triangles lie in different parts.
std::multiset<Edge> edges_between_parts(const Shell& shell, const std::vector<int>& part_of_triangle) {
    std::multiset<Edge> edges;
    for (size_t t = 0; t < shell.triangle_count(); ++t)
        for (int k = 0; k < 3; ++k) {
            const int u = shell.neighbor[t][k];
            if (size_t(u) > t && part_of_triangle[u] != part_of_triangle[t])
                edges.insert(std::minmax(shell.outer.triangles[t][k], shell.outer.triangles[t][(k + 1) % 3]));
        }
    return edges;
}

//! The edges of a part's surface that an M⁺ triangle and an M⁻ triangle
//! both have among their corners (each edge once; from the corners alone,
//! not the surface's adjacency lists, which part_lines walks).
std::multiset<Edge> edges_between_sides(const fabvdb::surface::PartMolding& part) {
    const PartSurface& s = part.surface;
    std::map<Edge, int> sides;  // bit 1: seen from M⁺, bit 2: from M⁻
    for (uint32_t i = 0; i < s.size(); ++i)
        for (int k = 0; k < 3; ++k) sides[std::minmax(s.corners[i][k], s.corners[i][(k + 1) % 3])] |= part.upper[i] ? 1 : 2;
    std::multiset<Edge> edges;
    for (const auto& [edge, seen] : sides)
        if (seen == 3) edges.insert(edge);
    return edges;
}

double outer_area_mm2(const Shell& shell, const std::vector<int>& part_of_triangle, int part) {
    double area = 0;
    for (size_t t = 0; t < shell.triangle_count(); ++t)
        if (part_of_triangle[t] == part) area += fabvdb::triangle_area(shell.outer, shell.outer.triangles[t]);
    return area;
}

double polyline_length(const std::vector<std::vector<Vec3>>& lines) {
    double length = 0;
    for (const auto& line : lines)
        for (size_t i = 0; i + 1 < line.size(); ++i) length += std::sqrt(fabvdb::squared_distance(line[i], line[i + 1]));
    return length;
}

//! A binary little-endian PLY as written for the decomposition: vertex and
//! face counts, and per face its colour and (if present) deformation value.
struct ColourPly {
    size_t vertices = 0, faces = 0;
    bool has_deformation = false;
    std::vector<std::array<uint8_t, 3>> colour;
    std::vector<float> deformation;
};

ColourPly read_colour_ply(const std::string& path) {
    const std::string bytes = fabvdb::test::read_bytes(path);
    ColourPly ply;
    const size_t end = bytes.find("end_header\n");
    EXPECT_NE(end, std::string::npos) << path;
    if (end == std::string::npos) return ply;
    std::istringstream header(bytes.substr(0, end));
    for (std::string line; std::getline(header, line);) {
        if (line.rfind("element vertex ", 0) == 0) ply.vertices = std::stoul(line.substr(15));
        if (line.rfind("element face ", 0) == 0) ply.faces = std::stoul(line.substr(13));
        if (line == "property float deformation") ply.has_deformation = true;
    }
    const size_t face_bytes = 1 + 12 + 3 + (ply.has_deformation ? 4 : 0);
    size_t at = end + 11;
    EXPECT_EQ(bytes.size(), at + 12 * ply.vertices + face_bytes * ply.faces) << path;
    if (bytes.size() != at + 12 * ply.vertices + face_bytes * ply.faces) return ply;
    at += 12 * ply.vertices;
    for (size_t f = 0; f < ply.faces; ++f, at += face_bytes) {
        EXPECT_EQ(uint8_t(bytes[at]), 3);
        ply.colour.push_back({uint8_t(bytes[at + 13]), uint8_t(bytes[at + 14]), uint8_t(bytes[at + 15])});
        if (ply.has_deformation) {
            float value;
            std::memcpy(&value, bytes.data() + at + 16, 4);
            ply.deformation.push_back(value);
        }
    }
    return ply;
}

}  // namespace

TEST(PartLines, BoundariesAreTheEdgesBetweenPartsInClosedLoops) {
    const Decomposed d = hemispheres_along_their_poles();
    const std::multiset<Edge> expected = edges_between_parts(d.shell, d.decomposition.part_of_triangle);
    ASSERT_GE(expected.size(), 10u);
    for (size_t p = 0; p < 2; ++p) {
        const auto lines = fabvdb::surface::part_lines(d.shell, d.decomposition, p);
        EXPECT_EQ(loop_segments(d.shell, lines.boundaries), expected) << "part " << p;
    }
}

TEST(PartLines, PartingLinesAreTheEdgesBetweenTopAndBottomInClosedLoops) {
    const Decomposed d = hemispheres_sideways();
    for (size_t p = 0; p < 2; ++p) {
        const std::multiset<Edge> expected = edges_between_sides(d.decomposition.parts[p]);
        ASSERT_FALSE(expected.empty()) << "part " << p;
        const auto lines = fabvdb::surface::part_lines(d.shell, d.decomposition, p);
        EXPECT_EQ(loop_segments(d.shell, lines.parting), expected) << "part " << p;
    }
}

TEST(PartLines, SolidSphereAsOnePartHasNoBoundaryAndOneEquator) {
    Shell shell = solid_sphere();
    const size_t n = shell.triangle_count();
    const Decomposed d(std::move(shell), std::vector<int>(n, 0), {{0, 0, 1}}, 0.0);
    const auto lines = fabvdb::surface::part_lines(d.shell, d.decomposition, 0);
    EXPECT_TRUE(lines.boundaries.empty());
    ASSERT_EQ(lines.parting.size(), 1u);
    // Along the outer S_low edges near z = 0: about the circumference 2π·20.
    for (const Vec3& p : lines.parting[0]) EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 20.0, 1e-9);
    const double length = polyline_length(lines.parting);
    EXPECT_GT(length, 2 * M_PI * 20.0 * 0.95);
    EXPECT_LT(length, 2 * M_PI * 20.0 * 1.6);
}

TEST(OuterUpper, SolidSphereAlongZIsTopAboveAndBottomBelow) {
    Shell shell = solid_sphere();
    const size_t n = shell.triangle_count();
    const Decomposed d(std::move(shell), std::vector<int>(n, 0), {{0, 0, 1}}, 0.0);
    const std::vector<char> upper = fabvdb::surface::outer_upper(d.shell, d.decomposition);
    ASSERT_EQ(upper.size(), n);
    size_t checked = 0;
    for (size_t t = 0; t < n; ++t) {
        const double nz = d.shell.normal[t][2];
        if (std::abs(nz) < 0.15) continue;
        ++checked;
        EXPECT_EQ(bool(upper[t]), nz > 0) << "triangle " << t << " n_z " << nz;
    }
    EXPECT_GT(checked, n * 3 / 4);
}

TEST(DeformationDensity, IntegratesToTheWeightedEnergy) {
    DecompositionOptions options;
    options.weights = {2.0, 0.5};
    const Decomposed d = hemispheres_sideways(options.weights);
    const std::vector<float> density =
        fabvdb::surface::deformation_density(d.shell, d.terms, d.decomposition, options);
    ASSERT_EQ(density.size(), d.shell.triangle_count());
    double integral = 0;
    for (size_t t = 0; t < density.size(); ++t) {
        EXPECT_GE(density[t], 0.0f);
        integral += double(density[t]) * d.shell.area[t];
    }
    double weighted = 0;
    for (const auto& part : d.decomposition.parts) weighted += 2.0 * part.energy.overhang + 0.5 * part.energy.overlap;
    ASSERT_GT(weighted, 1e-3);
    EXPECT_NEAR(integral, weighted, 1e-5 * weighted);
}

TEST(DeformationDensity, BoxAlongItsAxisHasNone) {
    // Faces parallel or perpendicular to z with no draft: no overhang, and the
    // top and bottom overlap only across M⁺/M⁻, which costs nothing.
    Shell shell = fabvdb::test::shell_of(fabvdb::test::make_box({0, 0, 0}, {10, 20, 30}), 1.0);
    shell.solid = true;
    const Decomposed d(std::move(shell), std::vector<int>(12, 0), {{0, 0, 1}}, 0.0);
    for (float value : fabvdb::surface::deformation_density(d.shell, d.terms, d.decomposition, {}))
        EXPECT_EQ(value, 0.0f);
}

TEST(DecompositionDocument, PassesTheIndependentChecksWithItsAreas) {
    const Decomposed d = hemispheres_along_their_poles();
    DecompositionOptions options;
    options.gamma = 0.25;
    options.overlap_weight = 123.0;
    const nlohmann::json doc = fabvdb::surface::decomposition_document(d.shell, d.terms, d.decomposition, options);
    EXPECT_EQ(doc.at("format"), "fabvdb decomposition");
    EXPECT_EQ(doc.at("version"), 1);
    EXPECT_DOUBLE_EQ(doc.at("gamma").get<double>(), 0.25);
    EXPECT_DOUBLE_EQ(doc.at("weights").at("w_O").get<double>(), 123.0);
    EXPECT_NEAR(doc.at("draft_degrees").get<double>(), 2.0, 1e-12);
    EXPECT_DOUBLE_EQ(doc.at("shell_thickness").get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(doc.at("unit_scale").get<double>(), 1.0 / 40.0);  // 1 / the sphere's diameter
    EXPECT_EQ(doc.at("part_of_triangle").get<std::vector<int>>(), d.decomposition.part_of_triangle);
    EXPECT_EQ(doc.at("low_res_surface").at("vertices").size(), d.shell.outer.vertices.size());
    EXPECT_EQ(doc.at("low_res_surface").at("inner_vertices").size(), d.shell.inner.size());

    const std::vector<double> areas = fabvdb::test::check_decomposition(doc);
    ASSERT_EQ(areas.size(), 2u);
    double energy = 0;
    for (int p = 0; p < 2; ++p) {
        const auto& part = doc.at("parts")[p];
        const double area = outer_area_mm2(d.shell, d.decomposition.part_of_triangle, p);
        EXPECT_NEAR(areas[p], area, 1e-9 * area);
        EXPECT_NEAR(part.at("area").get<double>(), area, 1e-9 * area);
        EXPECT_NEAR(part.at("area_unit").get<double>(), area / (40.0 * 40.0), 1e-9 * area);
        const Vec3 direction = part.at("parting_direction").get<Vec3>();
        EXPECT_GT(direction[2] * (p == 0 ? 1 : -1), 0.99) << "part " << p;
        energy += part.at("moldability_energy").get<double>();
    }
    EXPECT_NEAR(doc.at("total_moldability_energy").get<double>(), energy, 1e-12);
    // The boundary measured on the written triangles is the one part_lines chains.
    const double boundary = fabvdb::test::measure_boundaries(doc).length;
    EXPECT_NEAR(polyline_length(doc.at("parts")[0].at("boundaries").get<std::vector<std::vector<Vec3>>>()), boundary,
                1e-9 * boundary);
}

TEST(WriteDecomposition, ReplacesTheFolderWithTheThreeFiles) {
    const Decomposed d = hemispheres_sideways();
    const DecompositionOptions options;
    fabvdb::test::TempDir dir;
    const std::string folder = dir.file("decomposition");
    ASSERT_EQ(mkdir(folder.c_str(), 0755), 0);
    fabvdb::test::write_bytes(folder + "/stale.txt", "from an older run");
    fabvdb::surface::write_decomposition(folder, d.shell.outer, d.shell, d.terms, d.decomposition, options);
    EXPECT_EQ(fabvdb::test::entry_count(folder), 3);
    EXPECT_EQ(fabvdb::test::entry_count(dir.path()), 1);

    const nlohmann::json doc = fabvdb::test::read_decomposition(folder + "/decomposition.json");
    EXPECT_EQ(doc.at("parts").size(), 2u);
    EXPECT_EQ(doc.at("part_of_triangle").get<std::vector<int>>(), d.decomposition.part_of_triangle);

    // Parts coloured by the input (here S_low itself): one colour per part and
    // side, the parts apart, M⁻ a darker shade of M⁺.
    const ColourPly parts = read_colour_ply(folder + "/decomposition.ply");
    EXPECT_FALSE(parts.has_deformation);
    EXPECT_EQ(parts.vertices, d.shell.outer.vertices.size());
    ASSERT_EQ(parts.colour.size(), d.shell.triangle_count());
    const std::vector<char> upper = fabvdb::surface::outer_upper(d.shell, d.decomposition);
    using Colour = std::array<uint8_t, 3>;
    std::map<std::pair<int, bool>, Colour> colour_of;
    for (size_t t = 0; t < parts.colour.size(); ++t) {
        const auto key = std::make_pair(d.decomposition.part_of_triangle[t], bool(upper[t]));
        EXPECT_EQ(colour_of.emplace(key, parts.colour[t]).first->second, parts.colour[t]) << "triangle " << t;
    }
    ASSERT_EQ(colour_of.size(), 4u);
    const Colour top0 = colour_of[std::make_pair(0, true)], top1 = colour_of[std::make_pair(1, true)];
    EXPECT_NE(top0, top1);
    for (int p = 0; p < 2; ++p) {
        const Colour top = colour_of[std::make_pair(p, true)], bottom = colour_of[std::make_pair(p, false)];
        for (int c = 0; c < 3; ++c) EXPECT_EQ(bottom[c], uint8_t(top[c] * 0.55)) << "part " << p;
    }

    // Deformation on S_low: heat colours, red at the highest value, blue at zero,
    // and the values integrate to the total energy.
    const ColourPly heat = read_colour_ply(folder + "/deformation.ply");
    EXPECT_TRUE(heat.has_deformation);
    ASSERT_EQ(heat.deformation.size(), d.shell.triangle_count());
    const size_t highest = size_t(std::max_element(heat.deformation.begin(), heat.deformation.end()) -
                                  heat.deformation.begin());
    EXPECT_EQ(heat.colour[highest], (std::array<uint8_t, 3>{255, 0, 0}));
    double integral = 0;
    size_t zeros = 0;
    for (size_t t = 0; t < heat.deformation.size(); ++t) {
        integral += double(heat.deformation[t]) * d.shell.area[t];
        if (heat.deformation[t] == 0.0f) {
            ++zeros;
            EXPECT_EQ(heat.colour[t], (std::array<uint8_t, 3>{0, 0, 255})) << "triangle " << t;
        }
    }
    EXPECT_GT(zeros, 0u);
    EXPECT_NEAR(integral, d.decomposition.total_energy(), 1e-5 * d.decomposition.total_energy());
}

TEST(WriteDecomposition, MissingParentFolderIsAnIoErrorNamingIt) {
    const Decomposed d = hemispheres_along_their_poles();
    fabvdb::test::TempDir dir;
    const std::string folder = dir.file("no/such/parent");
    try {
        fabvdb::surface::write_decomposition(folder, d.shell.outer, d.shell, d.terms, d.decomposition, {});
        FAIL() << "no exception";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_IO);
        EXPECT_NE(std::string(e.what()).find(dir.file("no/such")), std::string::npos) << e.what();
    }
    EXPECT_EQ(fabvdb::test::entry_count(dir.path()), 0);
}
