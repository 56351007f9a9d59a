//! T(g) of the drainability model (see transfer_matrix.h).
#include "powder/transfer_matrix.h"

#include <cmath>

#include <Eigen/Geometry>

namespace fabvdb::powder {

namespace {

Eigen::Vector3d point(const Vec3& p) { return {p[0], p[1], p[2]}; }
Vec3 vec(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

}  // namespace

StochasticMatrix transfer_matrix(const CavityPatches& patches, const volume::SurfaceRayCaster& caster, const Vec3& gravity,
                                 const TransferOptions& options) {
    const Eigen::Vector3d g = point(gravity).normalized();
    const double floor_cosine = std::cos(options.repose_radians);
    const size_t n = patches.size();
    std::vector<double> height(n);
    for (size_t i = 0; i < n; ++i) height[i] = -point(patches.centroid[i]).dot(g);

    // The cone of fall directions around g.
    const Eigen::Vector3d e1 = g.unitOrthogonal(), e2 = g.cross(e1);
    std::vector<Eigen::Vector3d> fall{g};
    for (int k = 1; k < options.cone_rays; ++k) {
        const double phi = 2.0 * M_PI * (k - 1) / double(options.cone_rays - 1);
        fall.push_back(std::cos(options.cone_half_angle_radians) * g +
                       std::sin(options.cone_half_angle_radians) * (std::cos(phi) * e1 + std::sin(phi) * e2));
    }

    StochasticMatrix matrix;
    matrix.row_start.reserve(n + 1);
    std::vector<std::pair<uint32_t, double>> row;
    for (uint32_t i = 0; i < n; ++i) {
        row.clear();
        const Eigen::Vector3d normal = point(patches.normal[i]);
        const double up = -normal.dot(g);
        if (up < floor_cosine && up > 0.0) {
            const Eigen::Vector3d from = point(patches.centroid[i]);
            for (const PatchNeighbour& neighbour : patches.neighbours[i]) {
                const double drop = height[i] - height[neighbour.patch];
                if (drop <= 0.0) continue;
                const double run = (point(patches.centroid[neighbour.patch]) - from).norm();
                row.push_back({neighbour.patch, neighbour.shared_length * drop / run});
            }
        } else if (up <= 0.0) {
            const Eigen::Vector3d origin =
                point(patches.site[i]) + 0.05 * std::sqrt(patches.area[i]) * normal;
            for (const Eigen::Vector3d& direction : fall) {
                const int64_t hit = caster.first_hit(vec(origin), vec(direction), HUGE_VAL);
                if (hit < 0) continue;
                const uint32_t j = patches.patch_of_triangle[size_t(hit)];
                if (height[j] < height[i]) row.push_back({j, 1.0});
            }
        }
        double total = 0.0;
        for (const auto& entry : row) total += entry.second;
        if (row.empty() || !(total > 0.0)) {
            matrix.column.push_back(i);
            matrix.weight.push_back(1.0f);
        } else {
            for (const auto& [j, w] : row) {
                matrix.column.push_back(j);
                matrix.weight.push_back(float(w / total));
            }
        }
        matrix.row_start.push_back(uint32_t(matrix.column.size()));
    }
    return matrix;
}

}  // namespace fabvdb::powder
