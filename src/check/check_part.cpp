//! check_part: the signed distance, its surface, the two thickness walks and
//! each check's judgement against the profile (see check_part.h).
#include "check/check_part.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include <Eigen/Eigenvalues>

#include "check/build_fit.h"
#include "check/overhang_triangles.h"
#include "check/print_frame.h"
#include "check/resin_cups.h"
#include "check/thin_sheets.h"
#include "check/units_guess.h"
#include "core/colour_bar.h"
#include "core/error.h"
#include "core/stage_clock.h"
#include "powder/heatmap_ply.h"
#include "surface/inspect.h"
#include "surface/mesh_repair.h"
#include "surface/triangle_regions.h"
#include "volume/extract_mesh.h"
#include "volume/local_thickness.h"
#include "volume/mesh_shells.h"
#include "volume/signed_distance.h"
#include "volume/widen_band.h"

namespace fabvdb::check {

namespace {

enum Status { pass = 0, warn = 1, fail = 2 };
const char* const status_names[] = {"pass", "warn", "fail"};

//! Regions listed per check, the largest first; the rest are counted.
constexpr size_t kListedRegions = 20;

//! The automatic voxel, as a share of the minimum wall: never coarser than
//! half of it (a wall at the minimum spans two voxels, one at half of it
//! still holds a voxel centre, so it cannot vanish), never finer than a
//! quarter; between the two, the longest side / resolution (docs/check.md).
constexpr double kCoarsestVoxel = 0.5;
constexpr double kFinestVoxel = 0.25;

//! The cup search's grid holds at most this many cells (a byte each): about
//! 0.2 s of sampling on two cores, under the wall walk's time on the bench
//! models (docs/check.md, Speed).
constexpr uint64_t kMaxCupCells = uint64_t(1) << 23;
//! Cups under a cubic millimetre are not listed, as overhangs under a square
//! millimetre: a droplet's pocket, its seal on the film under 1 mm².
constexpr double kMinCupVolume = 1.0;

std::string mm(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g mm", value);
    return text;
}

nlohmann::json vec_json(const Vec3& v) { return nlohmann::json::array({v[0], v[1], v[2]}); }

nlohmann::json box_json(const BoundingBox& box) { return {{"min", vec_json(box.min)}, {"max", vec_json(box.max)}}; }

//! Status of a figure against a minimum: under it fails, under (1 + margin) × it warns.
Status against(double value, double minimum, double margin) {
    if (value < minimum) return fail;
    if (value < (1.0 + margin) * minimum) return warn;
    return pass;
}

nlohmann::json verdict(Status status, const std::string& message) {
    return {{"status", status_names[status]}, {"message", message}};
}

Status status_of(const nlohmann::json& check) {
    const std::string name = check["status"].get<std::string>();
    return name == "fail" ? fail : name == "warn" ? warn : pass;
}

//! The surface triangles whose corners' mean `value` is under `limit`.
std::vector<uint8_t> under(const Mesh& surface, const std::vector<double>& value, double limit) {
    std::vector<uint8_t> chosen(surface.triangles.size(), 0);
    for (size_t t = 0; t < surface.triangles.size(); ++t) {
        const Triangle& tri = surface.triangles[t];
        chosen[t] = (value[tri[0]] + value[tri[1]] + value[tri[2]]) / 3.0 < limit ? 1 : 0;
    }
    return chosen;
}

//! The vertex of `region` with the least `value`.
uint32_t least_vertex(const surface::TriangleRegion& region, const std::vector<double>& value) {
    uint32_t best = region.vertices.front();
    for (uint32_t v : region.vertices)
        if (value[v] < value[best]) best = v;
    return best;
}

//! A region as the report lists it: its area, its least value under `key`,
//! where that is, and its box.
nlohmann::json region_json(const Mesh& surface, const surface::TriangleRegion& region,
                           const std::vector<double>& value, const char* key) {
    const uint32_t v = least_vertex(region, value);
    return {{"area", region.area}, {key, value[v]}, {"center", vec_json(surface.vertices[v])},
            {"box", box_json(region.box)}};
}

//! The spread of a region's medial points along its two main directions
//! (standard deviations, largest first): a pin's lie along a line.
std::pair<double, double> medial_spread(const surface::TriangleRegion& region, const std::vector<Vec3>& centre) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (uint32_t v : region.vertices) mean += Eigen::Vector3d(centre[v][0], centre[v][1], centre[v][2]);
    mean /= double(region.vertices.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (uint32_t v : region.vertices) {
        const Eigen::Vector3d d = Eigen::Vector3d(centre[v][0], centre[v][1], centre[v][2]) - mean;
        covariance += d * d.transpose();
    }
    covariance /= double(region.vertices.size());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    const Eigen::Vector3d values = solver.eigenvalues();  // ascending
    return {std::sqrt(std::max(values[2], 0.0)), std::sqrt(std::max(values[1], 0.0))};
}

double median(std::vector<double> values) {
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

nlohmann::json mesh_check(const Mesh& mesh, Progress& progress) {
    nlohmann::json inspection = surface::inspect_mesh(mesh, progress);
    const auto count = [&](const char* key) { return inspection[key].get<uint64_t>(); };
    const bool manifold = count("non_manifold_edges") == 0 && count("non_manifold_vertices") == 0;
    const bool inside_out = inspection["volume"].is_number() && inspection["volume"].get<double>() < 0.0;
    const bool clean = inspection["closed"].get<bool>() && manifold && count("self_intersecting_pairs") == 0 &&
                       inspection["consistently_oriented"].get<bool>() && count("degenerate_triangles") == 0 &&
                       count("duplicate_triangles") == 0 && !inside_out;
    std::string path = "none";
    if (!clean) {
        const std::optional<surface::MeshRepair> repaired = surface::repair_at_mesh_level(mesh, progress);
        path = !repaired ? "volumetric" : repaired->rest.triangles.empty() ? "mesh" : "mixed";
    }
    std::vector<std::string> defects;
    if (!inspection["closed"].get<bool>())
        defects.push_back(std::to_string(count("boundary_loops")) + " holes");
    if (!manifold)
        defects.push_back(std::to_string(count("non_manifold_edges")) + " non-manifold edges, " +
                          std::to_string(count("non_manifold_vertices")) + " non-manifold vertices");
    if (count("self_intersecting_pairs") > 0)
        defects.push_back(std::to_string(count("self_intersecting_pairs")) + " crossing triangle pairs");
    if (!inspection["consistently_oriented"].get<bool>()) defects.push_back("inconsistent orientation");
    if (inside_out) defects.push_back("inside out");
    if (count("degenerate_triangles") + count("duplicate_triangles") > 0)
        defects.push_back(std::to_string(count("degenerate_triangles")) + " degenerate and " +
                          std::to_string(count("duplicate_triangles")) + " duplicate triangles");
    std::string message = "a clean closed solid: " + std::to_string(count("components")) + " shells";
    if (!clean) {
        message.clear();
        for (const std::string& d : defects) message += (message.empty() ? "" : "; ") + d;
        message += path == "volumetric" ? "; `fabvdb repair` would rebuild it through the level set"
                                        : path == "mixed" ? "; `fabvdb repair` would fix some shells exactly, the rest through the level set"
                                                          : "; `fabvdb repair` would fix it exactly, keeping its triangles";
    }
    nlohmann::json check = verdict(clean ? pass : warn, message);
    check["closed"] = inspection["closed"];
    check["manifold"] = manifold;
    check["consistently_oriented"] = inspection["consistently_oriented"];
    check["inside_out"] = inside_out;
    check["shells"] = inspection["components"];
    check["boundary_loops"] = inspection["boundary_loops"];
    check["non_manifold_edges"] = inspection["non_manifold_edges"];
    check["non_manifold_vertices"] = inspection["non_manifold_vertices"];
    check["self_intersecting_pairs"] = inspection["self_intersecting_pairs"];
    check["degenerate_triangles"] = inspection["degenerate_triangles"];
    check["duplicate_triangles"] = inspection["duplicate_triangles"];
    check["volume"] = inspection["volume"];
    check["repair_path"] = path;
    return check;
}

nlohmann::json units_check(const BoundingBox& box, double volume) {
    const UnitsGuess guess = guess_units(box);
    const Vec3 size{box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]};
    std::string message = "the size suits millimetres (longest side " + mm(guess.longest) + ")";
    if (guess.suspicious) {
        message = "longest side " + mm(guess.longest) + (guess.longest < 10.0 ? ": small" : ": large") + " for mm";
        for (size_t i = 0; i < guess.readings.size(); ++i) {
            char text[96];
            std::snprintf(text, sizeof text, "%s%s, scale by %g (--scale) to %.4g mm", i == 0 ? "; if it is in " : ", or in ",
                          guess.readings[i].unit.c_str(), guess.readings[i].scale, guess.readings[i].longest);
            message += text;
        }
    }
    nlohmann::json check = verdict(guess.suspicious ? warn : pass, message);
    check["size"] = vec_json(size);
    check["volume"] = volume;
    check["readings"] = nlohmann::json::array();
    for (const UnitsReading& r : guess.readings)
        check["readings"].push_back({{"unit", r.unit}, {"scale", r.scale}, {"size", r.longest}});
    check["suggested_scale"] = guess.readings.empty() ? nlohmann::json(nullptr) : nlohmann::json(guess.readings[0].scale);
    return check;
}

nlohmann::json wall_check(const Mesh& surface, const volume::LocalThickness& walls, const ProcessProfile& p) {
    const double limit = (1.0 + p.margin_fraction) * p.min_wall;
    const auto regions = surface::triangle_regions(surface, under(surface, walls.thickness, limit));
    Status status = pass;
    double thinnest = std::numeric_limits<double>::infinity(), thin_area = 0.0;
    nlohmann::json list = nlohmann::json::array();
    for (const auto& region : regions) {
        const double least = walls.thickness[least_vertex(region, walls.thickness)];
        thinnest = std::min(thinnest, least);
        if (least < p.min_wall) thin_area += region.area;
        status = std::max(status, against(least, p.min_wall, p.margin_fraction));
        if (list.size() < kListedRegions) list.push_back(region_json(surface, region, walls.thickness, "min_thickness"));
    }
    for (double t : walls.thickness) thinnest = std::min(thinnest, t);
    std::string message = status == pass ? "no wall under " + mm(limit)
                                         : std::to_string(regions.size()) + " regions under " + mm(limit) +
                                               ", thinnest " + mm(thinnest) + " (minimum " + mm(p.min_wall) + ")";
    nlohmann::json check = verdict(status, message);
    check["min_wall"] = p.min_wall;
    check["min_thickness"] = std::isfinite(thinnest) ? nlohmann::json(thinnest) : nlohmann::json(nullptr);
    check["thin_area"] = thin_area;
    check["region_count"] = regions.size();
    check["regions"] = list;
    return check;
}

//! A thin region's medial points lie along a line (a pin, a post): their
//! spread across it is a small part of its diameter, along it at least its
//! diameter. Returns the median thickness as the diameter and the length,
//! or nothing for a region of a few voxels (the wall check has it) or a sheet.
std::optional<std::pair<double, double>> pin_reading(const surface::TriangleRegion& region,
                                                     const volume::LocalThickness& walls) {
    if (region.vertices.size() < 8) return std::nullopt;
    std::vector<double> values;
    for (uint32_t v : region.vertices) values.push_back(walls.thickness[v]);
    const double diameter = median(values);
    const auto [along, across] = medial_spread(region, walls.centre);
    if (!(across < 0.25 * diameter && along * std::sqrt(12.0) >= diameter)) return std::nullopt;
    return std::make_pair(diameter, along * std::sqrt(12.0));
}

nlohmann::json feature_check(const Mesh& surface, const volume::LocalThickness& walls,
                             const std::vector<volume::MeshShell>& shells, double voxel, const ProcessProfile& p) {
    const double limit = (1.0 + p.margin_fraction) * p.min_pin;
    Status status = pass;
    nlohmann::json pins = nlohmann::json::array();
    for (const auto& region : surface::triangle_regions(surface, under(surface, walls.thickness, limit))) {
        const auto pin = pin_reading(region, walls);
        if (!pin) continue;
        status = std::max(status, against(pin->first, p.min_pin, p.margin_fraction));
        if (pins.size() < kListedRegions) {
            nlohmann::json item = region_json(surface, region, walls.thickness, "min_thickness");
            item["diameter"] = pin->first;
            item["length"] = pin->second;
            pins.push_back(item);
        }
    }
    // Fins: thin walls (under the wall's warning limit, not pins) held along
    // one edge only; a loop shorter than the circle of that limit is a ragged
    // island of the threshold, not where the wall is held (thin_sheets.h).
    const double wall_limit = (1.0 + p.margin_fraction) * p.min_wall;
    const auto thin = surface::triangle_regions(surface, under(surface, walls.thickness, wall_limit));
    const std::vector<SheetReading> sheets = thin_sheets(surface, thin, walls.centre, voxel, M_PI * wall_limit);
    nlohmann::json fins = nlohmann::json::array();
    size_t fin_count = 0;
    for (size_t r = 0; r < thin.size(); ++r) {
        if (!sheets[r].fin || pin_reading(thin[r], walls)) continue;
        const double least = walls.thickness[least_vertex(thin[r], walls.thickness)];
        status = std::max(status, against(least, p.min_wall, p.margin_fraction));
        ++fin_count;
        if (fins.size() < kListedRegions) fins.push_back(region_json(surface, thin[r], walls.thickness, "min_thickness"));
    }
    nlohmann::json pieces = nlohmann::json::array();
    for (const auto& shell : shells) {
        if (shell.volume <= 0.0) continue;
        BoundingBox box;
        box.min = box.max = surface.vertices[surface.triangles[shell.triangles.front()][0]];
        for (uint32_t t : shell.triangles)
            for (uint32_t v : surface.triangles[t]) box.add(surface.vertices[v]);
        double longest = 0.0;
        for (int k = 0; k < 3; ++k) longest = std::max(longest, box.max[k] - box.min[k]);
        if (longest >= p.min_feature) continue;
        status = fail;
        pieces.push_back({{"size", longest}, {"volume", shell.volume}, {"box", box_json(box)},
                          {"center", vec_json({0.5 * (box.min[0] + box.max[0]), 0.5 * (box.min[1] + box.max[1]),
                                               0.5 * (box.min[2] + box.max[2])})}});
    }
    std::string message = "no pin under " + mm(limit) + ", no fin under " + mm(wall_limit) + ", no piece under " +
                          mm(p.min_feature);
    if (status != pass)
        message = std::to_string(pins.size()) + " pins under " + mm(limit) + " (minimum " + mm(p.min_pin) + "), " +
                  std::to_string(fin_count) + " fins (thin walls held along one edge) under " + mm(wall_limit) +
                  " (minimum wall " + mm(p.min_wall) + "), " + std::to_string(pieces.size()) + " pieces under " +
                  mm(p.min_feature);
    nlohmann::json check = verdict(status, message);
    check["min_pin"] = p.min_pin;
    check["min_feature"] = p.min_feature;
    check["pins"] = pins;
    check["fins"] = fins;
    check["small_pieces"] = pieces;
    return check;
}

nlohmann::json hole_check(const Mesh& surface, const volume::LocalThickness& gaps, const ProcessProfile& p) {
    const double limit = (1.0 + p.margin_fraction) * p.min_hole;
    const auto regions = surface::triangle_regions(surface, under(surface, gaps.thickness, limit));
    Status status = pass;
    double narrowest = std::numeric_limits<double>::infinity();
    nlohmann::json list = nlohmann::json::array();
    for (const auto& region : regions) {
        const double least = gaps.thickness[least_vertex(region, gaps.thickness)];
        narrowest = std::min(narrowest, least);
        status = std::max(status, against(least, p.min_hole, p.margin_fraction));
        if (list.size() < kListedRegions) list.push_back(region_json(surface, region, gaps.thickness, "min_diameter"));
    }
    std::string message = status == pass ? "no hole, channel or gap under " + mm(limit)
                                         : std::to_string(regions.size()) + " holes, channels or gaps under " +
                                               mm(limit) + ", narrowest " + mm(narrowest) + " (minimum " +
                                               mm(p.min_hole) + ")";
    nlohmann::json check = verdict(status, message);
    check["min_hole"] = p.min_hole;
    check["min_diameter"] = std::isfinite(narrowest) ? nlohmann::json(narrowest) : nlohmann::json(nullptr);
    check["region_count"] = regions.size();
    check["regions"] = list;
    return check;
}

nlohmann::json cavity_check(const Mesh& surface, const std::vector<volume::MeshShell>& shells,
                            const ProcessProfile& p) {
    nlohmann::json cavities = nlohmann::json::array();
    double total = 0.0;
    for (const auto& shell : shells) {
        if (shell.volume >= 0.0) continue;
        BoundingBox box;
        box.min = box.max = surface.vertices[surface.triangles[shell.triangles.front()][0]];
        for (uint32_t t : shell.triangles)
            for (uint32_t v : surface.triangles[t]) box.add(surface.vertices[v]);
        total += -shell.volume;
        cavities.push_back({{"volume", -shell.volume}, {"box", box_json(box)},
                            {"center", vec_json({0.5 * (box.min[0] + box.max[0]), 0.5 * (box.min[1] + box.max[1]),
                                                 0.5 * (box.min[2] + box.max[2])})}});
    }
    Status status = pass;
    std::string message = "no sealed cavity";
    if (!cavities.empty()) {
        char text[160];
        std::snprintf(text, sizeof text, "%zu sealed cavities holding %.4g mm^3", cavities.size(), total);
        message = text;
        if (p.escape_hole > 0.0) {
            status = fail;
            message += " of trapped material: give each escape holes of at least " + mm(p.escape_hole) +
                       " (`fabvdb drain`)";
        } else {
            message += ": the process prints them sealed";
        }
    }
    nlohmann::json check = verdict(status, message);
    check["escape_hole"] = p.escape_hole;
    check["cavity_volume"] = total;
    check["cavities"] = cavities;
    return check;
}

nlohmann::json cup_check(const openvdb::FloatGrid& grid, const Mesh& surface, const Vec3& up,
                         const ProcessProfile& p, Progress& progress) {
    nlohmann::json check;
    if (!p.cups) {
        check = verdict(pass, "the process cures no layer against a vat film");
        check["cell"] = nullptr;
        check["cup_volume"] = 0.0;
        check["cups"] = nlohmann::json::array();
        return check;
    }
    const CupSearch found = find_cups(grid, surface.vertices, up, kMaxCupCells, kMinCupVolume, progress);
    double total = 0.0;
    nlohmann::json cups = nlohmann::json::array();
    for (const Cup& cup : found.cups) {
        total += cup.volume;
        if (cups.size() < kListedRegions)
            cups.push_back({{"volume", cup.volume}, {"center", vec_json(cup.center)}, {"box", box_json(cup.box)},
                            {"opening_area", cup.opening_area}, {"opening_center", vec_json(cup.opening_center)}});
    }
    std::string message = "no pocket sealed against the vat film as layers are added";
    if (!found.cups.empty()) {
        char text[320];
        const Vec3& at = found.cups.front().center;
        std::snprintf(text, sizeof text,
                      "%zu cups hold %.4g mm^3 of resin sealed against the vat film (suction at each peel), the largest "
                      "%.4g mm^3 at (%.1f, %.1f, %.1f): vent each through its floor (toward the plate) or turn the "
                      "part so it opens toward the plate",
                      found.cups.size(), total, found.cups.front().volume, at[0], at[1], at[2]);
        message = text;
    }
    check = verdict(found.cups.empty() ? pass : warn, message);
    check["cell"] = found.cell;
    check["cup_volume"] = total;
    check["cups"] = cups;
    return check;
}

nlohmann::json overhang_check(const Mesh& surface, const Vec3& up, double voxel, const ProcessProfile& p) {
    const auto regions = surface::triangle_regions(surface, overhang_triangles(surface, up, p.overhang_degrees, voxel));
    double area = 0.0;
    nlohmann::json list = nlohmann::json::array();
    for (const auto& region : regions) {
        area += region.area;
        if (list.size() < kListedRegions)
            list.push_back({{"area", region.area}, {"center", vec_json(region.centroid)}, {"box", box_json(region.box)}});
    }
    // Under a square millimetre is the facets of a rounded bottom, not a surface to support.
    const Status status = area > 1.0 ? warn : pass;
    char text[200];
    if (p.overhang_degrees >= 90.0)
        std::snprintf(text, sizeof text, "the process needs no support");
    else if (status == warn)
        std::snprintf(text, sizeof text, "%.4g mm^2 in %zu regions tilted more than %.0f degrees from vertical need support",
                      area, regions.size(), p.overhang_degrees);
    else
        std::snprintf(text, sizeof text, "nothing tilted more than %.0f degrees from vertical", p.overhang_degrees);
    nlohmann::json check = verdict(status, text);
    check["up"] = vec_json(up);
    check["overhang_degrees"] = p.overhang_degrees;
    check["area"] = area;
    check["region_count"] = regions.size();
    check["regions"] = list;
    return check;
}

//! The bounding-box sides of the mesh in the print frame: z along `up`, x and
//! y completing it (the shortest turn taking `up` to +z).
Vec3 print_frame_size(const Mesh& mesh, const Vec3& up) {
    const Eigen::Matrix3d turn = print_frame_turn(up);
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const Triangle& t : mesh.triangles)
        for (uint32_t v : t) {
            const Eigen::Vector3d p = turn * Eigen::Vector3d(mesh.vertices[v][0], mesh.vertices[v][1], mesh.vertices[v][2]);
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
    return {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
}

nlohmann::json build_check(const Mesh& mesh, const Vec3& up, const Vec3& volume) {
    const Vec3 size = print_frame_size(mesh, up);
    const BuildFit fit = fit_build_volume(size, volume);
    const char* axis = "xyz";
    std::string message = "fits as placed";
    if (!fit.as_placed && fit.turned)
        message = std::string("fits turned: its ") + axis[fit.axes[0]] + ", " + axis[fit.axes[1]] + ", " +
                  axis[fit.axes[2]] + " sides along the printer's x, y, z";
    if (!fit.turned) message = "does not fit in any quarter turn";
    nlohmann::json check = verdict(fit.as_placed ? pass : fit.turned ? warn : fail, message);
    check["size"] = vec_json(size);
    check["build_volume"] = vec_json(volume);
    check["fits_as_placed"] = fit.as_placed;
    check["fits_turned"] = fit.turned;
    return check;
}

// The report around the checks: the verdict is the worst check's status.
nlohmann::json assemble_report(nlohmann::json checks, const ProcessProfile& p, double voxel, size_t surface_vertices,
                               const StageClock& clock, const std::map<std::string, double>& stages) {
    Status worst = pass;
    for (const auto& item : checks.items()) worst = std::max(worst, status_of(item.value()));
    nlohmann::json report;
    report["verdict"] = status_names[worst];
    report["process"] = profile_json(p);
    report["voxel_size"] = voxel;
    report["surface_vertices"] = surface_vertices;
    report["checks"] = std::move(checks);
    report["warnings"] = nlohmann::json::array();
    for (const auto& item : stages) report["timings"][item.first] = item.second;
    report["timings"]["total"] = clock.total();
    return report;
}

// The report of an input that encloses no volume (an open sheet, a soup of
// loose triangles): it fails, the mesh check saying why, and every check
// measured on the solid fails with it, since there is nothing to print.
nlohmann::json no_solid_report(nlohmann::json checks, const BoundingBox& box, double voxel, const std::string& why,
                               const ProcessProfile& p, const StageClock& clock,
                               const std::map<std::string, double>& stages) {
    nlohmann::json& mesh = checks["mesh"];
    std::string defects = mesh["message"].get<std::string>();
    defects = defects.substr(0, defects.find("; `fabvdb repair`"));  // it would refuse this input too
    if (mesh["status"] == status_names[pass]) defects = "closed and manifold, but flat";
    mesh["message"] = defects + "; encloses no volume (an open sheet, loose triangles or pieces wound every which "
                                "way), so there is no solid to print; `fabvdb repair --thicken LEN` makes a sheet a solid";
    mesh["status"] = status_names[fail];
    mesh["no_solid"] = why;
    checks["units"] = units_check(box, 0.0);
    for (const char* name : {"wall_thickness", "small_features", "holes", "trapped_volumes", "overhangs", "cups"})
        checks[name] = verdict(fail, "not measured: the mesh encloses no volume");
    return assemble_report(std::move(checks), p, voxel, 0, clock, stages);
}

}  // namespace

nlohmann::json check_part(const Mesh& mesh, const CheckOptions& options, Progress& progress) {
    const ProcessProfile& p = options.profile;
    const double up_length = std::sqrt(options.up[0] * options.up[0] + options.up[1] * options.up[1] +
                                       options.up[2] * options.up[2]);
    if (!(up_length > 0.0) || !std::isfinite(up_length))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the build direction (up) must be a non-zero vector");
    std::map<std::string, double> stages;
    StageClock clock(stages);
    nlohmann::json checks;
    progress.stage("inspect");
    checks["mesh"] = mesh_check(mesh, progress);
    if (options.build_volume[0] > 0.0 && options.build_volume[1] > 0.0 && options.build_volume[2] > 0.0)
        checks["build_volume"] = build_check(mesh, options.up, options.build_volume);
    clock.lap("inspect");

    const BoundingBox box = bounding_box(mesh);
    double longest = 0.0;
    for (int k = 0; k < 3; ++k) longest = std::max(longest, box.max[k] - box.min[k]);
    double voxel = options.voxel_size;
    if (!(voxel > 0.0))
        voxel = std::clamp(longest / std::max(options.resolution, 1), kFinestVoxel * p.min_wall,
                           kCoarsestVoxel * p.min_wall);
    // The thickest reading a check needs is its warning limit: the walks
    // climb to half that (a radius), to the whole for a heat map, whose
    // colours run to twice the limit.
    const double wall_limit = std::max(p.min_wall, p.min_pin) * (1.0 + p.margin_fraction);
    const double gap_limit = p.min_hole * (1.0 + p.margin_fraction);
    const double wall_radius = options.thickness_map.empty() ? 0.5 * wall_limit : wall_limit;
    const double gap_radius = 0.5 * gap_limit;
    volume::SignedDistanceOptions sdf;
    sdf.voxel_size = voxel;
    sdf.memory_budget_bytes = options.memory_budget_bytes;
    sdf.input_name = options.input_name;
    volume::SignedDistanceStats stats;
    openvdb::FloatGrid::Ptr grid;
    try {
        grid = volume::signed_distance_from_mesh(mesh, sdf, progress, &stats);
    } catch (const Error& e) {
        if (e.status() != FABVDB_ERR_BAD_INPUT) throw;
        return no_solid_report(std::move(checks), box, voxel, e.what(), p, clock, stages);
    }
    clock.add_laps(stats.timings);
    // Each walk's side of the band reaches its radius and the ridge fit's
    // samples beyond it (local_thickness.h), the other side those samples.
    const int interior = int(std::ceil(wall_radius / voxel)) + 5, exterior = int(std::ceil(gap_radius / voxel)) + 5;
    if (std::max(interior, exterior) > sdf.half_band_voxels) {
        grid = volume::widen_band(*grid, interior, exterior, progress);
        clock.lap("widen band");
    }

    progress.stage("extract");
    const Mesh surface = volume::extract_mesh(*grid, 0.0, progress);
    const std::vector<volume::MeshShell> shells = volume::split_shells(surface);
    double solid_volume = 0.0;
    for (const auto& shell : shells) solid_volume += shell.volume;
    clock.lap("extract");
    checks["units"] = units_check(box, solid_volume);

    const volume::LocalThickness walls =
        volume::local_thickness(*grid, surface.vertices, volume::ThicknessSide::solid, wall_radius, progress);
    clock.lap("wall thickness");
    const volume::LocalThickness gaps =
        volume::local_thickness(*grid, surface.vertices, volume::ThicknessSide::gap, gap_radius, progress);
    clock.lap("gap width");

    checks["wall_thickness"] = wall_check(surface, walls, p);
    checks["small_features"] = feature_check(surface, walls, shells, voxel, p);
    checks["holes"] = hole_check(surface, gaps, p);
    checks["trapped_volumes"] = cavity_check(surface, shells, p);
    checks["overhangs"] = overhang_check(surface, options.up, voxel, p);
    clock.lap("judge");
    checks["cups"] = cup_check(*grid, surface, options.up, p, progress);
    clock.lap("cups");

    if (!options.thickness_map.empty()) {
        progress.stage("thickness map");
        const std::string& path = options.thickness_map;
        const std::string stem =
            path.size() > 4 && path.compare(path.size() - 4, 4, ".ply") == 0 ? path.substr(0, path.size() - 4) : path;
        const double top = 2.0 * wall_limit;
        powder::write_heatmap_ply(surface, walls.thickness, 0.0, top, "local wall thickness, mm", path, false);
        write_colour_bar_png(stem + ".png", "wall thickness", 0.0, top, "mm");
        checks["wall_thickness"]["map"] = {{"path", path}, {"legend", stem + ".png"}, {"min", 0.0}, {"max", top}};
        clock.lap("thickness map");
    }

    return assemble_report(std::move(checks), p, voxel, surface.vertices.size(), clock, stages);
}

}  // namespace fabvdb::check
