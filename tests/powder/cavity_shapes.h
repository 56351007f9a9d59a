//! Hollow test parts as level sets with known cavities, shared by the powder
//! tests: a hollow sphere and two separate hollow spheres. Each gives the part (negative inside, cavity
//! included), its cavity (negative inside the cavity) and the shell (negative
//! in the wall) = part minus cavity.
#pragma once

#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/LevelSetSphere.h>

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

}  // namespace fabvdb::test
