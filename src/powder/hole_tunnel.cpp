//! Drain-hole tunnels and crater cones (see hole_tunnel.h).
#include "powder/hole_tunnel.h"

namespace fabvdb::powder {

namespace {


//! Unit direction down the plane of the hole's mouth (gravity less its part
//! along the axis); zero when the axis is vertical.
Vec3 down_the_mouth(const DrainHole& hole, const Vec3& gravity) {
    const double along = dot(hole.axis, gravity);
    const Vec3 down{gravity[0] - along * hole.axis[0], gravity[1] - along * hole.axis[1],
                    gravity[2] - along * hole.axis[2]};
    const double length = std::sqrt(dot(down, down));
    if (!(length > 1e-12)) return {0, 0, 0};
    return {down[0] / length, down[1] / length, down[2] / length};
}

//! Whether the tunnel is steeper than the angle of repose for `gravity`.
bool steep(const DrainHole& hole, const Vec3& gravity, double repose_radians) {
    return dot(hole.axis, gravity) > std::sin(repose_radians);
}

//! The lowest point of the hole's outer mouth for `gravity`.
Vec3 outer_lip(const DrainHole& hole, const Vec3& gravity) {
    const Vec3 down = down_the_mouth(hole, gravity);
    const double radius = 0.5 * hole.diameter;
    Vec3 lip;
    for (int k = 0; k < 3; ++k) lip[k] = hole.center[k] + radius * down[k] + hole.through * hole.axis[k];
    return lip;
}

}  // namespace

bool passes_powder(const DrainHole& hole, const Vec3& gravity, double repose_radians) {
    if (steep(hole, gravity, repose_radians)) return true;
    // The slope of repose from the outer lip must meet the inner mouth below its top.
    const Vec3 down = down_the_mouth(hole, gravity);
    const double radius = 0.5 * hole.diameter;
    const Vec3 top{hole.center[0] - radius * down[0], hole.center[1] - radius * down[1],
                   hole.center[2] - radius * down[2]};
    const auto [rise, across] = rise_and_across(top, outer_lip(hole, gravity), gravity);
    return rise > std::tan(repose_radians) * across;
}

CraterCone crater_cone(const DrainHole& hole, const Vec3& gravity, double repose_radians) {
    CraterCone result;
    result.gravity = gravity;
    result.tan_repose = std::tan(repose_radians);
    if (steep(hole, gravity, repose_radians)) {
        // The crater's cone of repose rises from the rim of the mouth, not its centre.
        result.apex = hole.center;
        result.mouth = 0.5 * hole.diameter;
    } else {
        result.apex = outer_lip(hole, gravity);
    }
    return result;
}

}  // namespace fabvdb::powder
