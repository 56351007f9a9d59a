//! Robust signed distance from a dirty mesh (see signed_distance.h).
//!
//! 1. orient_soup: weld, drop degenerate/duplicate triangles, orient every
//!    piece consistently and outward.
//! 2. Unsigned distance in a narrow band (OpenVDB meshToVolume, unsigned).
//! 3. Sign of every band voxel from the winding number (inside: w >= 1/2),
//!    taken once per group of voxels with no surface between them where the
//!    bound on its gradient (winding_gradient_bound.h) shows the group on one
//!    side, else voxel by voxel (leaf_winding.h).
//! 4. If the signed band is a consistent distance field (every sign change
//!    between neighbours is a surface crossing, no surface voxel without one)
//!    the interior is flood-filled and we are done. Otherwise (holes wider
//!    than the band, interior or overlapping triangles, parts thinner than a
//!    voxel) the band is rebuilt from the zero surface of the field, off the
//!    band flood-filled for a closed-cycle input; for any other the winding
//!    number is sampled off the band first — the other voxels of band
//!    leaves, and the leaf-sized blocks of the bounding box, by groups again
//!    and voxel by voxel where w may cross 1/2 — so that it closes the holes.
#include "volume/signed_distance.h"

#include <atomic>
#include <cmath>
#include <optional>
#include <sstream>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <openvdb/tree/LeafManager.h>

#include "core/error.h"
#include "core/stage_clock.h"
#include "volume/closed_cycle.h"
#include "volume/edge_table.h"
#include "volume/enclosed_share.h"
#include "volume/leaf_winding.h"
#include "volume/memory_estimate.h"
#include "volume/orient_soup.h"
#include "volume/position_ids.h"
#include "volume/progress_interrupter.h"
#include "volume/rebuild_band.h"
#include "volume/unsigned_band.h"
#include "volume/winding_gradient_bound.h"
#include "volume/winding_number.h"

namespace fabvdb::volume {

namespace {

using FloatLeaf = openvdb::FloatTree::LeafNodeType;
constexpr int leaf_dim = int(FloatLeaf::DIM);
constexpr int leaf_size = int(FloatLeaf::SIZE);
// An input counts as enclosing volume when some band voxel is clearly inside
// (w >= 0.6, far above the tree's approximation error).
constexpr double clearly_inside = 0.6;
// Under this share of its area enclosing volume (enclosed_share.h) an input
// encloses nothing: soups, sheets, bowls and crossing tangles measure under
// 0.05, the corpus's scans with holes over 0.35
// (tests/volume/enclosed_share_test.cpp).
constexpr double min_enclosed_share = 0.1;
// Pieces the winding number's tree may hold beyond 4 per triangle for an
// open input (winding_number.h).
constexpr size_t open_input_extra_pieces = size_t(1) << 18;

void check_budget(double area, const SignedDistanceOptions& options, SignedDistanceStats& stats) {
    stats.estimated_bytes = estimate_level_set_bytes(area, options.voxel_size, options.half_band_voxels);
    if (options.memory_budget_bytes == 0 || stats.estimated_bytes <= options.memory_budget_bytes) return;
    std::ostringstream message;
    message.precision(3);
    message << options.input_name << ": a level set would need ~"
            << double(stats.estimated_bytes) / double(1ull << 30) << " GiB at voxel " << options.voxel_size
            << " mm (budget " << double(options.memory_budget_bytes) / double(1ull << 30) << " GiB); --voxel "
            << voxel_size_for_budget(area, options.half_band_voxels, options.memory_budget_bytes) << "mm fits";
    throw Error(FABVDB_ERR_OUT_OF_BUDGET, message.str());
}

// Runs `body(leaf_index)` over [0, count) in parallel, in slices so that
// progress is reported from this thread and cancellation stops it early.
template <class Body>
void for_each_index(size_t count, Progress& progress, const Body& body) {
    const size_t slices = 64, slice = (count + slices - 1) / slices;
    for (size_t begin = 0; begin < count; begin += slice) {
        const size_t end = std::min(count, begin + slice);
        tbb::parallel_for(tbb::blocked_range<size_t>(begin, end), [&](const tbb::blocked_range<size_t>& range) {
            for (size_t i = range.begin(); i != range.end(); ++i) {
                if (progress.cancelled()) return;
                body(i);
            }
        });
        progress.update(double(end) / double(count));
    }
    progress.check();
}

// The box of a leaf's voxel centres, in mm.
BoundingBox leaf_box(const FloatLeaf& leaf, const openvdb::math::Transform& transform) {
    const openvdb::Vec3d lo = transform.indexToWorld(leaf.origin());
    const openvdb::Vec3d hi = transform.indexToWorld(leaf.origin().offsetBy(leaf_dim - 1));
    return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
}

// Past this gradient bound no group of two voxels or more can be given one
// side (leaf_winding.h), so the bound need not be summed further.
double gradient_cap(double voxel) { return 0.5 / voxel; }

// A signed narrow band is a distance field of its zero surface only if every
// sign change between face neighbours is a crossing (|a| + |b| <= ~h) and
// every voxel within h/2 of a triangle has a neighbour across it (else the
// triangle lies inside the solid: an overlapping shell or an inner fin).
// For a closed-cycle input, an outside voxel near a triangle without one is
// beside a part thinner than a voxel: its distance to that part is true.
bool band_is_consistent(const openvdb::FloatGrid& grid, double voxel, bool closed_cycle) {
    std::atomic<bool> consistent{true};
    openvdb::tree::LeafManager<const openvdb::FloatTree> leaves(grid.tree());
    tbb::parallel_for(leaves.leafRange(), [&](const auto& range) {
        auto accessor = grid.getConstAccessor();
        for (auto leaf = range.begin(); leaf && consistent; ++leaf) {
            const float* values = leaf->buffer().data();
            const auto& active = leaf->getValueMask();
            // Whether the voxel at local (x, y, z) + step is active, and its
            // value: from the leaf itself when inside it.
            const auto probe = [&](int x, int y, int z, const openvdb::Coord& step, float& value) {
                x += step[0], y += step[1], z += step[2];
                if ((x | y | z) >= 0 && x < leaf_dim && y < leaf_dim && z < leaf_dim) {
                    const int offset = (x << 6) | (y << 3) | z;
                    value = values[offset];
                    return active.isOn(offset);
                }
                return accessor.probeValue(leaf->origin().offsetBy(x, y, z), value);
            };
            for (auto voxel_it = active.beginOn(); voxel_it; ++voxel_it) {
                const int offset = int(voxel_it.pos()), x = offset >> 6, y = (offset >> 3) & 7, z = offset & 7;
                const float a = values[offset];
                bool crossing = false;
                for (int axis = 0; axis < 3; ++axis)
                    for (int sign : {-1, 1}) {
                        openvdb::Coord step(0, 0, 0);
                        step[axis] = sign;
                        float b;
                        if (!probe(x, y, z, step, b) || (a < 0) == (b < 0)) continue;
                        crossing = true;
                        if (std::abs(a) + std::abs(b) > 1.5 * voxel) consistent = false;
                    }
                if (crossing || std::abs(a) >= 0.5 * voxel || (closed_cycle && a > 0)) continue;
                // Near a sharp edge or a thin part the surface may pass a voxel
                // diagonally: a crossing to any of the 26 neighbours will do.
                for (int dx = -1; dx <= 1 && !crossing; ++dx)
                    for (int dy = -1; dy <= 1 && !crossing; ++dy)
                        for (int dz = -1; dz <= 1 && !crossing; ++dz) {
                            float b;
                            crossing = probe(x, y, z, openvdb::Coord(dx, dy, dz), b) && (a < 0) != (b < 0);
                        }
                if (!crossing) consistent = false;
            }
        }
    });
    return consistent;
}

// The off-band part of the field for inputs whose band is not consistent.
void add_off_band_winding(openvdb::FloatGrid& grid, const WindingNumber& winding, const BoundingBox& box,
                          const WindingGradientBound& gradient, std::vector<float>& band_winding,
                          const std::vector<double>& leaf_gradient, const std::vector<char>& band_exact,
                          Progress& progress) {
    const openvdb::math::Transform& transform = grid.transform();
    const double voxel = transform.voxelSize()[0];
    const float background = grid.background();
    openvdb::FloatTree& tree = grid.tree();

    // Every voxel of band leaves: w where not yet known, then values.
    {
        openvdb::tree::LeafManager<openvdb::FloatTree> leaves(tree);
        progress.stage("winding number off band");
        for_each_index(leaves.leafCount(), progress, [&](size_t i) {
            off_band_leaf_values(leaves.leaf(i), winding, transform, leaf_gradient[i], background, band_exact[i] != 0,
                                 &band_winding[i * leaf_size]);
        });
    }

    // Leaf-sized blocks of the bounding box that the band does not reach:
    // classify each by w at its corners and centre; blocks where w crosses 1/2
    // are sampled voxel by voxel, inside blocks become inside tiles.
    progress.stage("winding number blocks");
    const openvdb::Coord lo = transform.worldToIndexNodeCentered(openvdb::Vec3d(box.min[0], box.min[1], box.min[2]));
    const openvdb::Coord hi = transform.worldToIndexNodeCentered(openvdb::Vec3d(box.max[0], box.max[1], box.max[2]));
    openvdb::Coord first, count;
    for (int k = 0; k < 3; ++k) {
        first[k] = ((lo[k] - leaf_dim) >> 3) * leaf_dim;
        count[k] = (((hi[k] + leaf_dim) >> 3) * leaf_dim - first[k]) / leaf_dim + 1;
    }
    const size_t corners_x = size_t(count[0]) + 1, corners_y = size_t(count[1]) + 1, corners_z = size_t(count[2]) + 1;
    std::vector<float> corner_winding(corners_x * corners_y * corners_z);
    for_each_index(corners_x, progress, [&](size_t i) {
        for (size_t j = 0; j < corners_y; ++j)
            for (size_t k = 0; k < corners_z; ++k) {
                const openvdb::Vec3d corner = transform.indexToWorld(
                    openvdb::Vec3d(first[0] + leaf_dim * double(i) - 0.5, first[1] + leaf_dim * double(j) - 0.5,
                                   first[2] + leaf_dim * double(k) - 0.5));
                corner_winding[(i * corners_y + j) * corners_z + k] = float(winding({corner[0], corner[1], corner[2]}));
            }
    });
    enum class Block : uint8_t { outside, inside, mixed };
    const size_t blocks = size_t(count[0]) * size_t(count[1]) * size_t(count[2]);
    std::vector<Block> kind(blocks, Block::outside);
    const auto block_origin = [&](size_t b) {
        const size_t i = b / (size_t(count[1]) * size_t(count[2])), j = (b / size_t(count[2])) % size_t(count[1]),
                     k = b % size_t(count[2]);
        return openvdb::Coord(first[0] + leaf_dim * int(i), first[1] + leaf_dim * int(j), first[2] + leaf_dim * int(k));
    };
    for_each_index(blocks, progress, [&](size_t b) {
        const openvdb::Coord origin = block_origin(b);
        if (tree.probeConstLeaf(origin)) return;
        const size_t i = size_t(origin[0] - first[0]) / leaf_dim, j = size_t(origin[1] - first[1]) / leaf_dim,
                     k = size_t(origin[2] - first[2]) / leaf_dim;
        const openvdb::Vec3d centre = transform.indexToWorld(origin.asVec3d() + openvdb::Vec3d(0.5 * (leaf_dim - 1)));
        double w_min = winding({centre[0], centre[1], centre[2]}), w_max = w_min;
        for (size_t c = 0; c < 8; ++c) {
            const double w = corner_winding[((i + (c & 1)) * corners_y + j + ((c >> 1) & 1)) * corners_z + k + (c >> 2)];
            w_min = std::min(w_min, w);
            w_max = std::max(w_max, w);
        }
        if (w_min > inside_winding + 0.1) kind[b] = Block::inside;
        else if (w_max >= inside_winding - 0.1) kind[b] = Block::mixed;
    });

    std::vector<FloatLeaf*> mixed_leaves;
    for (size_t b = 0; b < blocks; ++b) {
        if (kind[b] == Block::inside) tree.addTile(1, block_origin(b), -background, false);
        if (kind[b] == Block::mixed) mixed_leaves.push_back(tree.touchLeaf(block_origin(b)));
    }
    progress.stage("winding number across holes");
    for_each_index(mixed_leaves.size(), progress, [&](size_t i) {
        FloatLeaf& leaf = *mixed_leaves[i];
        float w[leaf_size];
        off_band_leaf_values(leaf, winding, transform, gradient(leaf_box(leaf, transform), gradient_cap(voxel)),
                             background, true, w);
    });
}

}  // namespace

openvdb::FloatGrid::Ptr signed_distance_from_mesh(const Mesh& input, const SignedDistanceOptions& options,
                                                  Progress& progress, SignedDistanceStats* stats_out,
                                                  OrientedInput* oriented) {
    if (!(options.voxel_size > 0.0)) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "voxel size must be > 0");
    if (options.half_band_voxels < 2) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "half band must be >= 2 voxels");
    if (options.thicken < 0.0) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "thickness must be >= 0");
    openvdb::initialize();
    SignedDistanceStats stats;
    check_budget(surface_area(input), options, stats);
    const double voxel = options.voxel_size;
    const float half_band = float(options.half_band_voxels);
    const auto transform = openvdb::math::Transform::createLinearTransform(voxel);

    StageClock clock(stats.timings);
    progress.stage("orient");
    Mesh mesh = options.oriented ? input : orient_soup(input, progress);
    clock.lap("orient");
    if (mesh.triangles.empty())
        throw Error(FABVDB_ERR_BAD_INPUT, options.input_name + ": no triangle with a non-zero area");

    progress.stage("winding number tree");
    // One edge table of the input welded by position serves the gradient
    // bound and the closed-cycle check.
    std::optional<WindingGradientBound> gradient_bound;
    bool closed = false;
    {
        const Mesh welded = weld_positions(mesh);
        const EdgeTable edges = build_edge_table(welded);
        gradient_bound.emplace(welded, edges);
        closed = is_closed_cycle(edges);
    }
    // Near the holes of an open input every band voxel takes its own walk:
    // there its long triangles are held in pieces (bed.obj's 14k make 318k).
    const size_t pieces = closed ? 0 : 4 * mesh.triangles.size() + open_input_extra_pieces;
    const auto winding = std::make_unique<WindingNumber>(mesh, WindingNumber::default_accuracy, pieces);
    clock.lap("winding number tree");
    // What encloses nothing is told apart before any voxel is built.
    progress.stage("enclosed share");
    const double share = enclosed_share(mesh, *winding);
    clock.lap("enclosed share");
    stats.enclosed_share = share;
    const bool encloses = share >= min_enclosed_share;
    if (!encloses && options.thicken <= 0.0) {
        std::ostringstream message;
        message.precision(2);
        message << options.input_name << ": encloses no volume (an open sheet, a single scan, a flat sliver, a "
                << "soup of unconnected triangles, or a tangle of inconsistently wound pieces: the winding number is "
                << "near 1 beside only " << 100.0 * share
                << "% of its surface); give a thickness (--thicken) to make it a solid sheet";
        throw Error(FABVDB_ERR_BAD_INPUT, message.str());
    }

    const openvdb::Int32Grid::Ptr closest_triangle = oriented ? openvdb::Int32Grid::create(-1) : nullptr;
    openvdb::FloatGrid::Ptr grid;
    if (encloses) {
        progress.stage("distance");
        grid = unsigned_band(mesh, *transform, half_band, progress, closest_triangle.get());
        clock.lap("distance");
    }

    std::vector<float> band_winding;    // per band leaf, w at its voxels
    std::vector<double> leaf_gradient;  // per band leaf, the bound on |grad w| over it
    std::vector<char> band_exact;       // per band leaf, whether every w was taken at its voxel
    std::atomic<uint64_t> clearly_inside_voxels{0};
    if (encloses) {
        progress.stage("winding number");
        openvdb::tree::LeafManager<openvdb::FloatTree> leaves(grid->tree());
        band_winding.assign(leaves.leafCount() * size_t(leaf_size), 0.0f);
        leaf_gradient.assign(leaves.leafCount(), 0.0);
        band_exact.assign(leaves.leafCount(), 0);
        const float smallest_distance = float(1e-6 * voxel);
        for_each_index(leaves.leafCount(), progress, [&](size_t i) {
            uint64_t inside = 0;
            float* leaf_winding = &band_winding[i * leaf_size];
            leaf_gradient[i] = (*gradient_bound)(leaf_box(leaves.leaf(i), *transform), gradient_cap(voxel));
            band_exact[i] = band_leaf_winding(leaves.leaf(i), *winding, *transform, leaf_gradient[i], leaf_winding);
            for (auto voxel_it = leaves.leaf(i).beginValueOn(); voxel_it; ++voxel_it) {
                const double w = leaf_winding[voxel_it.pos()];
                // Inside values are strictly negative, also on a triangle
                // (-0.0 would read as outside in every sign test).
                if (w >= inside_winding) voxel_it.setValue(-std::max(*voxel_it, smallest_distance));
                if (w >= clearly_inside) ++inside;
            }
            clearly_inside_voxels += inside;
        });
        clock.lap("winding number");
    }

    if (clearly_inside_voxels == 0) {
        if (options.thicken <= 0.0)
            throw Error(FABVDB_ERR_BAD_INPUT, options.input_name + ": encloses no volume at a voxel size of " +
                                                  std::to_string(voxel) +
                                                  " mm: no voxel lies inside it (walls thinner than a voxel); "
                                                  "give a smaller voxel size, or a thickness (--thicken) to make "
                                                  "it a solid sheet");
        progress.stage("thicken");
        const double half_thickness = 0.5 * options.thicken;
        grid = unsigned_band(mesh, *transform, float(std::ceil(half_thickness / voxel)) + half_band, progress,
                             closest_triangle.get());
        grid = rebuild_band(*grid, half_thickness, options.half_band_voxels, progress);
        stats.thickened = stats.rebuilt = true;
        clock.lap("thicken");
    } else if (band_is_consistent(*grid, voxel, closed)) {
        progress.stage("flood fill");
        openvdb::tools::signedFloodFill(grid->tree());
        clock.lap("flood fill");
    } else {
        progress.stage("rebuild");
        // A closed-cycle input has no hole for the winding number to close
        // off the band: every region off it borders band voxels of its own
        // side, so a flood fill signs it.
        if (closed)
            openvdb::tools::signedFloodFill(grid->tree());
        else
            add_off_band_winding(*grid, *winding, bounding_box(mesh), *gradient_bound, band_winding, leaf_gradient,
                                 band_exact, progress);
        band_winding = {};
        progress.stage("rebuild");
        grid = rebuild_band(*grid, 0.0, options.half_band_voxels, progress);
        stats.rebuilt = true;
        clock.lap("rebuild");
    }
    grid->setTransform(transform);
    grid->setGridClass(openvdb::GRID_LEVEL_SET);
    grid->setName("surface");
    stats.active_voxels = grid->activeVoxelCount();
    if (stats_out) *stats_out = stats;
    if (oriented) *oriented = {std::move(mesh), closest_triangle};
    return grid;
}

}  // namespace fabvdb::volume
