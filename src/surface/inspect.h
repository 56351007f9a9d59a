//! Inspection of a triangle mesh as a print-file checker sees it: counts,
//! topology (components, boundary edges and loops, non-manifold edges and
//! vertices, orientation, genus), defects (degenerate and duplicate triangles,
//! self-intersecting pairs by exact predicates) and measures (volume, bbox).
//! Pure: reads the mesh, returns the figures as a JSON object (README "fabvdb
//! info" defines every key). Reports progress; throws Error(CANCELLED).
#pragma once

#include <nlohmann/json.hpp>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::surface {

nlohmann::json inspect_mesh(const Mesh& mesh, Progress& progress);

}  // namespace fabvdb::surface
