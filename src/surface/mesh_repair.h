//! Repair at mesh level, keeping the input's own triangles: what a dirty
//! mesh needs when its defects are exactly fixable without voxels.
//!  1. The input itself when it is a clean solid (clean_solid.h), or with its
//!     crossing triangles cut down to the union of its shells
//!     (resolve_crossings.h) when crossings are its only defect.
//!  2. Else, when the input is a 2-manifold whose only defects are zero-area
//!     triangles (and crossings), those flipped or collapsed away
//!     (collapse_degenerate_triangles.h).
//!  3. Else the input welded at exactly coincident points, without
//!     degenerate and duplicate triangles, each piece consistently oriented
//!     and inverted shells turned (orient_soup.h: CGAL's polygon-soup repair
//!     and orientation), then shell by shell: a shell is kept when it is
//!     clean (a void's wall facing in counts), or once its holes under 5% of
//!     the bounding-box diagonal are filled with faired patches
//!     (fill_small_holes.h), or once its own crossings are resolved; the
//!     other shells are handed back in `rest` for the volumetric path. The
//!     shells kept must make one clean solid together (their crossings
//!     resolved).
//! Returns nothing when no shell can be kept, or the kept ones do not make a
//! clean solid together; `oriented`, when given, then receives the input as
//! orient_soup made it in step 3 (empty if step 3 was not reached), so that
//! the volumetric repair need not orient it again. Costs a few exact
//! crossing tests; reports progress, throws Error(CANCELLED).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::surface {

struct MeshRepair {
    //! The clean solid made of the shells kept.
    Mesh mesh;
    //! The shells left to the volumetric path (empty when all were kept).
    Mesh rest;
    //! "input" (the input was a clean solid) or "mesh" (fixed at mesh level).
    std::string path;
    //! What was done, in words ("removed 3 duplicate triangles").
    std::vector<std::string> fixes;
    //! Per shell, in order: "input", "mesh" or "volumetric" (in `rest`).
    std::vector<std::string> shell_paths;
};

std::optional<MeshRepair> repair_at_mesh_level(const Mesh& input, Progress& progress, Mesh* oriented = nullptr);

//! `kept` and `more` (two clean solids, such as the shells kept and the
//! volumetric repair of the rest) as one clean solid, their crossings
//! resolved (named in `fixes`); nothing when that fails.
std::optional<Mesh> unite_shells(const Mesh& kept, const Mesh& more, std::vector<std::string>& fixes,
                                 Progress& progress);

}  // namespace fabvdb::surface
