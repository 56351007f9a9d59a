//! C API: drainability — drain-hole planning and drilling (`fabvdb drain`)
//! and the reference powder simulation (`fabvdb powder-sim`).
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "api/fidelity_report.h"
#include "api/guard.h"
#include "api/options.h"
#include "core/colour_bar.h"
#include "core/mesh.h"
#include "core/stage_clock.h"
#include "core/turned_inside_out.h"
#include "powder/cleaning_routine.h"
#include "powder/drain_part.h"
#include "powder/heatmap_ply.h"
#include "powder/keep_out.h"
#include "powder/sandpile_routine.h"
#include "powder/sandpile_simulation.h"
#include "core/icosphere.h"
#include "volume/signed_distance.h"

namespace {

constexpr double kDegree = M_PI / 180.0;

std::vector<fabvdb::Vec3> orientation_list(const double* values, size_t count) {
    std::vector<fabvdb::Vec3> list;
    if (!values) return list;
    for (size_t i = 0; i < count; ++i) {
        const fabvdb::Vec3 g{values[3 * i], values[3 * i + 1], values[3 * i + 2]};
        const double length = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        if (!(length > 0.0) || !std::isfinite(length))
            throw fabvdb::Error(FABVDB_ERR_INVALID_ARGUMENT, "orientation " + std::to_string(i + 1) + " is not a direction");
        list.push_back({g[0] / length, g[1] / length, g[2] / length});
    }
    return list;
}

//! Throws Error(INVALID_ARGUMENT) with `message` unless `ok`: the one place
//! the ranges of the drain and powder options are checked (the CLI maps the
//! status to exit code 1).
void require_range(bool ok, const char* message) {
    if (!ok) throw fabvdb::Error(FABVDB_ERR_INVALID_ARGUMENT, message);
}

nlohmann::json vec_json(const fabvdb::Vec3& v) { return nlohmann::json::array({v[0], v[1], v[2]}); }

nlohmann::json holes_json(const std::vector<fabvdb::powder::DrainHole>& holes) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& hole : holes)
        list.push_back({{"center", vec_json(hole.center)},
                        {"axis", vec_json(hole.axis)},
                        {"diameter", hole.diameter},
                        {"depth", hole.depth},
                        {"cavity", hole.cavity}});
    return list;
}

fabvdb::Vec3 read_vec(const nlohmann::json& item, const char* key, size_t index) {
    const std::string where = "holes[" + std::to_string(index) + "]." + key;
    if (!item.contains(key) || !item[key].is_array() || item[key].size() != 3)
        throw fabvdb::Error(FABVDB_ERR_BAD_INPUT, where + " must be an array of three numbers");
    fabvdb::Vec3 v;
    for (int k = 0; k < 3; ++k) {
        if (!item[key][k].is_number()) throw fabvdb::Error(FABVDB_ERR_BAD_INPUT, where + " must hold numbers");
        v[k] = item[key][k].get<double>();
    }
    return v;
}

std::vector<fabvdb::powder::SandpileHole> parse_holes(const char* text) {
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw fabvdb::Error(FABVDB_ERR_BAD_INPUT, std::string("the holes are not valid JSON: ") + e.what());
    }
    if (!document.is_object() || !document.contains("holes") || !document["holes"].is_array())
        throw fabvdb::Error(FABVDB_ERR_BAD_INPUT, "the holes JSON has no \"holes\" array");
    std::vector<fabvdb::powder::SandpileHole> holes;
    size_t index = 0;
    for (const nlohmann::json& item : document["holes"]) {
        if (!item.is_object()) throw fabvdb::Error(FABVDB_ERR_BAD_INPUT, "holes[" + std::to_string(index) + "] is not an object");
        fabvdb::powder::SandpileHole hole;
        hole.center = read_vec(item, "center", index);
        hole.axis = read_vec(item, "axis", index);
        const double length = std::sqrt(hole.axis[0] * hole.axis[0] + hole.axis[1] * hole.axis[1] + hole.axis[2] * hole.axis[2]);
        if (!(length > 0.0)) throw fabvdb::Error(FABVDB_ERR_BAD_INPUT, "holes[" + std::to_string(index) + "].axis is zero");
        for (double& c : hole.axis) c /= length;
        if (!item.contains("diameter") || !item["diameter"].is_number() || !(item["diameter"].get<double>() > 0.0))
            throw fabvdb::Error(FABVDB_ERR_BAD_INPUT, "holes[" + std::to_string(index) + "].diameter must be a positive number");
        hole.diameter = item["diameter"].get<double>();
        hole.depth = 4.0 * hole.diameter;
        if (item.contains("depth")) {
            if (!item["depth"].is_number() || !(item["depth"].get<double>() > 0.0))
                throw fabvdb::Error(FABVDB_ERR_BAD_INPUT, "holes[" + std::to_string(index) + "].depth must be a positive number");
            hole.depth = item["depth"].get<double>();
        }
        holes.push_back(hole);
        ++index;
    }
    return holes;
}

//! The gravities of a routine to replay: a drain report's routine[] of
//! {gravity}, or an array of [x, y, z].
std::vector<fabvdb::Vec3> parse_routine(const char* text) {
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw fabvdb::Error(FABVDB_ERR_BAD_INPUT, std::string("the routine is not JSON: ") + e.what());
    }
    const nlohmann::json& steps = document.is_object() && document.contains("routine") ? document["routine"] : document;
    if (!steps.is_array() || steps.empty())
        throw fabvdb::Error(FABVDB_ERR_BAD_INPUT, "the routine must be a non-empty array (or a drain report's routine[])");
    std::vector<double> values;
    for (size_t i = 0; i < steps.size(); ++i) {
        const nlohmann::json& g = steps[i].is_object() && steps[i].contains("gravity") ? steps[i]["gravity"] : steps[i];
        if (!g.is_array() || g.size() != 3 || !g[0].is_number() || !g[1].is_number() || !g[2].is_number())
            throw fabvdb::Error(FABVDB_ERR_BAD_INPUT,
                                "routine[" + std::to_string(i) + "] must be [x, y, z] or have a gravity [x, y, z]");
        for (int k = 0; k < 3; ++k) values.push_back(g[k].get<double>());
    }
    return orientation_list(values.data(), steps.size());
}

//! The cleaning routine as the report gives it: each turn's gravity, the
//! hole that points down, the tilt from the previous turn and the words.
nlohmann::json routine_json(const fabvdb::powder::DrainPlan& plan) {
    nlohmann::json steps = nlohmann::json::array();
    for (const auto& step : fabvdb::powder::cleaning_steps(plan.holes, plan.first_gravity, plan.routine))
        steps.push_back({{"gravity", vec_json(step.gravity)},
                         {"hole_down", step.hole_down >= 0 ? nlohmann::json(step.hole_down) : nlohmann::json()},
                         {"lowest_hole", step.lowest_hole >= 0 ? nlohmann::json(step.lowest_hole) : nlohmann::json()},
                         {"tilt_degrees", step.tilt_degrees},
                         {"tilt_axis", vec_json(step.tilt_axis)},
                         {"instruction", step.instruction}});
    return steps;
}

//! Mean, standard deviation, least and most of the random routines' residual fractions.
nlohmann::json spread_json(const std::vector<double>& residuals, double total) {
    if (residuals.empty() || !(total > 0.0)) return nullptr;
    double sum = 0.0, squares = 0.0;
    for (double r : residuals) sum += r / total;
    const double mean = sum / double(residuals.size());
    for (double r : residuals) squares += (r / total - mean) * (r / total - mean);
    const auto [least, most] = std::minmax_element(residuals.begin(), residuals.end());
    return {{"routines", residuals.size()},
            {"mean_fraction", mean},
            {"std_fraction", std::sqrt(squares / double(residuals.size()))},
            {"min_fraction", *least / total},
            {"max_fraction", *most / total}};
}

//! The drain's two heat maps under the cleaning routine, per vertex of the
//! cavity surface: the share of the powder resting there at the start that
//! drains (over [0, 1]) and the powder left at the end, mm³ per mm² (over
//! [0, left_top]); and the share drained averaged by powder.
struct HeatMaps {
    std::vector<double> share, left;
    double left_top = 1.0;
    double mean_by_powder = 1.0;
};

HeatMaps heat_maps(const fabvdb::powder::DrainPlan& plan) {
    const auto& patches = plan.patches;
    const auto& evaluation = plan.routine_evaluation;
    std::vector<double> depth(patches.size(), 0.0);
    for (size_t j = 0; j < patches.size(); ++j)
        depth[j] = patches.area[j] > 0.0 ? evaluation.left_per_patch[j] / patches.area[j] : 0.0;
    HeatMaps maps;
    maps.share = fabvdb::powder::vertex_values(plan.cavity_surface, patches, evaluation.drained_share);
    maps.left = fabvdb::powder::vertex_values(plan.cavity_surface, patches, depth);
    double deepest = 0.0;
    for (double v : maps.left) deepest = std::max(deepest, v);
    maps.left_top = deepest > 0.0 ? deepest : 1.0;
    double weighted = 0.0, initial = 0.0;
    for (size_t j = 0; j < patches.size(); ++j) {
        weighted += evaluation.initial_per_patch[j] * evaluation.drained_share[j];
        initial += evaluation.initial_per_patch[j];
    }
    maps.mean_by_powder = initial > 0.0 ? weighted / initial : 1.0;
    return maps;
}

//! What the report says of the heat maps: their ranges and mean.
nlohmann::json heat_maps_json(const HeatMaps& maps) {
    return {{"drained_share", {{"min", 0.0}, {"max", 1.0}, {"mean_by_powder", maps.mean_by_powder}}},
            {"powder_left", {{"min", 0.0}, {"max", maps.left_top}, {"unit", "mm3/mm2"}}}};
}

//! Writes the heat maps and their legends (see fabvdb_drain_options'
//! heatmap_path): the share that drains at `path`, the powder left at
//! STEM_left.ply, each with STEM.png; adds the files to `entry`.
void write_heat_maps(const fabvdb::powder::DrainPlan& plan, const HeatMaps& maps, const std::string& path,
                     nlohmann::json& entry) {
    const std::string stem =
        path.size() > 4 && path.compare(path.size() - 4, 4, ".ply") == 0 ? path.substr(0, path.size() - 4) : path;
    fabvdb::powder::write_heatmap_ply(plan.cavity_surface, maps.share, 0.0, 1.0,
                                      "share of the powder resting here at the start that drains", path);
    fabvdb::write_colour_bar_png(stem + ".png", "powder that drains", 0.0, 1.0, "");
    fabvdb::powder::write_heatmap_ply(plan.cavity_surface, maps.left, 0.0, maps.left_top,
                                      "powder left at the end, mm3 per mm2 of surface", stem + "_left.ply");
    fabvdb::write_colour_bar_png(stem + "_left.png", "powder left", 0.0, maps.left_top, "mm");
    entry["drained_share"]["path"] = path;
    entry["drained_share"]["legend"] = stem + ".png";
    entry["powder_left"]["path"] = stem + "_left.ply";
    entry["powder_left"]["legend"] = stem + "_left.png";
}

}  // namespace

//! The heat maps as data (see fabvdb.h): the cavity surface turned to face
//! the powder, as the files have it, and each kind's values and colours.
struct fabvdb_heatmap {
    std::unique_ptr<fabvdb_mesh> surface;
    std::vector<double> values[2];
    std::vector<uint8_t> colours[2];
};

namespace {

std::unique_ptr<fabvdb_heatmap> new_heatmap_handle(const fabvdb::powder::DrainPlan& plan, HeatMaps maps) {
    auto handle = std::make_unique<fabvdb_heatmap>();
    handle->surface.reset(fabvdb::api::new_mesh_handle(fabvdb::turned_inside_out(plan.cavity_surface)));
    const double top[2] = {1.0, maps.left_top};
    handle->values[FABVDB_HEATMAP_DRAINED] = std::move(maps.share);
    handle->values[FABVDB_HEATMAP_LEFT] = std::move(maps.left);
    for (int kind : {FABVDB_HEATMAP_DRAINED, FABVDB_HEATMAP_LEFT}) {
        std::vector<uint8_t>& colours = handle->colours[kind];
        for (const auto& rgb : fabvdb::powder::heatmap_colours(handle->values[kind], 0.0, top[kind]))
            colours.insert(colours.end(), rgb.begin(), rgb.end());
    }
    return handle;
}

//! fabvdb_mesh_drain, and with `out_heatmap` (else NULL) fabvdb_mesh_drain_heatmap, inside the guard.
void drain(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, const fabvdb_drain_options* options, fabvdb_mesh** out_mesh,
           fabvdb_report** out_report, fabvdb_heatmap** out_heatmap) {
    fabvdb::api::require(mesh, "mesh");
    fabvdb::api::require(out_mesh, "out_mesh");
    const fabvdb_drain_options o =
        fabvdb::api::options_from(options, fabvdb_drain_options_init, "fabvdb_drain_options");
    require_range(std::isfinite(o.wall) && o.wall > 0.0, "wall must be > 0 mm");
    require_range(std::isfinite(o.hole_diameter) && o.hole_diameter > 0.0, "hole_diameter must be > 0 mm");
    require_range(o.repose_degrees > 0.0 && o.repose_degrees < 90.0, "repose_degrees must be in (0, 90)");
    require_range(o.effort >= 0.0 && o.effort < 1.0, "effort must be in [0, 1)");
    require_range(o.hole_count >= 0, "hole_count must be >= 0 (0: automatic)");
    require_range(o.patch_count >= 10, "patch_count must be >= 10");
    require_range(o.target_residual >= 0.0 && o.target_residual < 1.0, "target_residual must be in [0, 1)");
    require_range(std::isfinite(o.voxel_size) && o.voxel_size >= 0.0, "voxel_size must be >= 0 mm (0: wall / 4)");
    fabvdb::Progress progress = ctx->make_progress();
    fabvdb::powder::DrainPartOptions part_options;
    part_options.wall = o.wall;
    part_options.input_name = mesh->name;
    part_options.voxel_size = o.voxel_size;
    part_options.memory_budget_bytes = ctx->budget_bytes();
    part_options.plan.hole_diameter = o.hole_diameter;
    part_options.plan.repose_radians = o.repose_degrees * kDegree;
    part_options.plan.effort = o.effort;
    part_options.plan.orientations = orientation_list(o.orientations, o.orientation_count);
    part_options.plan.first_gravity = orientation_list(o.first_gravity, 1).front();
    part_options.plan.patch_count = size_t(o.patch_count);
    part_options.plan.search.hole_count = o.hole_count;
    part_options.plan.search.target_residual_fraction = o.target_residual;
    if (o.keep_out_path)
        part_options.plan.keep_out = fabvdb::powder::read_keep_out(
            o.keep_out_path, o.voxel_size > 0 ? o.voxel_size : o.wall / 4.0, 0.5 * o.hole_diameter, progress);
    fabvdb::powder::DrainPartResult result = fabvdb::powder::drain_part(mesh->mesh, part_options, progress);
    const auto timings_with_total = [&result] {
        nlohmann::json timings = result.timings;
        double total = 0.0;
        for (const auto& [name, seconds] : result.timings) total += seconds;
        timings["total"] = total;
        return timings;
    };
    if (!result.has_cavity) {
        nlohmann::json report = {{"holes", nlohmann::json::array()},
                                 {"predicted_residual_fraction", 0.0},
                                 {"predicted_residual_volume", 0.0},
                                 {"baseline_holes", nlohmann::json::array()},
                                 {"baseline_residual_fraction", 0.0},
                                 {"baseline_residual_volume", 0.0},
                                 {"cavity_volume", 0.0},
                                 {"cavities", 0},
                                 {"cavity_count", 0},
                                 {"input_was_hollow", result.input_was_hollow},
                                 {"fidelity", fabvdb::api::fidelity_report(result.fidelity, result.fidelity_limits)},
                                 {"voxel_size", result.voxel_size},
                                 {"timings", timings_with_total()},
                                 {"warnings", result.warnings}};
        std::unique_ptr<fabvdb_report> report_handle(
            out_report ? fabvdb::api::new_report_handle(std::move(report)) : nullptr);
        *out_mesh = fabvdb::api::new_mesh_handle(std::move(result.drilled), true);
        if (out_report) *out_report = report_handle.release();
        if (out_heatmap) *out_heatmap = nullptr;
        return;
    }
    const auto& plan = result.plan;
    nlohmann::json heatmap;
    std::unique_ptr<fabvdb_heatmap> heatmap_handle;
    if (o.heatmap_path || out_heatmap) {
        fabvdb::StageClock clock(result.timings);
        HeatMaps maps = heat_maps(plan);
        heatmap = heat_maps_json(maps);
        if (o.heatmap_path) write_heat_maps(plan, maps, o.heatmap_path, heatmap);
        if (out_heatmap) heatmap_handle = new_heatmap_handle(plan, std::move(maps));
        clock.lap("heat map");
    }
    nlohmann::json report;
    report["holes"] = holes_json(plan.holes);
    report["predicted_residual_fraction"] = plan.evaluation.residual_fraction();
    report["predicted_residual_volume"] = plan.evaluation.residual_volume;
    report["routine"] = routine_json(plan);
    report["routine_residual_fraction"] = plan.routine_evaluation.residual_fraction();
    report["routine_residual_volume"] = plan.routine_evaluation.residual_volume;
    report["random_routines"] = spread_json(plan.random_residuals, plan.evaluation.total_volume);
    report["baseline_holes"] = holes_json(plan.baseline);
    report["baseline_routine_residual_fraction"] =
        plan.evaluation.total_volume > 0 ? plan.baseline_routine_residual / plan.evaluation.total_volume : 0.0;
    report["baseline_residual_fraction"] = plan.baseline_evaluation.residual_fraction();
    report["baseline_residual_volume"] = plan.baseline_evaluation.residual_volume;
    report["cavity_volume"] = plan.evaluation.total_volume;
    report["cavities"] = plan.patches.cavity_count;
    report["cavity_count"] = plan.patches.cavity_count;
    report["warnings"] = result.warnings;
    report["residual_volume_per_cavity"] = plan.evaluation.residual_per_cavity;
    report["patches"] = plan.patches.size();
    report["candidates"] = plan.candidate_count;
    report["input_was_hollow"] = result.input_was_hollow;
    report["filled_cavities"] = nlohmann::json::array();
    for (const auto& [center, radius] : result.filled_cavities)
        report["filled_cavities"].push_back({{"center", vec_json(center)}, {"radius", radius}});
    report["fidelity"] = fabvdb::api::fidelity_report(result.fidelity, result.fidelity_limits);
    report["voxel_size"] = result.voxel_size;
    report["surface_voxel"] = result.surface_voxel;
    report["repose_degrees"] = o.repose_degrees;
    report["effort"] = o.effort;
    report["orientations"] = o.orientations ? o.orientation_count : size_t(162);
    if (!heatmap.is_null()) report["heatmap"] = heatmap;
    report["timings"] = timings_with_total();
    std::unique_ptr<fabvdb_report> report_handle(out_report ? fabvdb::api::new_report_handle(std::move(report))
                                                            : nullptr);
    *out_mesh = fabvdb::api::new_mesh_handle(std::move(result.drilled), true);
    if (out_report) *out_report = report_handle.release();
    if (out_heatmap) *out_heatmap = heatmap_handle.release();
}

}  // namespace

extern "C" {

void fabvdb_drain_options_init(fabvdb_drain_options* options) {
    if (!options) return;
    *options = fabvdb_drain_options{};
    options->struct_size = sizeof(fabvdb_drain_options);
    options->wall = 3.0;
    options->voxel_size = 0.0;
    options->hole_count = 0;
    options->hole_diameter = 4.0;
    options->repose_degrees = 35.0;
    options->effort = 0.9;
    options->target_residual = 0.01;
    options->first_gravity[2] = -1.0;
    options->patch_count = 2000;
}

void fabvdb_powder_options_init(fabvdb_powder_options* options) {
    if (!options) return;
    *options = fabvdb_powder_options{};
    options->struct_size = sizeof(fabvdb_powder_options);
    options->repose_degrees = 35.0;
    options->first_gravity[2] = -1.0;
    options->turns = 10;
    options->seed = 1;
    options->slope_window = 4;
}

fabvdb_status fabvdb_mesh_drain(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, const fabvdb_drain_options* options,
                                fabvdb_mesh** out_mesh, fabvdb_report** out_report) {
    return fabvdb::api::guard(ctx, [&] { drain(ctx, mesh, options, out_mesh, out_report, nullptr); });
}

fabvdb_status fabvdb_mesh_drain_heatmap(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, const fabvdb_drain_options* options,
                                        fabvdb_mesh** out_mesh, fabvdb_report** out_report,
                                        fabvdb_heatmap** out_heatmap) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(out_heatmap, "out_heatmap");
        drain(ctx, mesh, options, out_mesh, out_report, out_heatmap);
    });
}

void fabvdb_heatmap_free(fabvdb_heatmap* heatmap) { delete heatmap; }

const fabvdb_mesh* fabvdb_heatmap_surface(const fabvdb_heatmap* heatmap) {
    return heatmap ? heatmap->surface.get() : nullptr;
}

const double* fabvdb_heatmap_values(const fabvdb_heatmap* heatmap, int kind) {
    if (!heatmap || (kind != FABVDB_HEATMAP_DRAINED && kind != FABVDB_HEATMAP_LEFT)) return nullptr;
    return heatmap->values[kind].data();
}

const uint8_t* fabvdb_heatmap_colours(const fabvdb_heatmap* heatmap, int kind) {
    if (!heatmap || (kind != FABVDB_HEATMAP_DRAINED && kind != FABVDB_HEATMAP_LEFT)) return nullptr;
    return heatmap->colours[kind].data();
}

fabvdb_status fabvdb_powder_simulate(fabvdb_ctx* ctx, const fabvdb_mesh* part, const char* holes_json_text,
                                     const fabvdb_powder_options* options, fabvdb_report** out) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(part, "part");
        fabvdb::api::require(holes_json_text, "holes_json");
        fabvdb::api::require(out, "out");
        const fabvdb_powder_options o =
            fabvdb::api::options_from(options, fabvdb_powder_options_init, "fabvdb_powder_options");
        require_range(o.repose_degrees > 0.0 && o.repose_degrees < 90.0, "repose_degrees must be in (0, 90)");
        require_range(o.turns >= 1, "turns must be >= 1");
        require_range(o.slope_window >= 1 && o.slope_window <= 16, "slope_window must be in [1, 16]");
        require_range(std::isfinite(o.voxel_size) && o.voxel_size >= 0.0, "voxel_size must be >= 0 mm (0: automatic)");
        const std::vector<fabvdb::powder::SandpileHole> holes = parse_holes(holes_json_text);
        fabvdb::validate_mesh(part->mesh, part->name);
        if (part->mesh.triangles.empty()) throw fabvdb::Error(FABVDB_ERR_BAD_INPUT, part->name + ": no triangles");
        std::map<std::string, double> timings;
        fabvdb::StageClock clock(timings);
        double voxel = o.voxel_size;
        if (voxel == 0.0) {
            voxel = fabvdb::bounding_box(part->mesh).diagonal() / 150.0;
            for (const auto& hole : holes) voxel = std::min(voxel, hole.diameter / 4.0);
        }
        fabvdb::Progress progress = ctx->make_progress();
        fabvdb::volume::SignedDistanceOptions distance;
        distance.voxel_size = voxel;
        distance.memory_budget_bytes = ctx->budget_bytes();
        distance.input_name = part->name;
        const openvdb::FloatGrid::Ptr solid = fabvdb::volume::signed_distance_from_mesh(part->mesh, distance, progress);
        clock.lap("signed distance");

        std::vector<fabvdb::Vec3> set = orientation_list(o.orientations, o.orientation_count);
        if (set.empty()) set = fabvdb::thesis_directions().directions;
        fabvdb::powder::SandpileOptions sandpile;
        sandpile.cell_size = voxel;
        sandpile.repose_radians = o.repose_degrees * kDegree;
        sandpile.slope_window = o.slope_window;
        sandpile.routine = o.routine_json ? parse_routine(o.routine_json)
                                          : fabvdb::powder::operator_routine(orientation_list(o.first_gravity, 1).front(),
                                                                             set, o.turns, o.seed);
        const fabvdb::powder::SandpileResult result =
            fabvdb::powder::simulate_sandpile(*solid, holes, sandpile, progress);
        clock.lap("simulation");

        nlohmann::json report;
        report["initial_volume"] = result.initial_volume;
        report["residual_volume"] = result.residual_volume;
        report["residual_fraction"] = result.residual_fraction();
        report["residual_volume_after_turn"] = result.residual_after_turn;
        nlohmann::json routine = nlohmann::json::array();
        for (const auto& g : sandpile.routine) routine.push_back(vec_json(g));
        report["routine"] = routine;
        report["turns"] = sandpile.routine.size();
        if (o.routine_json) report["seed"] = nullptr;
        else report["seed"] = o.seed;
        report["voxel_size"] = voxel;
        report["holes"] = holes.size();
        report["timings"] = timings;
        report["timings"]["total"] = clock.total();
        *out = fabvdb::api::new_report_handle(std::move(report));
    });
}

}  // extern "C"
