//! Hollow test parts as level sets with known cavities, shared by the powder
//! tests: a hollow sphere, two separate hollow spheres, a box cavity with
//! a raised shelf that has a pocket (a well) sunk into it, and a shaft
//! behind a long flat tube. Each gives the part
//! (negative inside, cavity included), its cavity (negative inside the cavity)
//! and the shell (negative in the wall) = part minus cavity.
#pragma once

#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <openvdb/tools/MeshToVolume.h>

#include "core/mesh.h"

namespace fabvdb::test {

struct HollowPart {
    openvdb::FloatGrid::Ptr part, cavity, shell;
};

inline HollowPart finish(openvdb::FloatGrid::Ptr part, openvdb::FloatGrid::Ptr cavity) {
    HollowPart result;
    result.part = part;
    result.cavity = cavity;
    result.shell = openvdb::tools::csgDifferenceCopy(*part, *cavity);
    return result;
}

inline HollowPart hollow_sphere(const Vec3& center, double radius, double wall, double voxel) {
    openvdb::initialize();
    const openvdb::Vec3f c{float(center[0]), float(center[1]), float(center[2])};
    return finish(openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(float(radius), c, float(voxel)),
                  openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(float(radius - wall), c, float(voxel)));
}

//! Two hollow spheres side by side, apart.
inline HollowPart two_hollow_spheres(double radius, double wall, double voxel) {
    HollowPart a = hollow_sphere({0, 0, 0}, radius, wall, voxel);
    HollowPart b = hollow_sphere({2.5 * radius, 0, 0}, radius, wall, voxel);
    openvdb::tools::csgUnion(*a.part, *b.part);
    openvdb::tools::csgUnion(*a.cavity, *b.cavity);
    return finish(a.part, a.cavity);
}

//! A box-shaped level set with corners `lo` and `hi`.
inline openvdb::FloatGrid::Ptr box(const Vec3& lo, const Vec3& hi, double voxel) {
    const openvdb::Vec3s low{float(lo[0]), float(lo[1]), float(lo[2])}, high{float(hi[0]), float(hi[1]), float(hi[2])};
    const openvdb::math::BBox<openvdb::Vec3s> bounds{low, high};
    return openvdb::tools::createLevelSetBox<openvdb::FloatGrid>(
        bounds, *openvdb::math::Transform::createLinearTransform(voxel));
}

//! The pocket of `shelf_with_pocket`: powder in it stays in the first turn
//! unless a hole opens in it, since it lies above the main floor.
struct Pocket {
    Vec3 lo{6, -5, 4}, hi{14, 5, 10};
};

//! A cavity made of boxes, with a wall `wall` all round (every box grown by it).
inline HollowPart boxes_cavity(const std::vector<std::pair<Vec3, Vec3>>& rooms, double wall, double voxel) {
    openvdb::FloatGrid::Ptr cavity, part;
    for (const auto& [lo, hi] : rooms) {
        auto room = box(lo, hi, voxel);
        auto grown = box({lo[0] - wall, lo[1] - wall, lo[2] - wall}, {hi[0] + wall, hi[1] + wall, hi[2] + wall}, voxel);
        if (!cavity) {
            cavity = room;
            part = grown;
        } else {
            openvdb::tools::csgUnion(*cavity, *room);
            openvdb::tools::csgUnion(*part, *grown);
        }
    }
    return finish(part, cavity);
}

//! A shaft x ∈ [-12, 0], y ∈ [-6, 6], z ∈ [-20, 11] whose top opens into a
//! flat tube 3 mm high running to x = 30 (y ∈ [-3, 3], z ∈ [8, 11]).
//! Turned upside down (gravity +z), a hole on top of the tube's far end
//! drains the tube only as far as the slope of repose reaches (3 / tan θ_r
//! ≈ 4 mm at 35°): the powder beyond plugs the tube and holds the shaft.
inline HollowPart shaft_behind_flat_tube(double wall, double voxel) {
    openvdb::initialize();
    return boxes_cavity({{{-12, -6, -20}, {0, 6, 11}}, {{-0.5, -3, 8}, {30, 3, 11}}}, wall, voxel);
}

//! A cavity (wall `wall` all round, every box of the cavity grown by it) made
//! of a main room x ∈ [-16, 16], y ∈ [-8, 8], z ∈ [0, 20] whose floor rises
//! to a shelf at z = 10 for x > 4, and the Pocket sunk into the shelf.
inline HollowPart shelf_with_pocket(double wall, double voxel) {
    openvdb::initialize();
    const Pocket pocket;
    return boxes_cavity(
        {{{-16, -8, 0}, {4, 8, 20}}, {{4, -8, 10}, {16, 8, 20}}, {pocket.lo, {pocket.hi[0], pocket.hi[1], 10.5}}}, wall,
        voxel);
}

}  // namespace fabvdb::test
