//! Parts the sheets of a mesh where they touch at a single vertex: a vertex
//! whose triangles form several closed fans (a cut curve that runs through
//! an input vertex, as where a fold turns around one, leaves the union's
//! boundary pinched there) gets a copy per fan, moved 1% of the way toward
//! the centre of that fan's ring (the mean of its other corners), into the
//! fan's own cone; the copies are appended in vertex order and the vertex
//! itself is left unused. Linear in the corners; parallel (TBB) in finding
//! the fans.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::volume {

//! Returns the copies' indices, or nothing when some vertex's triangles do
//! not form closed fans (the mesh is not changed then).
std::optional<std::vector<uint32_t>> part_pinches(Mesh& mesh);

}  // namespace fabvdb::volume
