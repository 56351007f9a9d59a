//! Repair at mesh level, keeping the input's triangles (see mesh_repair.h).
#include "surface/mesh_repair.h"

#include <utility>

#include "core/turned_inside_out.h"
#include "surface/collapse_degenerate_triangles.h"
#include "surface/fill_small_holes.h"
#include "volume/clean_solid.h"
#include "volume/mesh_shells.h"
#include "volume/orient_soup.h"
#include "volume/resolve_crossings.h"

namespace fabvdb::surface {

namespace {

// Holes up to this share of the bounding-box diagonal across are filled at
// mesh level; larger ones (an open side, a scan's missing back) are left to
// the volumetric path, whose winding-number surface closes them.
constexpr double small_hole_share = 0.05;

// `mesh` if it is a clean solid, or its crossings resolved if they are its
// only defect and can be; the resolution is named in `fixes`.
std::optional<Mesh> clean_or_resolved(const Mesh& mesh, std::vector<std::string>& fixes, Progress& progress) {
    const volume::SolidCheck check = volume::check_solid(mesh, progress);
    if (check.clean) return mesh;
    if (check.crossings.empty()) return std::nullopt;
    std::optional<Mesh> resolved = volume::resolve_crossings(mesh, check.crossings, progress);
    if (resolved)
        fixes.push_back("cut " + std::to_string(check.crossings.size()) +
                        " crossing triangle pairs down to the union of the shells");
    return resolved;
}

bool is_clean_either_way(const Mesh& mesh, Progress& progress) {
    return volume::check_solid(mesh, progress).clean || volume::check_solid(turned_inside_out(mesh), progress).clean;
}

}  // namespace

std::optional<MeshRepair> repair_at_mesh_level(const Mesh& input, Progress& progress, Mesh* oriented_out) {
    if (input.triangles.empty()) return std::nullopt;
    MeshRepair repair;
    if (std::optional<Mesh> mesh = clean_or_resolved(input, repair.fixes, progress)) {
        repair.path = repair.fixes.empty() ? "input" : "mesh";
        repair.mesh = std::move(*mesh);
        repair.shell_paths.assign(volume::split_shells(repair.mesh).size(), repair.path);
        return repair;
    }
    // Zero-area triangles flipped or collapsed away where the input is a
    // 2-manifold: deleting them, as the soup repair below does, would leave
    // slits.
    if (std::optional<CollapsedDegenerates> collapsed = collapse_degenerate_triangles(input, progress)) {
        std::vector<std::string> fixes{"removed " + std::to_string(collapsed->degenerate) +
                                       " degenerate triangles by edge flips and collapses"};
        if (std::optional<Mesh> mesh = clean_or_resolved(collapsed->mesh, fixes, progress)) {
            repair.path = "mesh";
            repair.fixes = std::move(fixes);
            repair.mesh = std::move(*mesh);
            repair.shell_paths.assign(volume::split_shells(repair.mesh).size(), repair.path);
            return repair;
        }
    }
    Mesh oriented = volume::orient_soup(input, progress);
    if (oriented.triangles.empty()) return std::nullopt;
    repair.fixes.push_back("welded coincident points, oriented every shell outward");
    if (oriented.triangles.size() < input.triangles.size())
        repair.fixes.push_back("removed " + std::to_string(input.triangles.size() - oriented.triangles.size()) +
                               " degenerate or duplicate triangles");

    // Shell by shell: each kept when it is clean (either way round: a void's
    // wall faces in), else with its small holes filled, else with its own
    // crossings resolved; what is left goes volumetric.
    const double max_hole = small_hole_share * bounding_box(oriented).diagonal();
    size_t holes = 0, hole_triangles = 0;
    Mesh exact;
    for (const volume::MeshShell& shell : volume::split_shells(oriented)) {
        progress.check();
        Mesh piece = volume::sub_mesh(oriented, shell.triangles);
        if (!is_clean_either_way(piece, progress)) {
            const std::optional<FilledHoles> filled = fill_small_holes(piece, max_hole, progress);
            if (filled && is_clean_either_way(filled->mesh, progress)) {
                holes += filled->holes;
                hole_triangles += filled->added_triangles;
                piece = filled->mesh;
            } else {
                const volume::SolidCheck check = volume::check_solid(piece, progress);
                std::optional<Mesh> resolved;
                if (!check.crossings.empty()) resolved = volume::resolve_crossings(piece, check.crossings, progress);
                if (!resolved) {
                    append(repair.rest, piece);
                    repair.shell_paths.push_back("volumetric");
                    continue;
                }
                piece = std::move(*resolved);
            }
        }
        append(exact, piece);
        repair.shell_paths.push_back("mesh");
    }
    if (holes > 0)
        repair.fixes.push_back("filled " + std::to_string(holes) + " small holes with " +
                               std::to_string(hole_triangles) + " faired triangles");
    // The shells kept must still make one clean solid together.
    std::optional<Mesh> mesh;
    if (!exact.triangles.empty()) mesh = clean_or_resolved(exact, repair.fixes, progress);
    if (!mesh) {
        if (oriented_out) *oriented_out = std::move(oriented);
        return std::nullopt;
    }
    repair.path = "mesh";
    repair.mesh = std::move(*mesh);
    return repair;
}

std::optional<Mesh> unite_shells(const Mesh& kept, const Mesh& more, std::vector<std::string>& fixes,
                                 Progress& progress) {
    Mesh both = kept;
    append(both, more);
    return clean_or_resolved(both, fixes, progress);
}

}  // namespace fabvdb::surface
