//! The frame aligned with a direction (see aligned_frame.h).
#include "volume/aligned_frame.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/vec3_ops.h"

namespace fabvdb::volume {

namespace {

//! v over its length; scaled by its largest coordinate first, so lengths
//! whose square under- or overflows a double are fine.
Vec3 normalized_without_overflow(const Vec3& v) {
    const double largest = std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
    const Vec3 scaled{v[0] / largest, v[1] / largest, v[2] / largest};
    const double length = std::sqrt(dot(scaled, scaled));
    return {scaled[0] / length, scaled[1] / length, scaled[2] / length};
}

}  // namespace

Vec3 AlignedFrame::to_frame(const Vec3& world) const { return {dot(world, e1), dot(world, e2), dot(world, d)}; }

Vec3 AlignedFrame::to_world(const Vec3& local) const {
    Vec3 world;
    for (int k = 0; k < 3; ++k) world[k] = local[0] * e1[k] + local[1] * e2[k] + local[2] * d[k];
    return world;
}

AlignedFrame aligned_frame(const Vec3& direction) {
    const double largest = std::max({std::abs(direction[0]), std::abs(direction[1]), std::abs(direction[2])});
    if (!std::isfinite(direction[0]) || !std::isfinite(direction[1]) || !std::isfinite(direction[2]) ||
        largest == 0.0)
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the parting direction must be a finite non-zero vector");
    AlignedFrame frame;
    frame.d = normalized_without_overflow(direction);
    int least = 0;
    for (int k = 1; k < 3; ++k)
        if (std::abs(frame.d[k]) < std::abs(frame.d[least])) least = k;
    Vec3 axis{0, 0, 0};
    axis[least] = 1.0;
    frame.e1 = normalized_without_overflow(cross(axis, frame.d));
    frame.e2 = cross(frame.d, frame.e1);
    return frame;
}

Mesh rotate_mesh(const Mesh& mesh, const AlignedFrame& frame, bool inverse) {
    Mesh out = mesh;
    for (Vec3& p : out.vertices) p = inverse ? frame.to_world(p) : frame.to_frame(p);
    return out;
}

}  // namespace fabvdb::volume
