//! Degenerate triangles (zero area: a repeated corner or three collinear
//! ones, as degenerate_triangles.h decides) taken out of a mesh that is an
//! oriented 2-manifold, by CGAL's remove_degenerate_faces: a cap (a corner
//! on the opposite edge) goes by flipping that edge, a needle (two
//! coincident corners) by collapsing its short edge. Unlike deleting the
//! triangles, this leaves no slit: a closed mesh stays closed, and every
//! triangle away from the degenerate ones is kept as it is. Returns nothing
//! when the mesh has no degenerate triangle, is not an oriented 2-manifold,
//! or when CGAL cannot remove them all. Pure; checks `progress` once
//! (Error(CANCELLED)); costs a pass over the mesh plus local edits.
#pragma once

#include <cstddef>
#include <optional>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::surface {

struct CollapsedDegenerates {
    Mesh mesh;
    size_t degenerate = 0;  //!< degenerate triangles in the input
};

std::optional<CollapsedDegenerates> collapse_degenerate_triangles(const Mesh& mesh, Progress& progress);

}  // namespace fabvdb::surface
