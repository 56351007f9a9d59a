//! fit_build_volume: the six assignments of sides to axes, as placed first.
#include "check/build_fit.h"

#include <algorithm>

namespace fabvdb::check {

BuildFit fit_build_volume(const Vec3& size, const Vec3& volume) {
    BuildFit fit;
    std::array<int, 3> axes{0, 1, 2};
    do {
        if (size[axes[0]] <= volume[0] && size[axes[1]] <= volume[1] && size[axes[2]] <= volume[2]) {
            fit.turned = true;
            fit.axes = axes;
            fit.as_placed = axes == std::array<int, 3>{0, 1, 2};
            return fit;
        }
    } while (std::next_permutation(axes.begin(), axes.end()));
    return fit;
}

}  // namespace fabvdb::check
