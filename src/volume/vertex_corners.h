//! The corners of a triangle mesh grouped by vertex (compressed rows): corner
//! c = 3 t + k is corner k of triangle t, and vertex v's corners are
//! `corner[first[v]]` up to `corner[first[v + 1]]`, in triangle order (a
//! triangle that names v twice is there twice). Built in two passes.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::volume {

struct VertexCorners {
    std::vector<uint32_t> first;
    std::vector<uint32_t> corner;

    explicit VertexCorners(const Mesh& mesh);
};

}  // namespace fabvdb::volume
