//! Cavity patches (powder/cavity_patches.h) given by hand, for the powder
//! tests whose flows are worked out by hand: each patch's centroid (also its
//! site), normal into the cavity, area and neighbours, all on one cavity; and
//! the box room x ∈ [-5, 5], y ∈ [-3, 3], z ∈ [0, 8] with a patch per face of
//! make_box (two triangles each, in make_box's order of faces).
#pragma once

#include <vector>

#include "powder/cavity_patches.h"

namespace fabvdb::test {

struct HandPatch {
    Vec3 centroid, normal;
    double area;
    std::vector<powder::PatchNeighbour> neighbours;
};

inline powder::CavityPatches hand_patches(const std::vector<HandPatch>& list, std::vector<uint32_t> of_triangle) {
    powder::CavityPatches patches;
    for (const HandPatch& p : list) {
        patches.centroid.push_back(p.centroid);
        patches.site.push_back(p.centroid);
        patches.normal.push_back(p.normal);
        patches.area.push_back(p.area);
        patches.cavity.push_back(0);
        patches.neighbours.push_back(p.neighbours);
    }
    patches.cavity_count = 1;
    patches.patch_of_triangle = std::move(of_triangle);
    return patches;
}

enum RoomFace : uint32_t { kFloor, kCeiling, kFront, kBack, kLeft, kRight };

//! The room's patches (the room's mesh: make_box({-5, -3, 0}, {5, 3, 8})).
inline powder::CavityPatches room_patches() {
    return hand_patches({{{0, 0, 0}, {0, 0, 1}, 60, {{kFront, 10}, {kBack, 10}, {kLeft, 6}, {kRight, 6}}},
                         {{0, 0, 8}, {0, 0, -1}, 60, {{kFront, 10}, {kBack, 10}, {kLeft, 6}, {kRight, 6}}},
                         {{0, -3, 4}, {0, 1, 0}, 80, {{kFloor, 10}, {kCeiling, 10}, {kLeft, 8}, {kRight, 8}}},
                         {{0, 3, 4}, {0, -1, 0}, 80, {{kFloor, 10}, {kCeiling, 10}, {kLeft, 8}, {kRight, 8}}},
                         {{-5, 0, 4}, {1, 0, 0}, 48, {{kFloor, 6}, {kCeiling, 6}, {kFront, 8}, {kBack, 8}}},
                         {{5, 0, 4}, {-1, 0, 0}, 48, {{kFloor, 6}, {kCeiling, 6}, {kFront, 8}, {kBack, 8}}}},
                        {0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5});
}

}  // namespace fabvdb::test
