//! Writing a mesh only when it is a clean solid as written (see write_solid_mesh.h).
#include "surface/write_solid_mesh.h"

#include <optional>

#include "core/error.h"
#include "core/float_coordinates.h"
#include "surface/float_rounding.h"
#include "surface/inspect.h"
#include "surface/weld_vertices.h"
#include "volume/clean_solid.h"

namespace fabvdb::surface {

namespace {

bool stores_floats(io::MeshFormat format) {
    return format == io::MeshFormat::stl || format == io::MeshFormat::threemf;
}

void add_count(std::string& text, uint64_t count, const char* what) {
    if (count == 0) return;
    if (!text.empty()) text += ", ";
    text += std::to_string(count) + " " + what;
}

}  // namespace

Mesh mesh_as_written(const Mesh& mesh, io::MeshFormat format) {
    if (!stores_floats(format)) return mesh;
    Mesh written = mesh;
    for (Vec3& p : written.vertices) p = nearest_float(p);
    if (format == io::MeshFormat::stl) written = weld_coincident_vertices(written);
    return written;
}

std::string solid_defects(const Mesh& mesh, Progress& progress) {
    if (mesh.triangles.empty()) return "no triangles";
    if (volume::check_solid(mesh, progress).clean) return {};
    const nlohmann::json found = inspect_mesh(mesh, progress);
    std::string text;
    add_count(text, found["boundary_edges"].get<uint64_t>(), "boundary edges");
    add_count(text, found["non_manifold_edges"].get<uint64_t>(), "non-manifold edges");
    add_count(text, found["non_manifold_vertices"].get<uint64_t>(), "non-manifold vertices");
    add_count(text, found["inconsistent_edges"].get<uint64_t>(), "inconsistently oriented edges");
    add_count(text, found["degenerate_triangles"].get<uint64_t>(), "degenerate triangles");
    add_count(text, found["duplicate_triangles"].get<uint64_t>(), "duplicate triangles");
    add_count(text, found["self_intersecting_pairs"].get<uint64_t>(), "self-intersecting triangle pairs");
    if (text.empty()) text = "its shells do not bound a volume (inward, nested inconsistently, or flat)";
    return text;
}

void write_solid_mesh(const Mesh& mesh, const std::string& path, Progress& progress, fabvdb_status status) {
    const io::MeshFormat format = io::format_from_path(path);
    std::string defects = solid_defects(mesh_as_written(mesh, format), progress);
    std::optional<Mesh> rounded;
    if (!defects.empty() && stores_floats(format) && solid_defects(mesh, progress).empty()) {
        rounded = round_to_float(mesh, path);
        defects = solid_defects(mesh_as_written(*rounded, format), progress);
    }
    if (!defects.empty())
        throw Error(status, path + ": not written: the result is not a clean solid as it would be stored (" +
                                defects + ")");
    io::write_mesh(rounded ? *rounded : mesh, path);
}

}  // namespace fabvdb::surface
