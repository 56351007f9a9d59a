//! Whether a triangle mesh is a closed, oriented 2-manifold by its vertex
//! indices: no triangle repeats a vertex, and around every vertex its
//! triangles form one closed fan, each edge shared by exactly two triangles
//! that run along it in opposite directions. Parallel (TBB).
#pragma once

#include "core/mesh.h"

namespace fabvdb::volume {

bool is_closed_manifold(const Mesh& mesh);

}  // namespace fabvdb::volume
