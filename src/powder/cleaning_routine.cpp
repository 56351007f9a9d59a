//! A cleaning routine in words (see cleaning_routine.h).
#include "powder/cleaning_routine.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/vec3_ops.h"

namespace fabvdb::powder {

namespace {

//! A hole points down when its axis lies within this angle of gravity.
const double kDownCosine = std::cos(60.0 * M_PI / 180.0);

std::string format(const char* pattern, double a, double b = 0, double c = 0, double d = 0) {
    char text[160];
    std::snprintf(text, sizeof text, pattern, a, b, c, d);
    return text;
}

}  // namespace

std::vector<CleaningStep> cleaning_steps(const std::vector<DrainHole>& holes, const Vec3& first_gravity,
                                         const std::vector<Vec3>& later_gravities) {
    std::vector<Vec3> gravities{first_gravity};
    gravities.insert(gravities.end(), later_gravities.begin(), later_gravities.end());
    std::vector<CleaningStep> steps;
    for (size_t t = 0; t < gravities.size(); ++t) {
        CleaningStep step;
        step.gravity = gravities[t];
        double best = kDownCosine, lowest = -INFINITY;
        for (size_t h = 0; h < holes.size(); ++h) {
            const double along = dot(holes[h].axis, step.gravity);
            if (along >= best) {
                best = along;
                step.hole_down = int(h);
            }
            const double depth = dot(holes[h].center, step.gravity);
            if (depth > lowest) {
                lowest = depth;
                step.lowest_hole = int(h);
            }
        }
        std::string where;
        if (step.hole_down >= 0)
            where = format("hole %.0f points down", step.hole_down + 1.0);
        else if (step.lowest_hole >= 0)
            where = format("no hole points down; hole %.0f is lowest", step.lowest_hole + 1.0);
        if (t == 0) {
            step.instruction = "as printed: " + where + "; let the loose powder run out";
        } else {
            const Vec3& previous = gravities[t - 1];
            const double cosine = std::clamp(dot(previous, step.gravity), -1.0, 1.0);
            step.tilt_degrees = std::acos(cosine) * 180.0 / M_PI;
            Vec3 axis = cross(previous, step.gravity);
            const double length = std::sqrt(dot(axis, axis));
            if (length > 1e-9) axis = {axis[0] / length, axis[1] / length, axis[2] / length};
            else axis = {0, 0, 0};
            step.tilt_axis = axis;
            if (step.tilt_degrees < 0.5)
                step.instruction = "keep the part as it is, tap it; " + where;
            else if (length <= 1e-9)
                step.instruction = "turn the part upside down; " + where;
            else
                step.instruction = format("tilt the part %.0f deg about its axis (%.2f, %.2f, %.2f); ",
                                          step.tilt_degrees, axis[0], axis[1], axis[2]) +
                                   where;
        }
        steps.push_back(step);
    }
    return steps;
}

}  // namespace fabvdb::powder
