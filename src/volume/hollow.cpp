//! Hollowing (see hollow.h): outer surface, interior distance band, cavity
//! offset and opening, exact snap, void regions, separation proof.
#include "volume/hollow.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <type_traits>

#include <openvdb/tools/FastSweeping.h>
#include <openvdb/tree/NodeManager.h>
#include <tbb/enumerable_thread_specific.h>

#include "core/centred_frame.h"
#include "core/error.h"
#include "core/float_coordinates.h"
#include "core/stage_clock.h"
#include "core/turned_inside_out.h"
#include "volume/cavity_regions.h"
#include "volume/clean_solid.h"
#include "volume/extract_mesh.h"
#include "volume/faithful_repair.h"
#include "volume/input_fidelity.h"
#include "volume/memory_estimate.h"
#include "volume/mesh_shells.h"
#include "volume/repair.h"
#include "volume/resolve_crossings.h"
#include "volume/signed_distance.h"
#include "volume/snap_to_offset.h"
#include "volume/solid_distance.h"
#include "volume/surfaces_disjoint.h"

namespace fabvdb::volume {

namespace {

//! Halvings of the hollowing's voxel a repaired outer surface that lost the
//! model gets: 0.5 mm (a 2 mm wall) becomes at most 0.125 mm.
constexpr int kOuterSurfaceRefinements = 2;

void require(bool ok, const std::string& message) {
    if (!ok) throw Error(FABVDB_ERR_INVALID_ARGUMENT, message);
}

void validate(const HollowOptions& o) {
    require(std::isfinite(o.wall) && o.wall > 0.0, "wall must be > 0 mm");
    require(std::isfinite(o.closing) && o.closing >= 0.0, "closing distance must be >= 0 mm");
    require(std::isfinite(o.voxel_size) && o.voxel_size >= 0.0, "voxel size must be > 0 mm (0: automatic)");
    require(o.voxel_size == 0.0 || o.voxel_size <= o.wall,
            "voxel size must not exceed the wall (a wall needs at least one voxel)");
    require(o.adaptivity >= 0.0 && o.adaptivity <= 1.0, "adaptivity must be in [0, 1]");
    require(std::isfinite(o.min_cavity_volume) && o.min_cavity_volume >= 0.0, "minimum cavity volume must be >= 0");
    require(std::isfinite(o.infill.cell) && o.infill.cell >= 0.0, "infill cell must be >= 0 mm (0: no infill)");
    if (o.infill.cell > 0.0) validate_gyroid_struts(o.infill);
}

//! Adds `offset` to every value of `grid` (voxels, tiles and background),
//! so that its `-offset` iso-surface becomes the zero one. Node by node, in
//! parallel: a tree-wide iterator over all values would step through every
//! inactive tile of the upper nodes one by one.
void shift(openvdb::FloatGrid& grid, float offset) {
    openvdb::tree::NodeManager<openvdb::FloatTree> nodes(grid.tree());
    nodes.foreachTopDown([offset](auto& node) {
        using Node = std::decay_t<decltype(node)>;
        if constexpr (Node::LEVEL == 0) {
            float* values = node.buffer().data();
            for (openvdb::Index i = 0; i < Node::SIZE; ++i) values[i] += offset;
        } else {
            for (auto it = node.beginValueAll(); it; ++it) it.setValue(*it + offset);
        }
    });
    grid.tree().root().setBackground(grid.background() + offset, false);
}

//! The deepest value of a solid's distance band (tiles included), as a depth.
double deepest(const openvdb::FloatGrid& grid) {
    tbb::enumerable_thread_specific<float> lowest(0.0f);
    openvdb::tree::NodeManager<const openvdb::FloatTree> nodes(grid.tree());
    nodes.foreachTopDown([&lowest](const auto& node) {
        using Node = std::decay_t<decltype(node)>;
        float& low = lowest.local();
        if constexpr (Node::LEVEL == 0) {
            const float* values = node.buffer().data();
            for (openvdb::Index i = 0; i < Node::SIZE; ++i) low = std::min(low, values[i]);
        } else {
            for (auto it = node.cbeginValueAll(); it; ++it) low = std::min(low, *it);
        }
    });
    return -double(lowest.combine([](float a, float b) { return std::min(a, b); }));
}

//! The radius the cavity is opened by: the closing distance, at least one
//! voxel, so void slivers thinner than two voxels are dropped (the part stays
//! solid there) and every remaining cavity vertex can take the exact wall.
double cavity_opening(const HollowOptions& o, double voxel) { return std::max(o.closing, voxel); }

void check_budget(const Mesh& outer, const HollowOptions& o, double voxel) {
    if (o.memory_budget_bytes == 0) return;
    const double area = surface_area(outer);
    const int half_band = int(std::ceil(0.5 * ((o.wall + cavity_opening(o, voxel)) / voxel + 5.0)));
    uint64_t bytes = estimate_level_set_bytes(area, voxel, half_band);
    if (o.infill.cell > 0.0) {
        const BoundingBox box = bounding_box(outer);
        const double box_volume = (box.max[0] - box.min[0]) * (box.max[1] - box.min[1]) * (box.max[2] - box.min[2]);
        bytes = std::max(bytes, estimate_gyroid_struts_bytes(o.infill, box_volume, voxel));
    }
    if (bytes <= o.memory_budget_bytes) return;
    std::ostringstream message;
    message.precision(3);
    message << o.input_name << ": hollowing at voxel " << voxel << " mm needs ~" << double(bytes) / double(1ull << 30)
            << " GiB (budget " << double(o.memory_budget_bytes) / double(1ull << 30) << " GiB); --voxel "
            << voxel_size_for_budget(area, half_band, o.memory_budget_bytes) << "mm fits";
    throw Error(FABVDB_ERR_OUT_OF_BUDGET, message.str());
}

// Whether `mesh`, a clean solid in doubles given in `frame`, stays one as an
// STL file stores it (float_coordinates.h). The crossings of overlapping
// shells, cut in doubles, may lie closer than a float step.
bool clean_in_floats(Mesh mesh, const CentredFrame& frame, Progress& progress) {
    for (Vec3& p : mesh.vertices) p = stored_position(p, frame);
    return check_solid(mesh, progress).clean;
}

//! The outer surface: the input itself when it is clean, its shells' union
//! when only crossings spoil it and the union survives float rounding, else
//! the surface of its robust signed distance. Sets the result's
//! outer_surface and fidelity (and a warning when the union was refused).
Mesh outer_surface(const Mesh& input, const HollowOptions& options, double voxel, const CentredFrame& frame,
                   HollowResult& result, StageClock& clock, Progress& progress) {
    check_budget(input, options, voxel);
    const SolidCheck check = check_solid(input, progress);
    clock.lap("check input");
    std::optional<Mesh> resolved;
    if (!check.crossings.empty()) {
        resolved = resolve_crossings(input, check.crossings, progress);
        if (resolved && !clean_in_floats(*resolved, frame, progress)) resolved.reset();
        clock.lap("resolve crossings");
    }
    // The union must still be the input's model, as every outer surface
    // not the input's own (input_fidelity.h); else voxels repair the input.
    if (resolved) {
        result.fidelity_limits = exact_limits(input);
        result.fidelity = measure_fidelity(input, *resolved, result.fidelity_limits, progress);
        if (!result.fidelity.passed) {
            result.warnings.push_back(options.input_name + ": the union of its crossing shells was not the input's model (" +
                                      result.fidelity.defect + "), so voxels repaired it");
            resolved.reset();
        }
        clock.lap("fidelity");
    }
    if (check.clean) {
        result.outer_surface = "input";
        return input;
    }
    if (resolved) {
        result.outer_surface = "resolved";
        return std::move(*resolved);
    }
    // At the hollowing's voxel, coarser than a repair's, thin features of a
    // dirty input may be lost: the outer surface is refined until it is the
    // input's model (faithful_repair.h).
    RepairOptions repair_options;
    repair_options.distance.voxel_size = voxel;
    repair_options.distance.memory_budget_bytes = options.memory_budget_bytes;
    repair_options.distance.input_name = options.input_name;
    FaithfulRepair repaired =
        faithful_repair(input, input, repair_options, kOuterSurfaceRefinements, &frame, progress);
    result.outer_surface = "repaired";
    result.outer_surface_voxel = repaired.voxels.back();
    result.warnings.insert(result.warnings.end(), repaired.warnings.begin(), repaired.warnings.end());
    result.fidelity_limits = repaired.limits;
    result.fidelity = repaired.fidelity;
    clock.lap("repair");
    require_faithful(result.fidelity, options.input_name, "hollowed part's outer surface");
    return std::move(repaired.repaired.mesh);
}

//! The cavity's surface, before the snap: the core at -(wall + opening) of
//! the outer surface's interior distance, its distance rebuilt by fast
//! sweeping, grown back by the opening, the infill's struts carved out. No
//! value that deep: no core, so no cavity (the part is nowhere thick enough
//! for one; a warning says so) and an empty surface. `closest_triangle`
//! receives the interior distance's nearest triangles, which the snap reads.
Mesh cavity_before_snap(const Mesh& outer, const HollowOptions& options, double voxel, HollowResult& result,
                        StageClock& clock, Progress& progress, openvdb::Int32Grid::Ptr& closest_triangle) {
    // Distances down to the deepest iso-surface the cavity needs.
    const double opening = cavity_opening(options, voxel);
    const double depth = options.wall + opening;
    SolidDistance solid = solid_distance(outer, voxel, depth, progress);
    clock.lap("interior distance");
    const double thickest = deepest(*solid.distance);
    if (thickest <= depth) {
        std::ostringstream message;
        message.precision(3);
        message << options.input_name << ": wall " << options.wall << " mm";
        if (opening > 0.0) message << " (and " << opening << " mm to open the cavity)";
        message << " leaves no cavity: the part is nowhere thicker than " << 2.0 * thickest
                << " mm; it is returned solid";
        result.warnings.push_back(message.str());
    }
    progress.stage("cavity offset");
    openvdb::FloatGrid::Ptr cavity;
    if (thickest > depth) {
        cavity = openvdb::tools::sdfToSdf(*solid.distance, float(-depth));
        shift(*cavity, float(-opening));
    }
    solid.distance.reset();
    closest_triangle = std::move(solid.closest_triangle);
    progress.check();
    clock.lap("cavity offset");
    if (cavity && options.infill.cell > 0.0) cavity = carve_gyroid_struts(*cavity, options.infill, progress);
    if (options.infill.cell > 0.0) clock.lap("infill");
    Mesh surface = cavity ? extract_mesh(*cavity, options.adaptivity, progress) : Mesh{};
    cavity.reset();
    clock.lap("cavity extraction");
    return surface;
}

//! The voids large enough to keep, as indices into `regions`; the others are
//! filled (their volumes go to the result's filled_cavity_volumes). Solid
//! left floating in a void (where the opening closes around a pocket) would
//! print loose: it becomes void, and so does any void inside it (a warning
//! counts those pieces).
std::vector<size_t> voids_kept(const std::vector<CavityRegion>& regions, const HollowOptions& options,
                               HollowResult& result) {
    std::vector<size_t> open_regions;
    size_t islands = 0;
    double island_volume = 0.0;
    for (size_t r = 0; r < regions.size(); ++r) {
        const CavityRegion& region = regions[r];
        if (region.in_island) continue;
        islands += split_shells(region.islands).size();
        island_volume += region.island_volume;
        const double volume = region.volume + region.island_volume;
        if (volume >= options.min_cavity_volume && volume > 0.0)
            open_regions.push_back(r);
        else
            result.filled_cavity_volumes.push_back(volume);
    }
    if (islands > 0) {
        std::ostringstream message;
        message.precision(3);
        message << options.input_name << ": removed " << islands << " piece(s) of solid (" << island_volume
                << " mm³) that the cavity left floating inside it, which would print loose";
        result.warnings.push_back(message.str());
    }
    return open_regions;
}

//! The surfaces of the kept voids that stay clear of the outer surface. A
//! void whose surface touches the outer one (where a repaired or resolved
//! outer surface folds closer than the wall) is filled: the part keeps its
//! wall there, and the hollowed mesh its separation. Sets the result's
//! cavity_volumes and adds to filled_cavity_volumes (with a warning).
Mesh voids_clear_of(const Mesh& outer, const std::vector<CavityRegion>& regions,
                    const std::vector<size_t>& open_regions, const HollowOptions& options, HollowResult& result,
                    Progress& progress) {
    Mesh kept;
    std::vector<size_t> first_triangle;
    for (size_t r : open_regions) {
        first_triangle.push_back(kept.triangles.size());
        append(kept, regions[r].surface);
    }
    first_triangle.push_back(kept.triangles.size());
    const std::vector<char> touching = cavity_triangles_touching(outer, kept, progress);
    Mesh clear;
    size_t touching_count = 0;
    double touching_volume = 0.0;
    for (size_t k = 0; k < open_regions.size(); ++k) {
        const CavityRegion& region = regions[open_regions[k]];
        const double volume = region.volume + region.island_volume;
        if (std::any_of(touching.begin() + ptrdiff_t(first_triangle[k]),
                        touching.begin() + ptrdiff_t(first_triangle[k + 1]), [](char t) { return t != 0; })) {
            ++touching_count;
            touching_volume += volume;
            result.filled_cavity_volumes.push_back(volume);
        } else {
            result.cavity_volumes.push_back(volume);
            append(clear, region.surface);
        }
    }
    if (touching_count > 0) {
        std::ostringstream message;
        message.precision(3);
        message << options.input_name << ": " << touching_count << (touching_count == 1 ? " void" : " voids") << " ("
                << touching_volume << " mm³) that would touch the outer surface "
                << (touching_count == 1 ? "is" : "are") << " left solid";
        result.warnings.push_back(message.str());
    }
    return clear;
}

HollowResult hollow_in_frame(const Mesh& input, const HollowOptions& options, const CentredFrame& frame,
                             Progress& progress) {
    openvdb::initialize();
    HollowResult result;
    StageClock clock(result.timings);
    // With infill at most strut / 4 automatically, so a strut is four voxels across.
    const double voxel = options.voxel_size > 0.0 ? options.voxel_size
                         : options.infill.cell > 0.0
                             ? std::min(automatic_hollow_voxel(options.wall), options.infill.strut / 4.0)
                             : automatic_hollow_voxel(options.wall);
    result.voxel_size = voxel;

    Mesh outer = outer_surface(input, options, voxel, frame, result, clock, progress);
    result.volume_solid = signed_volume(outer);

    openvdb::Int32Grid::Ptr closest_triangle;
    Mesh cavity_surface = cavity_before_snap(outer, options, voxel, result, clock, progress, closest_triangle);

    // Strut surfaces lie deeper than the wall: with infill only shallow vertices move.
    const OffsetSnap snap =
        options.closing == 0.0 && options.infill.cell == 0.0 ? OffsetSnap::exact : OffsetSnap::at_least;
    const SnapStats snapped = snap_to_offset(cavity_surface, outer, *closest_triangle, options.wall, snap, progress);
    result.min_wall_at_vertices = snapped.min_depth;
    clock.lap("snap");

    const std::vector<CavityRegion> regions = split_cavity_regions(cavity_surface);
    const std::vector<size_t> open_regions = voids_kept(regions, options, result);
    clock.lap("cavity regions");
    Mesh kept = voids_clear_of(outer, regions, open_regions, options, result, progress);
    clock.lap("separation check");

    result.mesh = std::move(outer);
    append(result.mesh, turned_inside_out(std::move(kept)));
    result.volume_shell = result.volume_solid;
    for (double v : result.cavity_volumes) result.volume_shell -= v;
    return result;
}

}  // namespace

double automatic_hollow_voxel(double wall) { return wall / 4.0; }

HollowResult hollow(const Mesh& input, const HollowOptions& options, Progress& progress) {
    validate(options);
    validate_mesh(input, options.input_name);
    if (input.triangles.empty()) throw Error(FABVDB_ERR_BAD_INPUT, options.input_name + ": no triangles");
    const CentredFrame frame = centred_frame(input);
    HollowResult result = hollow_in_frame(to_local(input, frame), options, frame, progress);
    to_world(result.mesh, frame);
    return result;
}

openvdb::FloatGrid::Ptr shell_level_set(const Mesh& hollowed, double voxel_size, Progress& progress) {
    SignedDistanceOptions options;
    options.voxel_size = voxel_size;
    options.input_name = "hollowed mesh";
    return signed_distance_from_mesh(hollowed, options, progress);
}

}  // namespace fabvdb::volume
