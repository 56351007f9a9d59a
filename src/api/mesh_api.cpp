//! C API: mesh handles — creation from arrays, file read/write, accessors and
//! inspection (`fabvdb info`).
#include <cmath>
#include <map>
#include <string>

#include "api/guard.h"
#include "core/stage_clock.h"
#include "io/mesh_io.h"
#include "surface/inspect.h"
#include "surface/write_solid_mesh.h"

void fabvdb_mesh::flatten() {
    flat_vertices.resize(mesh.vertices.size() * 3);
    for (size_t i = 0; i < mesh.vertices.size(); ++i)
        for (int k = 0; k < 3; ++k) flat_vertices[3 * i + k] = mesh.vertices[i][k];
    flat_triangles.resize(mesh.triangles.size() * 3);
    for (size_t i = 0; i < mesh.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) flat_triangles[3 * i + k] = mesh.triangles[i][k];
}

namespace fabvdb::api {

fabvdb_mesh* new_mesh_handle(Mesh mesh, bool solid) {
    auto* handle = new fabvdb_mesh();
    handle->mesh = std::move(mesh);
    handle->solid = solid;
    handle->flatten();
    return handle;
}

}  // namespace fabvdb::api

extern "C" {

fabvdb_status fabvdb_mesh_new(fabvdb_ctx* ctx, const double* vertices, size_t vertex_count,
                              const uint32_t* triangles, size_t triangle_count, fabvdb_mesh** out) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(out, "out");
        if (vertex_count) fabvdb::api::require(vertices, "vertices");
        if (triangle_count) fabvdb::api::require(triangles, "triangles");
        fabvdb::Mesh mesh;
        mesh.vertices.resize(vertex_count);
        for (size_t i = 0; i < vertex_count; ++i)
            mesh.vertices[i] = {vertices[3 * i], vertices[3 * i + 1], vertices[3 * i + 2]};
        mesh.triangles.resize(triangle_count);
        for (size_t i = 0; i < triangle_count; ++i)
            mesh.triangles[i] = {triangles[3 * i], triangles[3 * i + 1], triangles[3 * i + 2]};
        fabvdb::validate_mesh(mesh, "mesh");
        *out = fabvdb::api::new_mesh_handle(std::move(mesh));
    });
}

void fabvdb_mesh_free(fabvdb_mesh* mesh) { delete mesh; }

fabvdb_status fabvdb_mesh_read(fabvdb_ctx* ctx, const char* path, fabvdb_mesh** out) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(path, "path");
        fabvdb::api::require(out, "out");
        fabvdb::Progress progress = ctx->make_progress();
        fabvdb_mesh* handle = fabvdb::api::new_mesh_handle(fabvdb::io::read_mesh(path, progress));
        handle->name = path;
        *out = handle;
    });
}

fabvdb_status fabvdb_mesh_write(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, const char* path) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(mesh, "mesh");
        fabvdb::api::require(path, "path");
        if (!mesh->solid) {
            fabvdb::io::write_mesh(mesh->mesh, path);
            return;
        }
        fabvdb::Progress progress = ctx->make_progress();
        progress.stage("check output");
        fabvdb::surface::write_solid_mesh(mesh->mesh, path, progress);
    });
}

fabvdb_status fabvdb_mesh_scale(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, double factor, fabvdb_mesh** out) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(mesh, "mesh");
        fabvdb::api::require(out, "out");
        if (!(std::isfinite(factor) && factor > 0))
            throw fabvdb::Error(FABVDB_ERR_INVALID_ARGUMENT, "the scale factor must be a positive number");
        fabvdb::Mesh scaled = mesh->mesh;
        for (fabvdb::Vec3& p : scaled.vertices)
            for (double& c : p) c *= factor;
        *out = fabvdb::api::new_mesh_handle(std::move(scaled), mesh->solid);
        (*out)->name = mesh->name;
    });
}

size_t fabvdb_mesh_vertex_count(const fabvdb_mesh* mesh) { return mesh ? mesh->mesh.vertices.size() : 0; }
size_t fabvdb_mesh_triangle_count(const fabvdb_mesh* mesh) { return mesh ? mesh->mesh.triangles.size() : 0; }
const double* fabvdb_mesh_vertices(const fabvdb_mesh* mesh) {
    return mesh && !mesh->flat_vertices.empty() ? mesh->flat_vertices.data() : nullptr;
}
const uint32_t* fabvdb_mesh_triangles(const fabvdb_mesh* mesh) {
    return mesh && !mesh->flat_triangles.empty() ? mesh->flat_triangles.data() : nullptr;
}

fabvdb_status fabvdb_mesh_inspect(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, fabvdb_report** out) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(mesh, "mesh");
        fabvdb::api::require(out, "out");
        std::map<std::string, double> stages;
        fabvdb::StageClock clock(stages);
        fabvdb::Progress progress = ctx->make_progress();
        nlohmann::json report = fabvdb::surface::inspect_mesh(mesh->mesh, progress);
        report["timings"] = {{"inspect", clock.lap("inspect")}, {"total", clock.total()}};
        *out = fabvdb::api::new_report_handle(std::move(report));
    });
}

}  // extern "C"
