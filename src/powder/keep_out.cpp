//! Keep-out regions for drain holes (see keep_out.h).
#include "powder/keep_out.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>
#include <openvdb/tools/Interpolation.h>

#include "core/error.h"
#include "io/mesh_io.h"
#include "volume/signed_distance.h"

namespace fabvdb::powder {

namespace {

bool has_json_extension(const std::string& path) {
    const size_t dot = path.find_last_of('.');
    if (dot == std::string::npos) return false;
    std::string extension = path.substr(dot + 1);
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension == "json";
}

KeepOutSphere parse_sphere(const nlohmann::json& item, const std::string& path) {
    if (!item.is_object() || !item.contains("center") || !item.contains("radius") || !item["center"].is_array() ||
        item["center"].size() != 3 || !item["radius"].is_number())
        throw Error(FABVDB_ERR_BAD_INPUT, path + ": each keep-out sphere needs \"center\": [x, y, z] and \"radius\"");
    KeepOutSphere sphere;
    for (int k = 0; k < 3; ++k) {
        if (!item["center"][k].is_number())
            throw Error(FABVDB_ERR_BAD_INPUT, path + ": a keep-out sphere's center is not three numbers");
        sphere.center[k] = item["center"][k].get<double>();
    }
    sphere.radius = item["radius"].get<double>();
    if (!(sphere.radius > 0.0) || !std::isfinite(sphere.radius))
        throw Error(FABVDB_ERR_BAD_INPUT, path + ": a keep-out sphere's radius must be positive");
    return sphere;
}

}  // namespace

bool KeepOut::touches(const Vec3& point, double margin) const {
    for (const KeepOutSphere& sphere : spheres) {
        const double dx = point[0] - sphere.center[0], dy = point[1] - sphere.center[1],
                     dz = point[2] - sphere.center[2];
        if (std::sqrt(dx * dx + dy * dy + dz * dz) < sphere.radius + margin) return true;
    }
    if (region) {
        const openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> sampler(*region);
        const double distance = sampler.wsSample(openvdb::Vec3d(point[0], point[1], point[2]));
        if (distance < margin && distance < double(region->background())) return true;
    }
    return false;
}

KeepOut read_keep_out(const std::string& path, double voxel_size, double reach, Progress& progress) {
    KeepOut keep_out;
    if (has_json_extension(path)) {
        std::ifstream file(path);
        if (!file) throw Error(FABVDB_ERR_IO, path + ": cannot open the keep-out file");
        nlohmann::json document;
        try {
            file >> document;
        } catch (const nlohmann::json::exception& e) {
            throw Error(FABVDB_ERR_BAD_INPUT, path + ": not valid JSON (" + e.what() + ")");
        }
        const nlohmann::json* list = &document;
        if (document.is_object()) {
            if (!document.contains("spheres"))
                throw Error(FABVDB_ERR_BAD_INPUT, path + ": a keep-out JSON object needs a \"spheres\" array");
            list = &document["spheres"];
        }
        if (!list->is_array()) throw Error(FABVDB_ERR_BAD_INPUT, path + ": the keep-out spheres are not an array");
        for (const nlohmann::json& item : *list) keep_out.spheres.push_back(parse_sphere(item, path));
        return keep_out;
    }
    const Mesh mesh = io::read_mesh(path, progress);
    volume::SignedDistanceOptions options;
    options.voxel_size = voxel_size;
    options.half_band_voxels = std::max(3, int(std::ceil(reach / voxel_size)) + 2);
    options.input_name = path;
    keep_out.region = volume::signed_distance_from_mesh(mesh, options, progress);
    return keep_out;
}

}  // namespace fabvdb::powder
