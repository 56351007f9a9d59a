//! A two-piece mold for one moldable part (thesis §3.6.3): in the frame where
//! the parting direction d is +Z, a block reaching at least `margin` past
//! the part (up to one grid step more: its grid lines keep clear of the
//! part's vertices, clear_grid_origin.h) is split by the RBF parting
//! surface through the part's silhouette (its parting line; kept a quarter
//! grid step above the line, which leaves a lip of that height on the
//! bottom piece instead of needle triangles) and the pieces are
//!   bottom = ((B⁻ ∪ SV↓ ∪ pins) ∖ SV↑ ∖ channels) ∩ slab,
//!   top    = ((B⁺ ∪ SV↑) ∖ SV↓ ∖ channels ∖ key holes) ∩ slab,
//! B∓ the block below/above the parting surface, SV↑ the part swept up to the
//! block top (the part and everything above it), SV↓ swept down, channels the
//! runner, sprue and vents (mold_features.h), slab the block's height range
//! (B∓ and SV reach past it, so no two solids share a plane). CGAL exact
//! booleans, the two pieces made at once on two threads. The part
//! must be a double height field along d (sweep.h makes it one). The pieces
//! come back in world coordinates, closed and 2-manifold, with float
//! coordinates that cross nowhere (float_rounding.h: what an STL file stores
//! is what was checked); the bottom is removed along −d, the top along +d.
//! Checks cancellation between stages.
#pragma once

#include <array>
#include <vector>

#include "core/mesh.h"
#include "core/progress.h"
#include "surface/mold_features.h"

namespace fabvdb::surface {

struct MoldOptions {
    //! Block margin around the part, mm (> 0).
    double margin = 10.0;
    //! Parting-surface grid step, mm; 0: margin/8.
    double grid_step = 0.0;
};

struct MoldPair {
    Mesh top, bottom;  //!< world coordinates
    Mesh channels;     //!< runner, sprue and vents as one solid (world), for volume accounting
    std::array<double, 3> block_size{0, 0, 0};  //!< along e1, e2 (up when pouring) and d
    Vec3 block_center{0, 0, 0};                  //!< world
    std::vector<Vec3> gates;                     //!< world, one per part
    std::vector<Vec3> vents;                     //!< world
    Vec3 up{0, 0, 0};                            //!< world direction that is up when pouring
};

//! `part`: closed, 2-manifold, world coordinates. `direction`: d.
MoldPair assemble_mold(const Mesh& part, const Vec3& direction, const MoldOptions& options, Progress& progress);

//! One mold for several parts (`--common-mold`): each part turned so its
//! direction is +Z (its aligned_frame) and moved by offsets[p] into a row
//! along X, a margin apart, with one gate per part on a shared runner and
//! sprue. "World" in the MoldPair means these row coordinates: a part's point
//! p is at aligned_frame(directions[p]).to_frame(p) + offsets[p].
MoldPair assemble_common_mold(const std::vector<Mesh>& parts, const std::vector<Vec3>& directions,
                              const MoldOptions& options, Progress& progress, std::vector<Vec3>& offsets);

}  // namespace fabvdb::surface
