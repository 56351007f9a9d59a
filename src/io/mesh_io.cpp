//! Format dispatch by extension, and the checks every read mesh passes.
#include "io/mesh_io.h"

#include <algorithm>
#include <cctype>

#include "core/error.h"
#include "io/obj_format.h"
#include "io/off_format.h"
#include "io/ply_format.h"
#include "io/stl_format.h"
#include "io/threemf_format.h"

namespace fabvdb::io {

MeshFormat format_from_path(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    const size_t dot = path.find_last_of('.');
    std::string extension;
    if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) extension = path.substr(dot + 1);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == "stl") return MeshFormat::stl;
    if (extension == "obj") return MeshFormat::obj;
    if (extension == "ply") return MeshFormat::ply;
    if (extension == "off") return MeshFormat::off;
    if (extension == "3mf") return MeshFormat::threemf;
    const std::string named = extension.empty() ? "no extension" : "unknown extension '." + extension + "'";
    throw Error(FABVDB_ERR_BAD_INPUT, path + ": " + named + " (known: .stl, .obj, .ply, .off, .3mf)");
}

Mesh read_mesh(const std::string& path, Progress& progress) {
    const MeshFormat format = format_from_path(path);
    progress.stage("reading mesh");
    Mesh mesh;
    switch (format) {
        case MeshFormat::stl: mesh = read_stl(path, progress); break;
        case MeshFormat::obj: mesh = read_obj(path, progress); break;
        case MeshFormat::ply: mesh = read_ply(path, progress); break;
        case MeshFormat::off: mesh = read_off(path, progress); break;
        case MeshFormat::threemf: mesh = read_3mf(path, progress); break;
    }
    validate_mesh(mesh, path);
    if (mesh.triangles.empty()) throw Error(FABVDB_ERR_BAD_INPUT, path + ": no triangles");
    progress.update(1.0);
    return mesh;
}

void write_mesh(const Mesh& mesh, const std::string& path) {
    const MeshFormat format = format_from_path(path);
    validate_mesh(mesh, path);
    switch (format) {
        case MeshFormat::stl: write_stl(mesh, path); break;
        case MeshFormat::obj: write_obj(mesh, path); break;
        case MeshFormat::ply: write_ply(mesh, path); break;
        case MeshFormat::off: write_off(mesh, path); break;
        case MeshFormat::threemf: write_3mf(mesh, path); break;
    }
}

}  // namespace fabvdb::io
