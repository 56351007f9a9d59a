//! The corners of a triangle mesh grouped by vertex (compressed rows): corner
//! c = 3 t + k is corner k of triangle t, and vertex v's corners are
//! `corner[first[v]]` up to `corner[first[v + 1]]`, in triangle order (a
//! triangle that names v twice is there twice). Built in two passes. Also
//! finds the triangles across an edge, for the callers that need a mesh's
//! edge neighbours.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::volume {

struct VertexCorners {
    std::vector<uint32_t> first;
    std::vector<uint32_t> corner;

    explicit VertexCorners(const Mesh& mesh);

    //! The triangles that run along edge k of triangle t (corner k to k + 1)
    //! the other way: how many, and the first in triangle order.
    struct Across {
        uint32_t first = UINT32_MAX;
        int count = 0;
    };
    //! `mesh`: the one the rows were built from.
    Across across(const Mesh& mesh, uint32_t t, int k) const;
};

}  // namespace fabvdb::volume
