// A level set by OpenVDB's meshToLevelSet (see plain_level_set.h).
#include "support/plain_level_set.h"

#include <openvdb/tools/MeshToVolume.h>

namespace fabvdb::test {

openvdb::FloatGrid::Ptr plain_level_set(const Mesh& mesh, double voxel) {
    return plain_level_set(mesh, *openvdb::math::Transform::createLinearTransform(voxel));
}

namespace {

openvdb::FloatGrid::Ptr level_set(const Mesh& mesh, const openvdb::math::Transform& transform, float half_width) {
    openvdb::initialize();
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    for (const Vec3& p : mesh.vertices) points.emplace_back(float(p[0]), float(p[1]), float(p[2]));
    for (const auto& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
    return openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(transform, points, triangles, half_width);
}

}  // namespace

openvdb::FloatGrid::Ptr plain_level_set(const Mesh& mesh, const openvdb::math::Transform& transform) {
    return level_set(mesh, transform, 3.0f);
}

openvdb::FloatGrid::Ptr plain_level_set(const Mesh& mesh, double voxel, double half_band) {
    return level_set(mesh, *openvdb::math::Transform::createLinearTransform(voxel), float(half_band / voxel));
}

}  // namespace fabvdb::test
