//! Gyroid strut infill carved out of a cavity level set (see gyroid_infill.h).
#include "volume/gyroid_infill.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <openvdb/tools/Composite.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "core/error.h"
#include "volume/memory_estimate.h"

namespace fabvdb::volume {

namespace {

using openvdb::Vec3d;

//! Band half width of the strut distances, in voxels.
constexpr int kHalfBand = 3;

struct Segment {
    Vec3d a, b;
};

double gyroid(const Vec3d& p) {
    return std::sin(p.x()) * std::cos(p.y()) + std::sin(p.y()) * std::cos(p.z()) + std::sin(p.z()) * std::cos(p.x());
}

bool lexicographically_positive(const Vec3d& d) {
    for (int k = 0; k < 3; ++k)
        if (std::abs(d[k]) > 1e-9) return d[k] > 0.0;
    return false;
}

//! The struts of one cell of side 1: the nodes are the points of the 1/8
//! lattice where the gyroid (period 1) reaches its maximum 3/2; each node
//! joins its three nearest nodes (at √2/4, periodic images included); each
//! strut is listed once, from the node it leaves in a lexicographically
//! positive direction.
std::vector<Segment> unit_cell_struts() {
    std::vector<Vec3d> nodes;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j)
            for (int k = 0; k < 8; ++k) {
                const Vec3d p(i / 8.0, j / 8.0, k / 8.0);
                if (gyroid(p * (2.0 * M_PI)) > 1.5 - 1e-9) nodes.push_back(p);
            }
    const double length = std::sqrt(2.0) / 4.0;
    std::vector<Segment> struts;
    for (const Vec3d& from : nodes)
        for (const Vec3d& node : nodes)
            for (int dx = -1; dx <= 1; ++dx)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dz = -1; dz <= 1; ++dz) {
                        const Vec3d to = node + Vec3d(dx, dy, dz);
                        if (std::abs((to - from).length() - length) < 1e-9 && lexicographically_positive(to - from))
                            struts.push_back({from, to});
                    }
    return struts;
}

double distance_to_segment(const Vec3d& p, const Segment& s) {
    const Vec3d ab = s.b - s.a;
    const double t = std::clamp((p - s.a).dot(ab) / ab.lengthSqr(), 0.0, 1.0);
    return (p - (s.a + ab * t)).length();
}

}  // namespace

void validate_gyroid_struts(const GyroidStruts& lattice) {
    if (!(std::isfinite(lattice.cell) && lattice.cell > 0.0))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "infill cell must be > 0 mm");
    if (!(std::isfinite(lattice.strut) && lattice.strut > 0.0))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "infill strut must be > 0 mm");
    if (lattice.strut > lattice.cell / 4.0)
        throw Error(FABVDB_ERR_INVALID_ARGUMENT,
                    "infill strut must be at most a quarter of the cell (wider struts close the open cells)");
}

uint64_t estimate_gyroid_struts_bytes(const GyroidStruts& lattice, double cavity_volume, double voxel_size) {
    const double cells = cavity_volume / (lattice.cell * lattice.cell * lattice.cell);
    const double strut_area = 12.0 * M_PI * lattice.strut * (std::sqrt(2.0) / 4.0 * lattice.cell);
    return estimate_level_set_bytes(cells * strut_area, voxel_size, kHalfBand);
}

openvdb::FloatGrid::Ptr carve_gyroid_struts(const openvdb::FloatGrid& cavity, const GyroidStruts& lattice,
                                            Progress& progress) {
    validate_gyroid_struts(lattice);
    progress.stage("gyroid infill");
    const openvdb::math::Transform& transform = cavity.transform();
    const double voxel = cavity.voxelSize()[0];
    const double radius = 0.5 * lattice.strut;
    const double band = kHalfBand * voxel;
    const double reach = radius + band;

    // The struts of every cell that the cavity's band box reaches.
    const openvdb::CoordBBox box = cavity.evalActiveVoxelBoundingBox();
    const Vec3d lo = transform.indexToWorld(box.min()) - Vec3d(reach);
    const Vec3d hi = transform.indexToWorld(box.max()) + Vec3d(reach);
    const std::vector<Segment> unit = unit_cell_struts();
    std::vector<Segment> struts;
    for (int i = int(std::floor(lo.x() / lattice.cell)) - 1; i <= int(std::floor(hi.x() / lattice.cell)); ++i)
        for (int j = int(std::floor(lo.y() / lattice.cell)) - 1; j <= int(std::floor(hi.y() / lattice.cell)); ++j)
            for (int k = int(std::floor(lo.z() / lattice.cell)) - 1; k <= int(std::floor(hi.z() / lattice.cell));
                 ++k)
                for (const Segment& s : unit) {
                    const Segment placed{(s.a + Vec3d(i, j, k)) * lattice.cell, (s.b + Vec3d(i, j, k)) * lattice.cell};
                    const Vec3d low = openvdb::math::minComponent(placed.a, placed.b) - Vec3d(reach);
                    const Vec3d high = openvdb::math::maxComponent(placed.a, placed.b) + Vec3d(reach);
                    if (low.x() <= hi.x() && low.y() <= hi.y() && low.z() <= hi.z() && high.x() >= lo.x() &&
                        high.y() >= lo.y() && high.z() >= lo.z())
                        struts.push_back(placed);
                }

    // Distance to the struts minus the radius, clamped to the band, in the
    // voxels where the cavity could gain a surface (at most a band outside it).
    tbb::enumerable_thread_specific<openvdb::FloatGrid::Ptr> partial([&] {
        openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(float(band));
        grid->setTransform(transform.copy());
        return grid;
    });
    tbb::parallel_for(tbb::blocked_range<size_t>(0, struts.size(), 16), [&](const tbb::blocked_range<size_t>& range) {
        openvdb::FloatGrid::Accessor out = partial.local()->getAccessor();
        openvdb::FloatGrid::ConstAccessor in = cavity.getConstAccessor();
        for (size_t n = range.begin(); n != range.end(); ++n) {
            if (progress.cancelled()) return;
            const Segment& s = struts[n];
            const openvdb::Coord first = transform.worldToIndexCellCentered(
                openvdb::math::minComponent(s.a, s.b) - Vec3d(reach));
            const openvdb::Coord last = transform.worldToIndexCellCentered(
                openvdb::math::maxComponent(s.a, s.b) + Vec3d(reach));
            for (openvdb::Coord c = first; c.x() <= last.x(); ++c.x())
                for (c.y() = first.y(); c.y() <= last.y(); ++c.y())
                    for (c.z() = first.z(); c.z() <= last.z(); ++c.z()) {
                        const double d = distance_to_segment(transform.indexToWorld(c), s) - radius;
                        if (d >= band || in.getValue(c) >= band) continue;
                        const float value = float(std::max(d, -band));
                        if (value < out.getValue(c)) out.setValue(c, value);
                    }
        }
    });
    progress.check();
    openvdb::FloatGrid::Ptr strut_distance;
    for (openvdb::FloatGrid::Ptr& grid : partial) {
        if (!strut_distance)
            strut_distance = grid;
        else
            openvdb::tools::compMin(*strut_distance, *grid);
    }
    progress.update(0.8);

    openvdb::FloatGrid::Ptr carved = cavity.deepCopy();
    if (strut_distance) {
        openvdb::FloatGrid::Accessor out = carved->getAccessor();
        for (auto it = strut_distance->cbeginValueOn(); it; ++it)
            out.setValue(it.getCoord(), std::max(out.getValue(it.getCoord()), -*it));
    }
    progress.update(1.0);
    return carved;
}

}  // namespace fabvdb::volume
