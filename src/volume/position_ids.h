//! Welding by position, the first step of reading any input: every vertex
//! gets the id of its position, where positions are equal when all three
//! coordinates compare equal as doubles (-0.0 is 0.0; no tolerance) and ids
//! number the distinct positions 0, 1, ... in increasing lexicographic order,
//! so comparing two ids compares their positions. weld_positions renumbers a
//! mesh to them. Costs one parallel sort of the vertex indices (TBB); pure.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::volume {

struct PositionIds {
    std::vector<uint32_t> id;  // per vertex
    uint32_t count = 0;        // distinct positions
};

PositionIds position_ids(const Mesh& mesh);

//! One vertex per distinct position, in the order of their ids, and the
//! triangles renumbered to them (kept as they are, also those that become
//! degenerate).
Mesh weld_positions(const Mesh& mesh);

}  // namespace fabvdb::volume
