//! CSG difference with capped cylinders (see drill_holes.h).
#include "volume/drill_holes.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <openvdb/tools/Prune.h>

#include "core/error.h"

namespace fabvdb::volume {

namespace {

//! Signed distance to a capped cylinder (negative inside).
double cylinder_distance(const openvdb::Vec3d& p, const openvdb::Vec3d& a, const openvdb::Vec3d& axis, double length,
                         double radius) {
    const openvdb::Vec3d v = p - a;
    const double t = v.dot(axis);
    const double across = (v - t * axis).length() - radius;
    const double along = std::max(-t, t - length);
    const double outside = std::hypot(std::max(across, 0.0), std::max(along, 0.0));
    return outside + std::min(std::max(across, along), 0.0);
}

}  // namespace

openvdb::FloatGrid::Ptr drill_holes(const openvdb::FloatGrid& solid, const std::vector<DrillCylinder>& cylinders,
                                    Progress& progress) {
    progress.stage("drill");
    openvdb::FloatGrid::Ptr drilled = solid.deepCopy();
    const float background = solid.background();
    const double voxel = solid.voxelSize()[0];
    auto accessor = drilled->getAccessor();
    for (size_t c = 0; c < cylinders.size(); ++c) {
        progress.update(double(c) / double(cylinders.size()));
        const DrillCylinder& cylinder = cylinders[c];
        const openvdb::Vec3d a(cylinder.start[0], cylinder.start[1], cylinder.start[2]);
        const openvdb::Vec3d b(cylinder.end[0], cylinder.end[1], cylinder.end[2]);
        const double length = (b - a).length();
        if (!(length > 0.0) || !(cylinder.radius > 0.0))
            throw Error(FABVDB_ERR_INVALID_ARGUMENT, "drill " + std::to_string(c + 1) + " of " +
                                                         std::to_string(cylinders.size()) + " has length " +
                                                         std::to_string(length) + " mm and radius " +
                                                         std::to_string(cylinder.radius) +
                                                         " mm: a drill needs a length and a positive radius");
        const openvdb::Vec3d axis = (b - a) / length;
        const double reach = cylinder.radius + double(background) + voxel;
        openvdb::Vec3d lo = openvdb::math::minComponent(a, b) - openvdb::Vec3d(reach);
        openvdb::Vec3d hi = openvdb::math::maxComponent(a, b) + openvdb::Vec3d(reach);
        const openvdb::Coord min = openvdb::Coord::floor(drilled->worldToIndex(lo));
        const openvdb::Coord max = openvdb::Coord::ceil(drilled->worldToIndex(hi));
        for (int x = min.x(); x <= max.x(); ++x)
            for (int y = min.y(); y <= max.y(); ++y)
                for (int z = min.z(); z <= max.z(); ++z) {
                    const openvdb::Coord ijk(x, y, z);
                    const double hole = cylinder_distance(drilled->indexToWorld(ijk), a, axis, length, cylinder.radius);
                    const float before = accessor.getValue(ijk);
                    const float after = std::max(before, float(-hole));
                    if (after == before) continue;
                    if (std::abs(after) < background)
                        accessor.setValueOn(ijk, after);
                    else
                        accessor.setValueOff(ijk, after > 0 ? background : -background);
                }
        progress.check();
    }
    openvdb::tools::pruneLevelSet(drilled->tree());
    progress.update(1.0);
    return drilled;
}

}  // namespace fabvdb::volume
