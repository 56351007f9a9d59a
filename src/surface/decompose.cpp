//! decompose_mesh: shell_from_mesh (again solid when the whole shell is one
//! thin feature) → compute_moldability_terms → coarse_decomposition →
//! smooth_boundaries → edits, timing each stage for the report.
#include "surface/decompose.h"

#include <algorithm>
#include <map>
#include <string>

#include "core/figure_text.h"
#include "core/stage_clock.h"
#include "core/vec3_ops.h"
#include "surface/boundary_smoothing.h"
#include "surface/shell_from_mesh.h"
#include "surface/undercut_depth.h"

namespace fabvdb::surface {

DecomposeResult decompose_mesh(const Mesh& input, const DecomposeSettings& settings, const std::vector<Edit>& edits,
                               Progress& progress) {
    DecomposeResult result;
    nlohmann::json& report = result.report;
    std::map<std::string, double> timings;
    StageClock clock(timings);
    nlohmann::json low_res;
    result.shell = shell_from_mesh(input, settings.shell, progress, &low_res);
    const bool all_thin =
        !settings.shell.solid &&
        std::all_of(result.shell.thin_segment.begin(), result.shell.thin_segment.end(), [](int s) { return s >= 0; });
    if (all_thin) {
        // Thin everywhere: nowhere deeper than the shell's band reached.
        volume::LowResShellOptions solid = settings.shell;
        solid.solid = true;
        solid.solid_depth = 2.0 * settings.shell.thickness;
        result.shell = shell_from_mesh(input, solid, progress, &low_res);
    }
    clock.lap("precompute_shell");
    result.terms = compute_moldability_terms(result.shell, settings.draft_radians, progress);
    clock.lap("precompute_directions");
    report["attempts"] = nlohmann::json::array();
    result.decomposition =
        coarse_decomposition(result.shell, result.terms, settings.decomposition, report["attempts"], progress);
    clock.lap("coarse_decomposition");
    if (settings.decomposition.smoothing_iterations > 0) progress.stage("boundary smoothing");
    report["smoothing"] = smooth_boundaries(result.shell, result.terms, result.decomposition, settings.decomposition,
                                            nullptr, progress);
    clock.lap("smoothing");
    report["edits"] = nlohmann::json::array();
    if (!edits.empty()) progress.stage("edits");
    for (size_t i = 0; i < edits.size(); ++i) {
        nlohmann::json record = apply_edit(result.shell, result.terms, settings.decomposition, edits[i], i,
                                           result.decomposition, progress);
        const double energy = record["total_moldability_energy"];
        if (energy > settings.decomposition.gamma)
            record["warning"] = "the total moldability energy exceeds gamma after this edit";
        report["edits"].push_back(std::move(record));
        progress.update(double(i + 1) / edits.size());
    }
    clock.lap("edits");

    const Decomposition& d = result.decomposition;
    const double energy = d.total_energy();
    report["gamma"] = settings.decomposition.gamma;
    report["shell_thickness"] = result.shell.thickness;
    report["solid"] = settings.shell.solid || all_thin;
    report["solid_chosen"] = all_thin;
    report["unit_scale"] = result.shell.unit_scale;
    report["low_res"] = low_res;
    report["overlap_pairs"] = result.terms.pair_count;
    report["part_count"] = d.parts.size();
    report["total_moldability_energy"] = energy;
    report["under_gamma"] = energy < settings.decomposition.gamma;
    report["parts"] = nlohmann::json::array();
    const double depth_bound = settings.decomposition.max_undercut_depth / result.shell.unit_scale;
    double deepest = 0;
    Vec3 deepest_at{0, 0, 0};
    // Each part's centre: the area-weighted centroid of its S_low triangles.
    std::vector<Vec3> centre(d.parts.size(), Vec3{0, 0, 0});
    std::vector<double> weight(d.parts.size(), 0.0);
    for (size_t t = 0; t < d.part_of_triangle.size(); ++t) {
        const int p = d.part_of_triangle[t];
        if (p < 0 || size_t(p) >= d.parts.size()) continue;
        const Triangle& tri = result.shell.outer.triangles[t];
        const double a = triangle_area(result.shell.outer, tri);
        for (uint32_t v : tri) centre[p] = centre[p] + (a / 3.0) * result.shell.outer.vertices[v];
        weight[p] += a;
    }
    for (size_t p = 0; p < d.parts.size(); ++p)
        if (weight[p] > 0.0) centre[p] = (1.0 / weight[p]) * centre[p];
    size_t costliest = 0;
    for (size_t p = 0; p < d.parts.size(); ++p) {
        if (d.parts[p].energy.total > d.parts[costliest].energy.total) costliest = p;
        double area = 0;
        for (size_t i = 0; i < d.parts[p].surface.size(); ++i)
            if (d.parts[p].surface.kind[i] == PartSurface::outer) area += d.parts[p].surface.area[i];
        const Vec3& direction = result.terms.directions.directions[d.parts[p].direction];
        const UndercutDepth undercut = undercut_depth(result.shell, d.part_of_triangle, int(p), direction,
                                                      undercut_line_spacing(result.shell),
                                                      undercut_reach(result.shell, settings.decomposition));
        if (undercut.depth > deepest) {
            deepest = undercut.depth;
            deepest_at = undercut.at;
        }
        report["parts"].push_back({{"id", p},
                                   {"parting_direction", direction},
                                   {"moldability_energy", d.parts[p].energy.total},
                                   {"area", area / (result.shell.unit_scale * result.shell.unit_scale)},
                                   {"centre", centre[p]},
                                   {"undercut_depth", undercut.depth},
                                   {"undercut_at", undercut.at}});
    }
    report["undercut_depth"] = deepest;
    report["undercut_at"] = deepest_at;
    report["timings"] = timings;
    report["timings"]["precompute_per_direction"] =
        timings["precompute_directions"] / double(result.terms.directions.directions.size());
    report["timings"]["total"] = clock.total();
    report["warnings"] = nlohmann::json::array();
    if (all_thin)
        report["warnings"].push_back("the part is thinner than twice the shell thickness everywhere (one thin "
                                     "feature): its parts are cast solid, as with --solid");
    if (deepest > depth_bound)
        report["warnings"].push_back("an undercut " + figure_text(deepest) + " mm deep at (" +
                                     figure_text(deepest_at[0]) + ", " + figure_text(deepest_at[1]) + ", " +
                                     figure_text(deepest_at[2]) + ") along its part's parting direction is over "
                                     "the bound " + figure_text(depth_bound) + " mm with any part count tried: "
                                     "the mold fills it, leaving the input up to that deep inside the cast part "
                                     "(a cut there, --edits, may avoid it)");
    if (!(energy < settings.decomposition.gamma) && !d.parts.empty()) {
        // Where: the part that carries most of the energy, and which term.
        const MoldabilityEnergy& worst = d.parts[costliest].energy;
        const Vec3& at = centre[costliest];
        report["warnings"].push_back(
            "the total moldability energy " + figure_text(energy) + " is not under gamma " +
            figure_text(settings.decomposition.gamma) +
            (settings.decomposition.parts > 0 ? " with " + std::to_string(d.parts.size()) + " parts"
                                              : " with any part count tried, up to " +
                                                    std::to_string(settings.decomposition.max_parts)) +
            ": part " +
            std::to_string(costliest) + " (around " + figure_text(at[0]) + ", " + figure_text(at[1]) + ", " +
            figure_text(at[2]) + " mm) carries " + figure_text(worst.total) + " of it, mostly " +
            (worst.overlap > worst.overhang ? "overlap (surface both halves of its mold would hold)"
                                            : "overhang (surface facing away from its parting direction)") +
            "; a cut there (--edits) may bring it under");
    }
    return result;
}

}  // namespace fabvdb::surface
