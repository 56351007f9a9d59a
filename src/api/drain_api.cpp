//! C API: drainability — drain-hole planning and drilling (`fabvdb drain`)
//! and the reference powder simulation (`fabvdb powder-sim`).
#include <chrono>
#include <cmath>

#include "api/guard.h"
#include "core/mesh.h"
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

void check_struct_size(size_t given, size_t needed, const char* name) {
    if (given < needed)
        throw fabvdb::Error(FABVDB_ERR_INVALID_ARGUMENT, std::string(name) + ".struct_size is too small (call its _init())");
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
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(mesh, "mesh");
        fabvdb::api::require(out_mesh, "out_mesh");
        fabvdb_drain_options o;
        fabvdb_drain_options_init(&o);
        if (options) {
            check_struct_size(options->struct_size, sizeof(fabvdb_drain_options), "fabvdb_drain_options");
            o = *options;
        }
        if (!(o.hole_diameter > 0.0) || !(o.repose_degrees > 0.0 && o.repose_degrees < 90.0) ||
            !(o.effort >= 0.0 && o.effort < 1.0) || o.hole_count < 0 || o.patch_count < 1 ||
            !(o.target_residual >= 0.0) || !(o.voxel_size >= 0.0))
            throw fabvdb::Error(FABVDB_ERR_INVALID_ARGUMENT,
                                "drain options out of range (hole diameter > 0, 0 < repose < 90, 0 <= effort < 1, "
                                "hole count >= 0, patch count >= 1, target >= 0, voxel size >= 0)");
        fabvdb::Progress progress = ctx->make_progress();
        fabvdb::powder::DrainPartOptions part_options;
        part_options.wall = o.wall;
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
                o.keep_out_path, o.voxel_size > 0 ? o.voxel_size : o.wall / 4.0, progress);
        fabvdb::powder::DrainPartResult result = fabvdb::powder::drain_part(mesh->mesh, part_options, progress);
        const auto& plan = result.plan;
        if (o.heatmap_path) {
            const auto start = std::chrono::steady_clock::now();
            fabvdb::powder::write_heatmap_ply(plan.cavity_surface, plan.patches, plan.evaluation.drainability,
                                              o.heatmap_path);
            result.timings["heat map"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        }
        nlohmann::json report;
        report["holes"] = holes_json(plan.holes);
        report["predicted_residual_fraction"] = plan.evaluation.residual_fraction();
        report["predicted_residual_mm3"] = plan.evaluation.residual_volume;
        report["baseline_holes"] = holes_json(plan.baseline);
        report["baseline_residual_fraction"] = plan.baseline_evaluation.residual_fraction();
        report["baseline_residual_mm3"] = plan.baseline_evaluation.residual_volume;
        report["cavity_volume_mm3"] = plan.evaluation.total_volume;
        report["cavities"] = plan.patches.cavity_count;
        report["residual_per_cavity_mm3"] = plan.evaluation.residual_per_cavity;
        report["patches"] = plan.patches.size();
        report["candidates"] = plan.candidate_count;
        report["input_was_hollow"] = result.input_was_hollow;
        report["voxel_size"] = result.voxel_size;
        report["repose_degrees"] = o.repose_degrees;
        report["effort"] = o.effort;
        report["orientations"] = o.orientations ? o.orientation_count : size_t(162);
        report["timings"] = result.timings;
        double total = 0.0;
        for (const auto& [name, seconds] : result.timings) total += seconds;
        report["timings"]["total"] = total;
        fabvdb_report* report_handle = out_report ? fabvdb::api::new_report_handle(std::move(report)) : nullptr;
        *out_mesh = fabvdb::api::new_mesh_handle(std::move(result.drilled));
        if (out_report) *out_report = report_handle;
    });
}

fabvdb_status fabvdb_powder_simulate(fabvdb_ctx* ctx, const fabvdb_mesh* part, const char* holes_json_text,
                                     const fabvdb_powder_options* options, fabvdb_report** out) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(part, "part");
        fabvdb::api::require(holes_json_text, "holes_json");
        fabvdb::api::require(out, "out");
        fabvdb_powder_options o;
        fabvdb_powder_options_init(&o);
        if (options) {
            check_struct_size(options->struct_size, sizeof(fabvdb_powder_options), "fabvdb_powder_options");
            o = *options;
        }
        if (!(o.repose_degrees > 0.0 && o.repose_degrees < 90.0) || o.turns < 1 || o.slope_window < 1 ||
            o.slope_window > 16 ||
            !(o.voxel_size >= 0.0))
            throw fabvdb::Error(FABVDB_ERR_INVALID_ARGUMENT,
                                "powder options out of range (0 < repose < 90, turns >= 1, 1 <= slope window <= 16, "
                                "voxel size >= 0)");
        const std::vector<fabvdb::powder::SandpileHole> holes = parse_holes(holes_json_text);
        fabvdb::validate_mesh(part->mesh, "part");
        if (part->mesh.triangles.empty()) throw fabvdb::Error(FABVDB_ERR_BAD_INPUT, "part: no triangles");
        const auto start = std::chrono::steady_clock::now();
        double voxel = o.voxel_size;
        if (voxel == 0.0) {
            voxel = fabvdb::bounding_box(part->mesh).diagonal() / 150.0;
            for (const auto& hole : holes) voxel = std::min(voxel, hole.diameter / 4.0);
        }
        fabvdb::Progress progress = ctx->make_progress();
        fabvdb::volume::SignedDistanceOptions distance;
        distance.voxel_size = voxel;
        distance.memory_budget_bytes = ctx->budget_bytes();
        distance.input_name = "part";
        const openvdb::FloatGrid::Ptr solid = fabvdb::volume::signed_distance_from_mesh(part->mesh, distance, progress);
        const double distance_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

        std::vector<fabvdb::Vec3> set = orientation_list(o.orientations, o.orientation_count);
        if (set.empty()) set = fabvdb::thesis_directions().directions;
        fabvdb::powder::SandpileOptions sandpile;
        sandpile.cell_size = voxel;
        sandpile.repose_radians = o.repose_degrees * kDegree;
        sandpile.slope_window = o.slope_window;
        sandpile.routine = fabvdb::powder::operator_routine(orientation_list(o.first_gravity, 1).front(), set,
                                                            o.turns, o.seed);
        const fabvdb::powder::SandpileResult result =
            fabvdb::powder::simulate_sandpile(*solid, holes, sandpile, progress);
        const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

        nlohmann::json report;
        report["initial_mm3"] = result.initial_volume;
        report["residual_mm3"] = result.residual_volume;
        report["residual_fraction"] = result.residual_fraction();
        report["residual_after_turn_mm3"] = result.residual_after_turn;
        nlohmann::json routine = nlohmann::json::array();
        for (const auto& g : sandpile.routine) routine.push_back(vec_json(g));
        report["routine"] = routine;
        report["turns"] = o.turns;
        report["seed"] = o.seed;
        report["voxel_size"] = voxel;
        report["holes"] = holes.size();
        report["timings"] = {{"signed distance", distance_seconds}, {"simulation", total - distance_seconds},
                             {"total", total}};
        *out = fabvdb::api::new_report_handle(std::move(report));
    });
}

}  // extern "C"
