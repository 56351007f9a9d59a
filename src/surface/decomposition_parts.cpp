//! The parts of a decomposition document, validated against the input (see
//! decomposition_parts.h).
#include "surface/decomposition_parts.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/error.h"
#include "volume/surface_distance.h"
#include "core/vec3_ops.h"

namespace fabvdb::surface {

using volume::SurfaceDistance;

namespace {

[[noreturn]] void fail(const std::string& name, const std::string& defect) {
    throw Error(FABVDB_ERR_BAD_INPUT, name + ": " + defect);
}

std::vector<Vec3> points(const nlohmann::json& array, const std::string& name, const char* what) {
    if (!array.is_array()) fail(name, std::string(what) + " is missing or not an array");
    std::vector<Vec3> result;
    result.reserve(array.size());
    for (const auto& p : array) {
        const Vec3 v = p.get<Vec3>();
        if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
            fail(name, std::string(what) + " has a coordinate that is not finite");
        result.push_back(v);
    }
    return result;
}

//! Every directed edge used as often as its reverse: the surface bounds a
//! volume (a part touching itself along a prism edge has four triangles
//! there; the level sets made from it take that as it is).
bool closed(const Mesh& mesh) {
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (const Triangle& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
    for (const auto& [edge, count] : directed) {
        const auto reverse = directed.find({edge.second, edge.first});
        if (reverse == directed.end() || reverse->second != count) return false;
    }
    return !mesh.triangles.empty();
}

//! The low-resolution surface must lie on the input's surface: its vertices
//! within 1% of the diagonal on average, and its bounding box the input's
//! within 5% of the diagonal. No bound on the farthest vertex: an open scan
//! is decomposed closed, and the cap over its hole lies far from any input
//! triangle (falconstatue_boundary: 5.6 mm, 8% of the diagonal).
void require_fit(const std::vector<Vec3>& low_res, const Mesh& input, const std::string& name) {
    const BoundingBox box = bounding_box(input);
    const double diagonal = box.diagonal();
    Vec3 lo = low_res.front(), hi = low_res.front();
    for (const Vec3& p : low_res)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    double box_error = 0;
    for (int k = 0; k < 3; ++k)
        box_error = std::max({box_error, std::abs(lo[k] - box.min[k]), std::abs(hi[k] - box.max[k])});
    const SurfaceDistance surface(input);
    const size_t stride = std::max<size_t>(1, low_res.size() / 2000);
    double sum = 0, largest = 0;
    size_t count = 0;
    for (size_t v = 0; v < low_res.size(); v += stride, ++count) {
        const double d = surface.nearest(low_res[v]).distance;
        sum += d;
        largest = std::max(largest, d);
    }
    const double mean = sum / double(count);
    if (box_error > 0.05 * diagonal || mean > 0.01 * diagonal) {
        std::ostringstream message;
        message << "does not belong to this input (made for another model or another scale): its surface lies "
                << mean << " mm from the input on average, " << largest << " mm at most, its bounding box "
                << box_error << " mm off (input diagonal " << diagonal << " mm)";
        fail(name, message.str());
    }
}

}  // namespace

DecomposedModel decomposed_parts(const nlohmann::json& document, const std::string& name, const Mesh& input) {
    try {
        if (!document.is_object() || document.value("format", "") != "fabvdb decomposition")
            fail(name, "not a fabvdb decomposition document (no \"format\": \"fabvdb decomposition\")");
        if (document.value("version", 0) != 1) fail(name, "unsupported decomposition version (1 is supported)");
        DecomposedModel model;
        model.shell_thickness = document.at("shell_thickness").get<double>();
        if (!(model.shell_thickness > 0) || !std::isfinite(model.shell_thickness))
            fail(name, "shell_thickness must be a positive number");
        const nlohmann::json& surface = document.at("low_res_surface");
        const std::vector<Vec3> outer = points(surface.at("vertices"), name, "low_res_surface.vertices");
        const std::vector<Vec3> inner = points(surface.at("inner_vertices"), name, "low_res_surface.inner_vertices");
        const size_t triangle_count = surface.at("triangles").size();
        if (outer.empty() || inner.size() != outer.size() || triangle_count == 0)
            fail(name, "the low-resolution surface is empty or its inner vertices do not match its vertices");
        require_fit(outer, input, name);

        const auto part_of_triangle = document.at("part_of_triangle").get<std::vector<int>>();
        if (part_of_triangle.size() != triangle_count)
            fail(name, "part_of_triangle has " + std::to_string(part_of_triangle.size()) + " entries for " +
                           std::to_string(triangle_count) + " triangles");
        const nlohmann::json& parts = document.at("parts");
        if (!parts.is_array() || parts.empty()) fail(name, "has no parts");
        std::set<int> ids;
        const size_t corner_count = outer.size() + inner.size();
        for (const nlohmann::json& entry : parts) {
            DecomposedPart part;
            part.id = entry.at("id").get<int>();
            if (!ids.insert(part.id).second) fail(name, "part " + std::to_string(part.id) + " appears twice");
            const Vec3 d = entry.at("parting_direction").get<Vec3>();
            if (!(norm(d) > 0) || !std::isfinite(norm(d)))
                fail(name, "part " + std::to_string(part.id) + " has no valid parting direction");
            part.direction = normalized(d);
            std::map<uint32_t, uint32_t> local;
            for (const auto& corners : entry.at("surface").at("triangles")) {
                Triangle t;
                for (int k = 0; k < 3; ++k) {
                    const uint32_t id = corners.at(size_t(k)).get<uint32_t>();
                    if (id >= corner_count)
                        fail(name, "part " + std::to_string(part.id) + " has a corner id out of range");
                    const auto [it, fresh] = local.emplace(id, uint32_t(part.solid.vertices.size()));
                    if (fresh) part.solid.vertices.push_back(id < outer.size() ? outer[id] : inner[id - outer.size()]);
                    t[k] = it->second;
                }
                part.solid.triangles.push_back(t);
            }
            if (!closed(part.solid))
                fail(name, "the surface of part " + std::to_string(part.id) + " is not closed");
            if (!(signed_volume(part.solid) > 0))
                fail(name, "part " + std::to_string(part.id) + " encloses no volume");
            model.parts.push_back(std::move(part));
        }
        for (int owner : part_of_triangle)
            if (!ids.count(owner))
                fail(name, "part " + std::to_string(owner) + " is missing (part_of_triangle refers to it)");
        for (int id : ids)
            if (std::find(part_of_triangle.begin(), part_of_triangle.end(), id) == part_of_triangle.end())
                fail(name, "part " + std::to_string(id) + " owns no triangle of the low-resolution surface");
        return model;
    } catch (const nlohmann::json::exception& e) {
        fail(name, std::string("malformed decomposition: ") + e.what());
    }
}

DecomposedModel read_decomposed_parts(const std::string& path, const Mesh& input) {
    std::ifstream in(path);
    if (!in) throw Error(FABVDB_ERR_IO, path + ": cannot read");
    nlohmann::json document;
    try {
        in >> document;
    } catch (const nlohmann::json::exception& e) {
        fail(path, std::string("not valid JSON: ") + e.what());
    }
    return decomposed_parts(document, path, input);
}

}  // namespace fabvdb::surface
