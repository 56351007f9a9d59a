//! The patches of a cut surface (cut_along_crossings.h): its triangles
//! joined across every edge but the cuts (union-find over the edges), and
//! for every cut edge the patches on its two sides. Pure; near linear in the
//! triangles; parallel (TBB) in finding each edge's opposite.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "volume/cut_along_crossings.h"

namespace fabvdb::volume {

struct Patches {
    std::vector<uint32_t> of_triangle;  //!< per triangle, its patch, numbered in order of first triangle
    size_t count = 0;
    //! For every cut edge, the patches of the triangles on its two sides
    //! (one sheet): the winding number in front of them differs by one.
    std::vector<std::pair<uint32_t, uint32_t>> across_cuts;
};

//! Nothing when some edge has no single opposite (not a manifold by its
//! indices) or a cut does not part its two sides (a cut that ends inside a
//! patch, as at a branch point, where no winding number holds for a patch).
//! An edge between two untouched triangles (before `first_piece`) is never
//! a cut.
std::optional<Patches> cut_patches(const CutSurface& surface);

}  // namespace fabvdb::volume
