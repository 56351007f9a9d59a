//! How powder meets a drain hole for one gravity direction, with powder of
//! angle of repose θ_r: whether the hole's tunnel lets it out, and the cone
//! of repose its crater leaves in the cavity.
//! - A tunnel steeper than θ_r (axis within 90° − θ_r of gravity) passes
//!   whatever reaches it; its crater's cone rises with slope θ_r from the rim
//!   of the mouth, and inside the mouth powder drains down to one radius
//!   below the centre.
//! - A flatter tunnel holds a slope of repose rising from its outer lip (the
//!   lowest point of the outer mouth): it passes powder when that slope
//!   meets the inner mouth below its top, and the cone rises from the lip.
//! Pure functions, O(1); the derivation is in docs/design/drainability.md.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/mesh.h"
#include "powder/drain_hole.h"
#include "core/vec3_ops.h"

namespace fabvdb::powder {

//! Height of `point` along −gravity above `from`, and its horizontal distance from it.
inline std::pair<double, double> rise_and_across(const Vec3& point, const Vec3& from, const Vec3& gravity) {
    const Vec3 v{point[0] - from[0], point[1] - from[1], point[2] - from[2]};
    const double rise = -dot(v, gravity);
    return {rise, std::sqrt(std::max(0.0, dot(v, v) - rise * rise))};
}

//! Whether powder can leave through the hole's tunnel for `gravity` (unit).
bool passes_powder(const DrainHole& hole, const Vec3& gravity, double repose_radians);

//! The cone of repose a hole's crater leaves for one gravity: powder under
//! it stays, powder above it can drain.
struct CraterCone {
    Vec3 apex{0, 0, 0}, gravity{0, 0, -1};
    double mouth = 0.0;  //!< the radius of the flat top at the apex (a steep tunnel's mouth), else 0
    double tan_repose = 0.0;
    //! Whether powder at `point` stays (under the cone).
    bool below(const Vec3& point) const;
};

CraterCone crater_cone(const DrainHole& hole, const Vec3& gravity, double repose_radians);

// Inline: the walks up the sample chains call it for every sample.
inline bool CraterCone::below(const Vec3& point) const {
    const Vec3 v{point[0] - apex[0], point[1] - apex[1], point[2] - apex[2]};
    const double rise = -dot(v, gravity);
    const double across_squared = std::max(0.0, dot(v, v) - rise * rise);
    if (across_squared <= mouth * mouth) return rise < -mouth;
    if (rise < 0.0) return true;
    const double reach = rise / tan_repose + mouth;  // the cone's radius at this height
    return reach * reach < across_squared;
}

}  // namespace fabvdb::powder
