//! Spacing between drain holes (see drain_hole.h).
#include "powder/drain_hole.h"

#include <cmath>

#include "core/vec3_ops.h"

namespace fabvdb::powder {

bool spaced_from(const DrainHole& candidate, const std::vector<DrainHole>& holes, double min_center_distance) {
    for (const DrainHole& hole : holes) {
        const Vec3 v{candidate.center[0] - hole.center[0], candidate.center[1] - hole.center[1],
                     candidate.center[2] - hole.center[2]};
        if (std::sqrt(dot(v, v)) < min_center_distance) return false;
    }
    return true;
}

}  // namespace fabvdb::powder
