//! Vertices that share one position though their indices differ (sheets of
//! an extracted surface touching at a point: welded by position, as STL
//! stores them, they would pinch the surface) each moved a hundredth of the
//! way toward the centre of its own ring of neighbours, into its own sheet.
//! Every other vertex and every triangle stays as it is. Returns how many
//! vertices moved. Linear in the mesh plus a sort of its vertices.
#pragma once

#include <cstddef>

#include "core/mesh.h"

namespace fabvdb::volume {

size_t part_coincident_vertices(Mesh& mesh);

}  // namespace fabvdb::volume
