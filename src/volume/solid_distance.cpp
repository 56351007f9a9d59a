//! Signed distance of a clean solid with its nearest triangles (see solid_distance.h).
#include "volume/solid_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include <openvdb/tools/SignedFloodFill.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "core/error.h"
#include "volume/closest_point_on_triangle.h"
#include "volume/nearest_triangle.h"
#include "volume/vertex_corners.h"

namespace fabvdb::volume {

namespace {

using openvdb::Coord;
using openvdb::Vec3d;
using FloatLeaf = openvdb::FloatTree::LeafNodeType;
using IndexLeaf = openvdb::Int32Tree::LeafNodeType;

//! Unit face normals, angle-weighted vertex pseudonormals, and for every
//! triangle edge k (corner k to corner k+1) the triangle across it (the
//! first, by index, that runs along it the other way; itself if none).
struct Pseudonormals {
    std::vector<Vec3d> face, vertex;
    std::vector<uint32_t> across;

    Pseudonormals(const Mesh& mesh, const std::vector<Vec3d>& points)
        : face(mesh.triangles.size()), vertex(points.size(), Vec3d(0.0)), across(3 * mesh.triangles.size()) {
        const size_t triangle_count = mesh.triangles.size();
        std::vector<Vec3d> corner_normal(3 * triangle_count);
        tbb::parallel_for(tbb::blocked_range<size_t>(0, triangle_count), [&](const tbb::blocked_range<size_t>& range) {
            for (size_t t = range.begin(); t != range.end(); ++t) {
                const Triangle& tri = mesh.triangles[t];
                Vec3d n = (points[tri[1]] - points[tri[0]]).cross(points[tri[2]] - points[tri[0]]);
                const double length = n.length();
                face[t] = length > 0.0 ? n / length : Vec3d(0.0);
                for (int k = 0; k < 3; ++k) {
                    const Vec3d u = points[tri[(k + 1) % 3]] - points[tri[k]];
                    const Vec3d v = points[tri[(k + 2) % 3]] - points[tri[k]];
                    corner_normal[3 * t + k] = face[t] * std::atan2(u.cross(v).length(), u.dot(v));
                }
            }
        });
        // Per vertex, its corners in triangle order, so that the sums below
        // add in that order.
        const VertexCorners corners(mesh);
        tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size()), [&](const tbb::blocked_range<size_t>& range) {
            for (size_t v = range.begin(); v != range.end(); ++v)
                for (uint32_t c = corners.first[v]; c != corners.first[v + 1]; ++c)
                    vertex[v] += corner_normal[corners.corner[c]];
        });
        tbb::parallel_for(tbb::blocked_range<size_t>(0, triangle_count), [&](const tbb::blocked_range<size_t>& range) {
            for (size_t t = range.begin(); t != range.end(); ++t)
                for (int k = 0; k < 3; ++k) {
                    const VertexCorners::Across other = corners.across(mesh, uint32_t(t), k);
                    across[3 * t + k] = other.count > 0 ? other.first : uint32_t(t);
                }
        });
    }

    Vec3d at(const Mesh& mesh, uint32_t t, TriangleFeature feature) const {
        switch (feature) {
            case TriangleFeature::corner0: return vertex[mesh.triangles[t][0]];
            case TriangleFeature::corner1: return vertex[mesh.triangles[t][1]];
            case TriangleFeature::corner2: return vertex[mesh.triangles[t][2]];
            case TriangleFeature::edge01: return face[t] + face[across[3 * t]];
            case TriangleFeature::edge12: return face[t] + face[across[3 * t + 1]];
            case TriangleFeature::edge20: return face[t] + face[across[3 * t + 2]];
            case TriangleFeature::face: break;
        }
        return face[t];
    }
};

//! Leaf block coordinates packed in 21 bits each.
constexpr int64_t kBlockOffset = int64_t(1) << 20;

uint64_t block_key(int64_t bx, int64_t by, int64_t bz) {
    return (uint64_t(bx + kBlockOffset) << 42) | (uint64_t(by + kBlockOffset) << 21) | uint64_t(bz + kBlockOffset);
}

Coord block_origin(uint64_t key) {
    const auto field = [](uint64_t bits) { return int32_t(int64_t(bits & ((uint64_t(1) << 21) - 1)) - kBlockOffset) * 8; };
    return Coord(field(key >> 42), field(key >> 21), field(key));
}

//! Voxel index range [lo, hi] of a triangle's bounding box widened by `width`.
void voxel_range(const Vec3d& a, const Vec3d& b, const Vec3d& c, double width, Coord& lo, Coord& hi) {
    for (int k = 0; k < 3; ++k) {
        lo[k] = int32_t(std::ceil(std::min({a[k], b[k], c[k]}) - width));
        hi[k] = int32_t(std::floor(std::max({a[k], b[k], c[k]}) + width));
    }
}

//! The surface in index space (voxel centres at integer coordinates).
struct IndexSurface {
    const Mesh& mesh;
    std::vector<Vec3d> points;
    Pseudonormals normals;

    IndexSurface(const Mesh& surface, double voxel) : mesh(surface), points(scaled(surface, voxel)), normals(surface, points) {}

    static std::vector<Vec3d> scaled(const Mesh& surface, double voxel) {
        std::vector<Vec3d> points(surface.vertices.size());
        for (size_t i = 0; i < points.size(); ++i)
            points[i] = Vec3d(surface.vertices[i][0], surface.vertices[i][1], surface.vertices[i][2]) / voxel;
        return points;
    }
    const Vec3d& corner(uint32_t t, int k) const { return points[mesh.triangles[t][k]]; }
    double squared_distance(const Vec3d& p, uint32_t t) const {
        return (p - closest_point_on_triangle(p, corner(t, 0), corner(t, 1), corner(t, 2)).point).lengthSqr();
    }
    //! Whether p lies inside, judged at its nearest point on triangle t.
    bool inside(const Vec3d& p, uint32_t t) const {
        const TrianglePoint nearest = closest_point_on_triangle(p, corner(t, 0), corner(t, 1), corner(t, 2));
        return (p - nearest.point).dot(normals.at(mesh, t, nearest.feature)) < 0.0;
    }
};

//! Every voxel within one voxel of a triangle: its exact signed distance and
//! nearest triangle, as leaves of both grids.
void exact_band(const IndexSurface& surface, double voxel, openvdb::FloatTree& distance,
                openvdb::Int32Tree& nearest, Progress& progress) {
    constexpr double kWidth = 1.0;
    const size_t triangle_count = surface.mesh.triangles.size();
    // (block, triangle) pairs, sorted by block.
    tbb::enumerable_thread_specific<std::vector<std::pair<uint64_t, uint32_t>>> local_pairs;
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, uint32_t(triangle_count), 4096),
                      [&](const tbb::blocked_range<uint32_t>& range) {
                          auto& out = local_pairs.local();
                          for (uint32_t t = range.begin(); t != range.end(); ++t) {
                              Coord lo, hi;
                              voxel_range(surface.corner(t, 0), surface.corner(t, 1), surface.corner(t, 2), kWidth,
                                          lo, hi);
                              for (int32_t bx = lo.x() >> 3; bx <= hi.x() >> 3; ++bx)
                                  for (int32_t by = lo.y() >> 3; by <= hi.y() >> 3; ++by)
                                      for (int32_t bz = lo.z() >> 3; bz <= hi.z() >> 3; ++bz)
                                          out.emplace_back(block_key(bx, by, bz), t);
                          }
                      });
    std::vector<std::pair<uint64_t, uint32_t>> pairs;
    for (auto& part : local_pairs) pairs.insert(pairs.end(), part.begin(), part.end());
    local_pairs.clear();
    tbb::parallel_sort(pairs.begin(), pairs.end());
    std::vector<size_t> block_start;
    for (size_t i = 0; i < pairs.size(); ++i)
        if (i == 0 || pairs[i].first != pairs[i - 1].first) block_start.push_back(i);
    block_start.push_back(pairs.size());
    progress.update(0.2);

    const size_t blocks = block_start.size() - 1;
    std::vector<std::unique_ptr<FloatLeaf>> distance_leaves(blocks);
    std::vector<std::unique_ptr<IndexLeaf>> nearest_leaves(blocks);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, blocks, 16), [&](const tbb::blocked_range<size_t>& range) {
        double best[FloatLeaf::SIZE];
        uint32_t winner[FloatLeaf::SIZE];
        for (size_t b = range.begin(); b != range.end(); ++b) {
            if (progress.cancelled()) return;
            const Coord origin = block_origin(pairs[block_start[b]].first);
            std::fill(std::begin(best), std::end(best), std::numeric_limits<double>::infinity());
            for (size_t i = block_start[b]; i != block_start[b + 1]; ++i) {
                const uint32_t t = pairs[i].second;
                const Vec3d &a = surface.corner(t, 0), &bb = surface.corner(t, 1), &c = surface.corner(t, 2);
                Coord lo, hi;
                voxel_range(a, bb, c, kWidth, lo, hi);
                const Vec3d box_lo = minComponent(minComponent(a, bb), c), box_hi = maxComponent(maxComponent(a, bb), c);
                for (int32_t x = std::max(lo.x(), origin.x()); x <= std::min(hi.x(), origin.x() + 7); ++x)
                    for (int32_t y = std::max(lo.y(), origin.y()); y <= std::min(hi.y(), origin.y() + 7); ++y)
                        for (int32_t z = std::max(lo.z(), origin.z()); z <= std::min(hi.z(), origin.z() + 7); ++z) {
                            const Vec3d p(x, y, z);
                            // The bounding box's distance bounds the triangle's from below.
                            double box_distance = 0.0;
                            for (int k = 0; k < 3; ++k) {
                                const double gap = std::max({box_lo[k] - p[k], p[k] - box_hi[k], 0.0});
                                box_distance += gap * gap;
                            }
                            const openvdb::Index offset = FloatLeaf::coordToOffset(Coord(x, y, z));
                            if (box_distance > kWidth * kWidth || box_distance >= best[offset]) continue;
                            const double squared = surface.squared_distance(p, t);
                            if (squared < best[offset]) {
                                best[offset] = squared;
                                winner[offset] = t;
                            }
                        }
            }
            auto distance_leaf = std::make_unique<FloatLeaf>(origin, distance.background(), false);
            auto nearest_leaf = std::make_unique<IndexLeaf>(origin, -1, false);
            bool any = false;
            for (openvdb::Index offset = 0; offset < FloatLeaf::SIZE; ++offset) {
                if (!(best[offset] <= kWidth * kWidth)) continue;
                const Vec3d p = (origin + FloatLeaf::offsetToLocalCoord(offset)).asVec3d();
                const double d = std::sqrt(best[offset]) * voxel;
                distance_leaf->setValueOn(offset, float(surface.inside(p, winner[offset]) ? -d : d));
                nearest_leaf->setValueOn(offset, int32_t(winner[offset]));
                any = true;
            }
            if (any) {
                distance_leaves[b] = std::move(distance_leaf);
                nearest_leaves[b] = std::move(nearest_leaf);
            }
        }
    });
    progress.check();
    for (size_t b = 0; b < blocks; ++b)
        if (distance_leaves[b]) {
            distance.addLeaf(distance_leaves[b].release());
            nearest.addLeaf(nearest_leaves[b].release());
        }
}

//! The inside distance (negative) and nearest triangle of each voxel in
//! `voxels`: the nearest of its active neighbours' triangles.
void nearest_from_neighbours(const openvdb::FloatGrid& grid, const NearestTriangle& search,
                             const std::vector<Coord>& voxels, std::vector<float>& value,
                             std::vector<int32_t>& winner, Progress& progress) {
    value.resize(voxels.size());
    winner.resize(voxels.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, voxels.size(), 256), [&](const tbb::blocked_range<size_t>& range) {
        NearestTriangle::Query query(search, false);
        for (size_t i = range.begin(); i != range.end(); ++i) {
            if (progress.cancelled()) return;
            const NearestTriangle::Result result = query(grid.indexToWorld(voxels[i]));
            value[i] = float(-result.distance);
            winner[i] = int32_t(result.triangle);
        }
    });
    progress.check();
}

//! Grows the band inward a layer at a time. The first layer is the face
//! neighbours of the band's inside voxels: such a neighbour is inside (were
//! it outside, the unit step to it would cross the surface, leaving it within
//! a voxel of the surface, so in the band already), and more than a voxel
//! deep. The next layers are the 26-neighbours of the last one: a voxel that
//! deep has no outside neighbour beyond the band (sqrt(3) - 1 < 1). Each new
//! voxel takes the nearest of its active neighbours' triangles. Layers are
//! taken in order of distance, a voxel deep at a time, like a bucketed
//! Dijkstra: a voxel found farther than the current depth waits (and is
//! asked again) until then, so that a far side of the part, reached first
//! across a diagonal, cannot give it a far triangle before the near side's
//! voxels exist.
void grow_inward(const Mesh& surface, double depth, openvdb::FloatGrid& distance_grid,
                 openvdb::Int32Grid& nearest_grid, Progress& progress) {
    openvdb::FloatTree& distance = distance_grid.tree();
    openvdb::Int32Tree& nearest = nearest_grid.tree();
    const double voxel = distance_grid.voxelSize()[0];
    const NearestTriangle search(surface, nearest_grid);
    std::vector<Coord> frontier;
    for (auto it = distance.cbeginValueOn(); it; ++it)
        if (*it < 0.0f) frontier.push_back(it.getCoord());
    const double deepest = depth + voxel;
    // Voxels found deeper than the current depth, with their estimate: it
    // changes only when a neighbour joins, which finds them again.
    struct Waiting {
        Coord voxel;
        float value;
        int32_t winner;
    };
    std::vector<Waiting> waiting;
    double accept = 2.0 * voxel;
    for (int layer = 0; accept <= deepest + voxel && (!frontier.empty() || !waiting.empty());
         ++layer, accept += voxel) {
        const int reach = layer == 0 ? 1 : 3;  // |dx| + |dy| + |dz| at most: faces, then all 26
        tbb::enumerable_thread_specific<std::vector<Coord>> local_found;
        tbb::parallel_for(tbb::blocked_range<size_t>(0, frontier.size(), 1024),
                          [&](const tbb::blocked_range<size_t>& range) {
                              const openvdb::tree::ValueAccessor<const openvdb::FloatTree> active(distance);
                              auto& out = local_found.local();
                              for (size_t i = range.begin(); i != range.end(); ++i)
                                  for (int dx = -1; dx <= 1; ++dx)
                                      for (int dy = -1; dy <= 1; ++dy)
                                          for (int dz = -1; dz <= 1; ++dz) {
                                              if (std::abs(dx) + std::abs(dy) + std::abs(dz) > reach) continue;
                                              const Coord c = frontier[i].offsetBy(dx, dy, dz);
                                              if (!active.isValueOn(c)) out.push_back(c);
                                          }
                          });
        std::vector<Coord> found;
        for (auto& part : local_found) found.insert(found.end(), part.begin(), part.end());
        tbb::parallel_sort(found.begin(), found.end());
        found.erase(std::unique(found.begin(), found.end()), found.end());

        std::vector<float> value;
        std::vector<int32_t> winner;
        nearest_from_neighbours(distance_grid, search, found, value, winner, progress);
        frontier.clear();
        std::vector<Waiting> still_waiting;
        const auto take = [&](const Coord& c, float v, int32_t t) {
            if (-v > accept) {
                still_waiting.push_back({c, v, t});
                return;
            }
            distance.setValueOn(c, v);
            nearest.setValueOn(c, t);
            frontier.push_back(c);
        };
        for (size_t i = 0; i < found.size(); ++i) take(found[i], value[i], winner[i]);
        for (const Waiting& w : waiting)
            if (!std::binary_search(found.begin(), found.end(), w.voxel)) take(w.voxel, w.value, w.winner);
        waiting = std::move(still_waiting);
        progress.update(0.5 + 0.3 * std::min(1.0, accept / deepest));
    }
}

}  // namespace

SolidDistance solid_distance(const Mesh& surface, double voxel, double interior_depth, Progress& progress) {
    if (!(voxel > 0.0) || !(interior_depth >= 0.0))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "solid distance: voxel must be > 0 and interior depth >= 0");
    progress.stage("surface distance");
    const IndexSurface indexed(surface, voxel);
    // Deeper than the band reaches: the interior beyond it reads as deeper still.
    const float background = float(interior_depth + 4.0 * voxel);
    SolidDistance solid;
    solid.distance = openvdb::FloatGrid::create(background);
    solid.distance->setTransform(openvdb::math::Transform::createLinearTransform(voxel));
    solid.distance->setGridClass(openvdb::GRID_LEVEL_SET);
    solid.closest_triangle = openvdb::Int32Grid::create(-1);
    solid.closest_triangle->setTransform(solid.distance->transform().copy());
    exact_band(indexed, voxel, solid.distance->tree(), solid.closest_triangle->tree(), progress);
    progress.update(0.5);
    grow_inward(surface, interior_depth, *solid.distance, *solid.closest_triangle, progress);
    openvdb::tools::signedFloodFill(solid.distance->tree());
    progress.update(1.0);
    return solid;
}

}  // namespace fabvdb::volume
