//! Inspection of a triangle mesh as a print-file checker sees it: counts,
//! topology (components, boundary edges and loops, non-manifold edges and
//! vertices, orientation, genus), defects (degenerate and duplicate triangles,
//! self-intersecting pairs by exact predicates, with the indices of the
//! triangles in them, so a viewer can select them) and measures (volume, bbox),
//! and warnings: a size under 1 mm or over 2 m across suggests other units
//! (metres, inches, micrometres); over 1 km from the origin STL loses precision.
//! Pure: reads the mesh, returns the figures as a JSON object (README "fabvdb
//! info" defines every key). Reports progress; throws Error(CANCELLED).
#pragma once

#include <nlohmann/json.hpp>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::surface {

nlohmann::json inspect_mesh(const Mesh& mesh, Progress& progress);

}  // namespace fabvdb::surface
