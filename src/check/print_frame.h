//! The print frame of a part standing on the plate: the shortest turn that
//! takes the build direction `up` (any length but zero) to +z, x and y
//! completing it. Pure.
#pragma once

#include <Eigen/Geometry>

#include "core/mesh.h"

namespace fabvdb::check {

inline Eigen::Matrix3d print_frame_turn(const Vec3& up) {
    const Eigen::Vector3d u = Eigen::Vector3d(up[0], up[1], up[2]).normalized();
    return Eigen::Quaterniond::FromTwoVectors(u, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

}  // namespace fabvdb::check
