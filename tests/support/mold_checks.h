//! Independent acceptance checks of a two-piece mold for tests (gtest
//! expectations; no code shared with the generator): both pieces closed,
//! 2-manifold, self-intersection free, of positive
//! volume and without triangles that degenerate when stored as float STL;
//! the part a double height field along d; each piece a height field along
//! d ending at the block's face (top removed along +d, bottom along −d)
//! without overlapping the other; their sampled common volume ~0; the void
//! between them minus the channels equal to the part's volume within 2%;
//! the void one connected region reaching the outside. By ray casting
//! (support/ray_cast.h) and the divergence theorem.
#pragma once

#include "core/mesh.h"

namespace fabvdb::test {

struct TwoPieceMold {
    const Mesh& top;
    const Mesh& bottom;
    const Mesh& channels;  //!< runner, sprue and vents as one solid
};

void check_two_piece_mold(const Mesh& part, const Vec3& d, const TwoPieceMold& mold);

}  // namespace fabvdb::test
