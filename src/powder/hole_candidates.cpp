//! Candidate drain-hole sites (see hole_candidates.h).
#include "powder/hole_candidates.h"

#include <cmath>
#include <optional>

#include <Eigen/Geometry>
#include <openvdb/tools/Interpolation.h>
#include <tbb/parallel_for.h>

namespace fabvdb::powder {

namespace {

using Sampler = openvdb::tools::GridSampler<openvdb::FloatGrid::ConstAccessor, openvdb::tools::BoxSampler>;

Eigen::Vector3d point(const Vec3& p) { return {p[0], p[1], p[2]}; }
Vec3 vec(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }
double at(const Sampler& sampler, const Eigen::Vector3d& p) { return sampler.wsSample(openvdb::Vec3d(p.x(), p.y(), p.z())); }

//! Distance along one drill line from its start to where it leaves the wall
//! into the outside, or nothing if the line does not pass cleanly.
std::optional<double> clean_exit(const Sampler& shell, const Sampler& part, const Eigen::Vector3d& start,
                                 const Eigen::Vector3d& axis, double step, double min_wall, double max_wall,
                                 double lead_in, double clearance) {
    double t = 0.0;
    while (at(shell, start + t * axis) > 0.0) {  // still in the cavity
        if (at(part, start + t * axis) > 0.0) return std::nullopt;
        t += step;
        if (t > lead_in) return std::nullopt;
    }
    const double entry = t;
    while (at(shell, start + t * axis) <= 0.0) {
        t += step;
        if (t - entry > max_wall) return std::nullopt;
    }
    if (t - entry < min_wall) return std::nullopt;
    const double exit = t;
    for (; t <= exit + clearance; t += step) {
        const Eigen::Vector3d p = start + t * axis;
        if (at(shell, p) <= 0.0 || at(part, p) <= 0.0) return std::nullopt;
    }
    return exit;
}

}  // namespace

std::vector<DrainHole> hole_candidates(const CavityPatches& patches, const openvdb::FloatGrid& shell,
                                       const openvdb::FloatGrid& part, const KeepOut& keep_out,
                                       const HoleCandidateOptions& options, Progress& progress) {
    progress.stage("hole candidates");
    const double radius = 0.5 * options.diameter;
    const double step = 0.5 * shell.voxelSize()[0];
    const size_t n = patches.size();
    std::vector<std::optional<DrainHole>> found(n);
    tbb::parallel_for(size_t(0), n, [&](size_t i) {
        if (progress.cancelled()) return;
        const openvdb::FloatGrid::ConstAccessor shell_accessor = shell.getConstAccessor();
        const openvdb::FloatGrid::ConstAccessor part_accessor = part.getConstAccessor();
        const Sampler shell_sampler(shell_accessor, shell.transform());
        const Sampler part_sampler(part_accessor, part.transform());
        const Eigen::Vector3d center = point(patches.site[i]);
        const Eigen::Vector3d axis = -point(patches.normal[i]);
        // Lines start one radius back in the cavity, so curved walls are entered.
        const Eigen::Vector3d back = center - radius * axis;
        const auto axis_exit = clean_exit(shell_sampler, part_sampler, back, axis, step, 0.5 * options.nominal_wall,
                                          2.0 * options.nominal_wall, 2.0 * radius + step, options.diameter);
        if (!axis_exit) return;
        const Eigen::Vector3d e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
        for (int k = 0; k < 6; ++k) {
            const double phi = M_PI * k / 3.0;
            const Eigen::Vector3d rim = back + radius * (std::cos(phi) * e1 + std::sin(phi) * e2);
            if (!clean_exit(shell_sampler, part_sampler, rim, axis, step, 0.0, 2.0 * options.nominal_wall + radius,
                            3.0 * radius + step, options.diameter))
                return;
        }
        const double through = *axis_exit - radius;  // from the site to the outer surface
        const Eigen::Vector3d outer = center + through * axis;
        if (keep_out.touches(patches.site[i], radius) || keep_out.touches(vec(outer), radius) ||
            keep_out.touches(vec(0.5 * (center + outer)), radius))
            return;
        DrainHole hole;
        hole.patch = uint32_t(i);
        hole.center = patches.site[i];
        hole.axis = vec(axis);
        hole.diameter = options.diameter;
        hole.depth = through + options.diameter;
        hole.through = through;
        hole.cavity = patches.cavity[i];
        found[i] = hole;
    });
    progress.check();
    std::vector<DrainHole> candidates;
    for (const auto& hole : found)
        if (hole) candidates.push_back(*hole);
    progress.update(1.0);
    return candidates;
}

}  // namespace fabvdb::powder
