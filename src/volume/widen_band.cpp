//! Closest-point propagation of a narrow band (see widen_band.h).
#include "volume/widen_band.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <openvdb/tools/ChangeBackground.h>
#include <openvdb/tools/Morphology.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <openvdb/tree/LeafManager.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "core/error.h"

namespace fabvdb::volume {

namespace {

using openvdb::Coord;
using openvdb::Vec3d;
using openvdb::Vec3s;

struct NewVoxel {
    Coord ijk;
    float value;
    Vec3s closest;  //!< index space
    bool in_band;   //!< a voxel of the given band, which keeps its value
    bool later;     //!< farther from its point than this layer takes
};

//! The closest surface point (index space) of the band's voxels within a
//! voxel and a half of the surface, from the distance and its central
//! differences, into `closest` (made with the band's topology): the seeds.
//! Its other voxels are switched off, to be reached by propagation (farther
//! out, a direction error moves the point more, and at the band's rim only
//! one-sided differences are left).
void seed_closest_points(const openvdb::FloatTree& tree, double voxel, openvdb::Vec3STree& closest) {
    openvdb::tree::LeafManager<openvdb::Vec3STree> leaves(closest);
    leaves.foreach([&](openvdb::Vec3STree::LeafNodeType& leaf, size_t) {
        openvdb::tree::ValueAccessor<const openvdb::FloatTree> values(tree);
        for (auto it = leaf.beginValueOn(); it; ++it) {
            const Coord c = it.getCoord();
            const double phi = values.getValue(c);
            Vec3d gradient(0.0);
            bool central = std::abs(phi) <= 1.5 * voxel;
            for (int k = 0; k < 3 && central; ++k) {
                Coord step(0, 0, 0);
                step[k] = 1;
                float plus = 0.0f, minus = 0.0f;
                central = values.probeValue(c + step, plus) && values.probeValue(c - step, minus);
                gradient[k] = 0.5 * (double(plus) - double(minus));
            }
            const double length = gradient.length();
            if (!central || !(length > 0.0)) {
                it.setValueOff();
                continue;
            }
            it.setValue(Vec3s(c.asVec3d() - (phi / voxel) * gradient / length));
        }
    });
}

}  // namespace

openvdb::FloatGrid::Ptr widen_band(const openvdb::FloatGrid& grid, int interior, int exterior, Progress& progress) {
    if (interior < 1 || exterior < 1)
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "widen_band: the widths must be at least a voxel");
    progress.stage("widen band");
    const double voxel = grid.voxelSize()[0];
    const float outside = float(exterior * voxel), inside = float(interior * voxel);
    openvdb::FloatGrid::Ptr wide = grid.deepCopy();
    openvdb::FloatTree& tree = wide->tree();
    openvdb::Vec3STree closest(tree, Vec3s(0.0f), openvdb::TopologyCopy());
    seed_closest_points(tree, voxel, closest);

    // The voxels given a closest point last (at first the seeds): their
    // neighbours without one are the next layer's candidates, the band's
    // own (which keep their values) and new ones within the widths. Layer k
    // takes those within 2.5 + k voxels of their point, in order of
    // distance like a bucketed Dijkstra; the others wait (and are asked
    // again), so that a voxel reached first across a diagonal does not keep
    // a point sideways of it before its nearer neighbours have theirs.
    openvdb::MaskTree frontier(closest, false, openvdb::TopologyCopy());
    openvdb::MaskTree waiting(false);
    const int widest = std::max(interior, exterior), layers = widest + 4;
    for (int layer = 0; layer < layers; ++layer) {
        const double accept = 2.5 + layer;
        openvdb::MaskTree fresh(frontier);
        openvdb::tools::dilateActiveValues(fresh, 1, openvdb::tools::NN_FACE_EDGE_VERTEX,
                                           openvdb::tools::IGNORE_TILES);
        fresh.topologyUnion(waiting);
        fresh.topologyDifference(closest);
        openvdb::tree::LeafManager<openvdb::MaskTree> leaves(fresh);
        tbb::enumerable_thread_specific<std::vector<NewVoxel>> found;
        const openvdb::FloatTree& values_tree = tree;
        const openvdb::Vec3STree& points_tree = closest;
        tbb::parallel_for(leaves.leafRange(), [&](const openvdb::tree::LeafManager<openvdb::MaskTree>::LeafRange& range) {
            if (progress.cancelled()) return;
            openvdb::tree::ValueAccessor<const openvdb::FloatTree> values(values_tree);
            openvdb::tree::ValueAccessor<const openvdb::Vec3STree> points(points_tree);
            std::vector<NewVoxel>& out = found.local();
            for (auto leaf = range.begin(); leaf; ++leaf)
                for (auto it = leaf->cbeginValueOn(); it; ++it) {
                    const Coord c = it.getCoord();
                    const Vec3d at = c.asVec3d();
                    double best = std::numeric_limits<double>::infinity();
                    float side = 0.0f;
                    Vec3s point(0.0f);
                    for (int dx = -1; dx <= 1; ++dx)
                        for (int dy = -1; dy <= 1; ++dy)
                            for (int dz = -1; dz <= 1; ++dz) {
                                const Coord n = c.offsetBy(dx, dy, dz);
                                Vec3s candidate;
                                if (!points.probeValue(n, candidate)) continue;
                                const double squared = (at - Vec3d(candidate)).lengthSqr();
                                if (squared < best) {
                                    best = squared;
                                    side = values.getValue(n);
                                    point = candidate;
                                }
                            }
                    if (!(best < std::numeric_limits<double>::infinity())) continue;
                    const bool later = std::sqrt(best) > accept;
                    float own;
                    if (values.probeValue(c, own)) {
                        out.push_back({c, own, point, true, later});
                        continue;
                    }
                    const float distance = float(std::sqrt(best) * voxel);
                    if (distance >= (side < 0.0f ? inside : outside)) continue;
                    out.push_back({c, side < 0.0f ? -distance : distance, point, false, later});
                }
        });
        progress.check();
        size_t added = 0, waits = 0;
        frontier.clear();
        waiting.clear();
        openvdb::tree::ValueAccessor<openvdb::FloatTree> values(tree);
        openvdb::tree::ValueAccessor<openvdb::Vec3STree> points(closest);
        openvdb::tree::ValueAccessor<openvdb::MaskTree> last(frontier), wait(waiting);
        for (const std::vector<NewVoxel>& part : found)
            for (const NewVoxel& v : part) {
                if (v.later) {
                    wait.setValueOn(v.ijk);
                    ++waits;
                    continue;
                }
                if (!v.in_band) values.setValueOn(v.ijk, v.value);
                points.setValueOn(v.ijk, v.closest);
                last.setValueOn(v.ijk);
                ++added;
            }
        progress.update(double(layer + 1) / double(layers));
        // Past the widths with none waiting, the next layer would only
        // find the odd voxel a hair inside them, across a diagonal.
        if (added + waits == 0 || (waits == 0 && accept >= widest)) break;
    }
    openvdb::tools::changeAsymmetricLevelSetBackground(tree, outside, -inside);
    openvdb::tools::signedFloodFillWithValues(tree, outside, -inside);
    progress.check();
    return wide;
}

}  // namespace fabvdb::volume
