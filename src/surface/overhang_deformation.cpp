//! Overhang removal by ARAP deformation (see overhang_deformation.h).
#include "surface/overhang_deformation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_deformation.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetMeasure.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/Morphology.h>
#include <openvdb/tools/Prune.h>

#include "core/error.h"
#include "core/vec3_ops.h"
#include "volume/extract_mesh.h"
#include "volume/progress_interrupter.h"
#include "volume/require_level_set.h"

namespace fabvdb::surface {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Deformation = CGAL::Surface_mesh_deformation<SurfaceMesh, CGAL::Default, CGAL::Default, CGAL::SRE_ARAP>;
using Sampler = openvdb::tools::GridSampler<openvdb::FloatGrid::ConstAccessor, openvdb::tools::BoxSampler>;

constexpr uint32_t no_vertex = std::numeric_limits<uint32_t>::max();

struct Handle {
    uint32_t vertex = 0;
    Vec3 target{0, 0, 0};
};

//! Every vertex facing ±d (|n·d| >= 0.3) whose line along its facing side of
//! d leaves the part and enters it again within `max_gap`, through space that
//! no keep-out solid occupies, becomes a handle moved halfway across the gap,
//! never farther than `max_move`. Also marks the vertices within a voxel of a
//! keep-out solid (`touching`): they stay where they are, so nothing is
//! dragged into another part.
std::vector<Handle> find_handles(const Mesh& mesh, const openvdb::FloatGrid& part,
                                 const std::vector<openvdb::FloatGrid::ConstPtr>& keep_out, const Vec3& d,
                                 double max_gap, double max_move, std::vector<char>& touching,
                                 const Progress& progress) {
    const double voxel = part.voxelSize()[0];
    const double step = 0.25 * voxel;
    const std::vector<Vec3> normals = area_weighted_vertex_normals(mesh);
    std::vector<Handle> found(mesh.vertices.size(), Handle{no_vertex, {0, 0, 0}});
    touching.assign(mesh.vertices.size(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.vertices.size(), 1024), [&](const tbb::blocked_range<size_t>& range) {
        if (progress.cancelled()) return;
        const openvdb::FloatGrid::ConstAccessor part_access = part.getConstAccessor();
        const Sampler part_sampler(part_access, part.transform());
        std::vector<openvdb::FloatGrid::ConstAccessor> other_access;
        for (const auto& other : keep_out) other_access.push_back(other->getConstAccessor());
        std::vector<Sampler> other_samplers;
        for (size_t k = 0; k < keep_out.size(); ++k) other_samplers.emplace_back(other_access[k], keep_out[k]->transform());
        const auto value = [](const Sampler& sampler, const Vec3& p) {
            return double(sampler.wsSample(openvdb::Vec3d(p[0], p[1], p[2])));
        };
        for (size_t v = range.begin(); v != range.end(); ++v) {
            touching[v] = std::any_of(other_samplers.begin(), other_samplers.end(), [&](const Sampler& other) {
                return value(other, mesh.vertices[v]) < voxel;
            });
            if (touching[v]) continue;
            const Vec3 n = normalized(normals[v]);
            const double facing = dot(n, d);
            if (std::abs(facing) < 0.3) continue;
            const Vec3 along = facing > 0 ? d : -1.0 * d;
            const Vec3& start = mesh.vertices[v];
            double previous_t = 2 * step, previous_phi = value(part_sampler, start + previous_t * along);
            if (previous_phi <= 0) continue;
            for (double t = previous_t + step; t <= max_gap; t += step) {
                const Vec3 p = start + t * along;
                const bool occupied = std::any_of(other_samplers.begin(), other_samplers.end(),
                                                  [&](const Sampler& other) { return value(other, p) < 0; });
                if (occupied) break;
                const double phi = value(part_sampler, p);
                if (phi < 0) {
                    const double gap = previous_t + step * previous_phi / (previous_phi - phi);
                    found[v] = {uint32_t(v), start + std::min(0.5 * gap, max_move) * along};
                    break;
                }
                previous_t = t;
                previous_phi = phi;
            }
        }
    });
    progress.check();
    std::vector<Handle> handles;
    for (const Handle& handle : found)
        if (handle.vertex != no_vertex) handles.push_back(handle);
    return handles;
}

//! Vertices within `radius` (straight-line distance) of a handle, handles
//! included, `fixed` ones excluded. Straight-line, not along the surface, so
//! the far side of a thin overhang follows the side that moves and the
//! overhang moves as a whole instead of growing into the gap.
std::vector<char> region_of_interest(const Mesh& mesh, const std::vector<Handle>& handles,
                                     const std::vector<char>& fixed, double radius) {
    using Cell = std::array<int64_t, 3>;
    const auto cell_of = [radius](const Vec3& p) {
        return Cell{int64_t(std::floor(p[0] / radius)), int64_t(std::floor(p[1] / radius)),
                    int64_t(std::floor(p[2] / radius))};
    };
    std::map<Cell, std::vector<Vec3>> buckets;
    for (const Handle& handle : handles) buckets[cell_of(mesh.vertices[handle.vertex])].push_back(mesh.vertices[handle.vertex]);
    std::vector<char> inside(mesh.vertices.size(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.vertices.size(), 4096), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t v = range.begin(); v != range.end(); ++v) {
            if (fixed[v]) continue;
            const Vec3& p = mesh.vertices[v];
            const Cell c = cell_of(p);
            for (int64_t i = -1; i <= 1 && !inside[v]; ++i)
                for (int64_t j = -1; j <= 1 && !inside[v]; ++j)
                    for (int64_t k = -1; k <= 1 && !inside[v]; ++k) {
                        const auto bucket = buckets.find({c[0] + i, c[1] + j, c[2] + k});
                        if (bucket == buckets.end()) continue;
                        for (const Vec3& q : bucket->second)
                            if (norm(p - q) <= radius) {
                                inside[v] = 1;
                                break;
                            }
                    }
        }
    });
    for (const Handle& handle : handles) inside[handle.vertex] = 1;
    return inside;
}

//! SRE-ARAP on the triangles around the region (the region free, the rest of
//! them fixed, the handles at their targets); moves the mesh's vertices.
//! Returns false, leaving the mesh as it was, when the system cannot be
//! factored.
bool deform_region(Mesh& mesh, const std::vector<Handle>& handles, const std::vector<char>& region, int iterations) {
    SurfaceMesh surface;
    std::vector<SurfaceMesh::Vertex_index> local(mesh.vertices.size());
    std::vector<char> added(mesh.vertices.size(), 0);
    for (const Triangle& t : mesh.triangles) {
        if (!region[t[0]] && !region[t[1]] && !region[t[2]]) continue;
        for (uint32_t v : t)
            if (!added[v]) {
                const Vec3& p = mesh.vertices[v];
                local[v] = surface.add_vertex(Kernel::Point_3(p[0], p[1], p[2]));
                added[v] = 1;
            }
        // A face that would make the local surface non-manifold is left out;
        // its vertices still move with the others around them.
        surface.add_face(local[t[0]], local[t[1]], local[t[2]]);
    }
    Deformation deformation(surface);
    std::vector<uint32_t> free_vertices;
    for (size_t v = 0; v < mesh.vertices.size(); ++v)
        if (region[v] && !surface.is_isolated(local[v])) {
            deformation.insert_roi_vertex(local[v]);
            free_vertices.push_back(uint32_t(v));
        }
    for (const Handle& handle : handles)
        if (!surface.is_isolated(local[handle.vertex])) deformation.insert_control_vertex(local[handle.vertex]);
    if (!deformation.preprocess()) return false;
    for (const Handle& handle : handles)
        if (!surface.is_isolated(local[handle.vertex]))
            deformation.set_target_position(local[handle.vertex],
                                            Kernel::Point_3(handle.target[0], handle.target[1], handle.target[2]));
    deformation.deform(unsigned(iterations), 1e-4);
    for (uint32_t v : free_vertices) {
        const Kernel::Point_3& p = surface.point(local[v]);
        mesh.vertices[v] = {p.x(), p.y(), p.z()};
    }
    return true;
}

//! The level set of `mesh` on the transform of `like`, `band` voxels wide.
openvdb::FloatGrid::Ptr level_set_of(const Mesh& mesh, const openvdb::FloatGrid& like, float band,
                                     Progress& progress) {
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    for (const Vec3& p : mesh.vertices) {
        const openvdb::Vec3d index = like.transform().worldToIndex(openvdb::Vec3d(p[0], p[1], p[2]));
        points.emplace_back(float(index[0]), float(index[1]), float(index[2]));
    }
    for (const Triangle& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
    volume::ProgressInterrupter interrupter(progress);
    openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3s, openvdb::Vec3I> adapter(points, triangles);
    openvdb::FloatGrid::Ptr grid =
        openvdb::tools::meshToVolume<openvdb::FloatGrid>(interrupter, adapter, like.transform(), band, band);
    progress.check();
    return grid;
}

//! Only the voxels within `band` voxels of a vertex that moved (before or
//! after) and of the deformed surface take the deformed surface's values; the
//! others keep the part's own, so meshing and re-voxelising change nothing the
//! deformation did not move, and off the deformed band the part's distances
//! are off by no more than the displacement.
void replace_near_moved(openvdb::FloatGrid& part, const openvdb::FloatGrid& deformed, const Mesh& before,
                        const Mesh& after, int band) {
    openvdb::BoolGrid mask(false);
    auto marks = mask.getAccessor();
    for (size_t v = 0; v < before.vertices.size(); ++v) {
        if (before.vertices[v] == after.vertices[v]) continue;
        for (const Vec3& p : {before.vertices[v], after.vertices[v]})
            marks.setValueOn(part.transform().worldToIndexCellCentered(openvdb::Vec3d(p[0], p[1], p[2])));
    }
    openvdb::tools::dilateActiveValues(mask.tree(), band, openvdb::tools::NN_FACE_EDGE_VERTEX,
                                       openvdb::tools::IGNORE_TILES);
    auto target = part.getAccessor();
    const auto source = deformed.getConstAccessor();
    for (auto voxel = mask.cbeginValueOn(); voxel; ++voxel)
        if (source.isValueOn(voxel.getCoord())) target.setValue(voxel.getCoord(), source.getValue(voxel.getCoord()));
    openvdb::tools::pruneLevelSet(part.tree());
}

}  // namespace

OverhangDeformation deform_overhangs(const openvdb::FloatGrid& part, const Vec3& direction,
                                     const std::vector<openvdb::FloatGrid::ConstPtr>& keep_out,
                                     const OverhangDeformationOptions& options, Progress& progress) {
    volume::require_level_set(part, "the part");
    for (const auto& solid : keep_out) {
        if (!solid) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "a keep-out solid is null");
        volume::require_level_set(*solid, "a keep-out solid");
    }
    if (!(options.max_displacement > 0) || !std::isfinite(options.max_displacement) ||
        !(options.region_radius >= 0) || !std::isfinite(options.region_radius) || options.iterations < 1)
        throw Error(FABVDB_ERR_INVALID_ARGUMENT,
                    "overhang deformation needs a displacement > 0, a region radius >= 0 and >= 1 iteration");
    const Vec3 d = normalized(direction);
    if (!(norm(d) > 0)) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the parting direction is zero");

    OverhangDeformation result;
    result.volume_before = result.volume_after = openvdb::tools::levelSetVolume(part);
    progress.stage("overhang deformation: gaps");
    const Mesh surface = volume::extract_mesh(part, 0.0, progress);
    std::vector<char> touching;
    const std::vector<Handle> handles = find_handles(surface, part, keep_out, d, 2 * options.max_displacement,
                                                     options.max_displacement, touching, progress);
    if (handles.empty()) {
        result.part = part.deepCopy();
        return result;
    }

    progress.stage("overhang deformation: ARAP");
    const double radius = options.region_radius > 0 ? options.region_radius : 4 * options.max_displacement;
    const std::vector<char> region = region_of_interest(surface, handles, touching, radius);
    progress.check();
    Mesh deformed = surface;
    if (!deform_region(deformed, handles, region, options.iterations)) {
        result.part = part.deepCopy();
        return result;
    }
    progress.check();
    double sum = 0;
    for (size_t v = 0; v < deformed.vertices.size(); ++v) {
        const double moved = norm(deformed.vertices[v] - surface.vertices[v]);
        if (moved <= 0) continue;
        ++result.moved_vertices;
        sum += moved;
        result.max_displacement = std::max(result.max_displacement, moved);
    }
    result.handles = handles.size();
    result.mean_displacement = result.moved_vertices ? sum / double(result.moved_vertices) : 0.0;

    progress.stage("overhang deformation: level set");
    const int band = 3 + int(std::ceil(result.max_displacement / part.voxelSize()[0]));
    const openvdb::FloatGrid::Ptr deformed_grid = level_set_of(deformed, part, float(band), progress);
    result.part = part.deepCopy();
    replace_near_moved(*result.part, *deformed_grid, surface, deformed, band);
    progress.check();
    result.part->setGridClass(openvdb::GRID_LEVEL_SET);
    result.volume_after = openvdb::tools::levelSetVolume(*result.part);
    return result;
}

}  // namespace fabvdb::surface
