//! Inspection for `fabvdb info`: gathers the topology summary (as stored and
//! after welding), the degenerate, duplicate and self-intersecting triangles,
//! the signed volumes and the bounding box into one JSON object, with
//! warnings when the size or place of the model suggests other units.
#include "surface/inspect.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/figure_text.h"
#include "surface/degenerate_triangles.h"
#include "surface/duplicate_triangles.h"
#include "surface/mesh_topology.h"
#include "surface/self_intersections.h"
#include "surface/signed_volume.h"
#include "surface/weld_vertices.h"

namespace fabvdb::surface {

namespace {

std::string millimetres(double value) { return figure_text(value) + " mm"; }

// What the size and place of the model suggest about its units: a part under
// 1 mm or over 2 m across was most likely drawn in other units (metres,
// inches, micrometres), and one far from the origin loses precision in STL.
std::vector<std::string> unit_warnings(const BoundingBox& box) {
    std::vector<std::string> warnings;
    double longest = 0.0, farthest = 0.0;
    for (int k = 0; k < 3; ++k) {
        longest = std::max(longest, box.max[k] - box.min[k]);
        farthest = std::max({farthest, std::abs(box.min[k]), std::abs(box.max[k])});
    }
    if (longest > 0.0 && longest < 1.0)
        warnings.push_back("the model is only " + millimetres(longest) +
                           " across: if its file is in metres, scale it by 1000 (--scale 1000); in inches, by 25.4");
    else if (longest > 2000.0)
        warnings.push_back("the model is " + millimetres(longest) +
                           " across: if its file is in micrometres, scale it by 0.001 (--scale 0.001); check its units");
    if (farthest > 1e6) {
        const double step = std::nextafter(float(farthest), HUGE_VALF) - float(farthest);
        warnings.push_back("the model lies " + millimetres(farthest) + " from the origin, where STL and 3MF store "
                           "coordinates " + millimetres(step) + " apart; write .obj, .ply or .off to keep them");
    }
    return warnings;
}

}  // namespace

nlohmann::json inspect_mesh(const Mesh& mesh, Progress& progress) {
    progress.stage("topology");
    const TopologySummary topology = summarize_topology(mesh);
    const Mesh welded = weld_coincident_vertices(mesh);
    const TopologySummary welded_topology = summarize_topology(welded);
    progress.update(0.5);
    const std::vector<uint32_t> degenerate = degenerate_triangles(mesh);
    const size_t duplicates = duplicate_triangles(mesh).size();
    const std::vector<double> volumes =
        component_signed_volumes(mesh, topology.triangle_component, topology.components);
    progress.update(1.0);
    const std::vector<std::pair<uint32_t, uint32_t>> intersecting = self_intersecting_pairs(mesh, progress);
    std::vector<bool> is_degenerate(mesh.triangles.size(), false);
    for (uint32_t t : degenerate) is_degenerate[t] = true;
    size_t intersecting_with_degenerate = 0;
    std::vector<uint32_t> crossing;
    crossing.reserve(2 * intersecting.size());
    for (const auto& [i, j] : intersecting) {
        if (is_degenerate[i] || is_degenerate[j]) ++intersecting_with_degenerate;
        crossing.push_back(i);
        crossing.push_back(j);
    }
    std::sort(crossing.begin(), crossing.end());
    crossing.erase(std::unique(crossing.begin(), crossing.end()), crossing.end());

    nlohmann::json volume = nullptr;
    size_t negative_shells = 0;
    double total_volume = 0;
    for (size_t c = 0; c < volumes.size(); ++c) {
        total_volume += volumes[c];
        if (topology.component_closed[c] && volumes[c] < 0) ++negative_shells;
    }
    if (topology.closed) volume = total_volume;
    const BoundingBox box = bounding_box(mesh);

    nlohmann::json report;
    report["vertices"] = mesh.vertices.size();
    report["triangles"] = mesh.triangles.size();
    report["unreferenced_vertices"] = topology.unreferenced_vertices;
    report["components"] = topology.components;
    report["closed"] = topology.closed;
    report["boundary_edges"] = topology.boundary_edges;
    report["boundary_loops"] = topology.boundary_loops;
    report["non_manifold_edges"] = topology.non_manifold_edges;
    report["non_manifold_vertices"] = topology.non_manifold_vertices;
    report["consistently_oriented"] = topology.inconsistent_edges == 0;
    report["inconsistent_edges"] = topology.inconsistent_edges;
    report["degenerate_triangles"] = degenerate.size();
    report["duplicate_triangles"] = duplicates;
    report["self_intersecting_pairs"] = intersecting.size();
    report["self_intersecting_pairs_degenerate"] = intersecting_with_degenerate;
    report["self_intersecting_triangle_indices"] = crossing;
    report["degenerate_triangle_indices"] = degenerate;
    report["volume"] = volume;
    report["negative_volume_shells"] = negative_shells;
    report["genus"] = topology.genus ? nlohmann::json(*topology.genus) : nlohmann::json(nullptr);
    report["bbox"] = {{"min", box.min}, {"max", box.max}};
    report["welded"] = {{"vertices", welded.vertices.size()},
                        {"components", welded_topology.components},
                        {"closed", welded_topology.closed},
                        {"boundary_edges", welded_topology.boundary_edges},
                        {"boundary_loops", welded_topology.boundary_loops},
                        {"non_manifold_edges", welded_topology.non_manifold_edges},
                        {"non_manifold_vertices", welded_topology.non_manifold_vertices}};
    report["warnings"] = unit_warnings(box);
    return report;
}

}  // namespace fabvdb::surface
