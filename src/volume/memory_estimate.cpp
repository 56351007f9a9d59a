//! Memory estimate of a narrow-band level set (see memory_estimate.h).
#include "volume/memory_estimate.h"

#include <cmath>

namespace fabvdb::volume {

namespace {
// Peak bytes per active voxel, measured on the shared models (bench/repair):
// the float band and its leaf overhead (~10 B), OpenVDB's closest-triangle
// Int32 grid and intermediate masks (~14 B), the rebuilt band (~10 B).
constexpr double bytes_per_active_voxel = 48.0;
}  // namespace

double surface_area(const Mesh& mesh) {
    double area = 0.0;
    for (const Triangle& t : mesh.triangles) area += triangle_area(mesh, t);
    return area;
}

uint64_t estimate_active_voxels(double area, double voxel_size, int half_band_voxels) {
    return uint64_t(area / (voxel_size * voxel_size) * (2.0 * half_band_voxels + 1.0)) + 4096;
}

uint64_t estimate_level_set_bytes(double area, double voxel_size, int half_band_voxels) {
    return uint64_t(double(estimate_active_voxels(area, voxel_size, half_band_voxels)) * bytes_per_active_voxel);
}

double voxel_size_for_budget(double area, int half_band_voxels, uint64_t budget_bytes) {
    const double voxels = double(budget_bytes) / bytes_per_active_voxel - 4096.0;
    if (voxels <= 0.0 || area <= 0.0) return 0.0;
    const double exact = std::sqrt(area * (2.0 * half_band_voxels + 1.0) / voxels);
    const double scale = std::pow(10.0, std::floor(std::log10(exact)) - 1.0);
    return std::ceil(exact / scale) * scale;
}

}  // namespace fabvdb::volume
