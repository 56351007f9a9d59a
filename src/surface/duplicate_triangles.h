//! Duplicate triangles: a triangle whose set of vertex indices (in any order
//! and orientation) equals that of an earlier triangle. Only the later copies
//! count, so n identical triangles give n - 1 duplicates. Indices as stored:
//! weld first (weld_vertices.h) to compare positions instead.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::surface {

//! Indices of the triangles that repeat an earlier one, ascending.
std::vector<uint32_t> duplicate_triangles(const Mesh& mesh);

}  // namespace fabvdb::surface
