//! Connected regions of chosen triangles of a mesh (a thin wall, a narrow
//! slot, an overhang): the chosen triangles joined through shared vertices,
//! each region with its area, area-weighted centroid and bounding box, the
//! largest first. Pure; linear in the mesh's size.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::surface {

struct TriangleRegion {
    std::vector<uint32_t> triangles;  //!< indices into the mesh's triangles
    std::vector<uint32_t> vertices;   //!< the vertices they use, ascending
    double area = 0.0;                //!< mm²
    Vec3 centroid{0, 0, 0};           //!< area-weighted centre of its triangles
    BoundingBox box;                  //!< of its vertices
};

//! `chosen`: one flag per triangle of `mesh`.
std::vector<TriangleRegion> triangle_regions(const Mesh& mesh, const std::vector<uint8_t>& chosen);

}  // namespace fabvdb::surface
