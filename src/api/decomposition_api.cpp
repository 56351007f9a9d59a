//! C API: decomposition sessions (fabvdb studio) — the handle around a
//! surface::DecompositionSession, typed edits, undo/redo, the flat arrays a
//! viewer reads (filled lazily after each change), the draft map, and the
//! decomposition folder and edit list it writes.
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <optional>

#include "api/decompose_settings.h"
#include "api/guard.h"
#include "api/options.h"
#include "core/atomic_output.h"
#include "core/stage_clock.h"
#include "surface/decomposition_io.h"
#include "surface/decomposition_session.h"
#include "surface/draft_map.h"

struct fabvdb_decomposition {
    std::optional<fabvdb::surface::DecompositionSession> session;
    fabvdb_decompose_options made_with{};  //!< the options the session was made with
    double last_seconds = 0;

    // The arrays handed out, filled on first use after a change.
    struct Arrays {
        bool mesh = false, labels = false, deformation = false, lines = false;
        std::vector<double> vertices;
        std::vector<uint32_t> triangles;
        std::vector<int32_t> label;
        std::vector<uint8_t> side;
        std::vector<float> heat;
        std::vector<double> line_points[2];
        std::vector<size_t> line_starts[2];
        std::vector<int32_t> line_parts[2];
    };
    mutable Arrays arrays;

    void changed(bool moved) {
        const bool triangles_known = !arrays.triangles.empty();
        arrays.labels = arrays.deformation = arrays.lines = false;
        if (moved || !triangles_known) arrays.mesh = false;
    }
    void fill_mesh() const;
    void fill_labels() const;
    void fill_deformation() const;
    void fill_lines() const;  //!< both kinds: part_lines gives them together
};

namespace {

using fabvdb::Error;
using fabvdb::surface::DecompositionSession;
using fabvdb::surface::Edit;

void fill_if(bool& done, const std::function<void()>& fill) {
    if (done) return;
    fill();
    done = true;
}

}  // namespace

void fabvdb_decomposition::fill_mesh() const {
    const fabvdb::surface::Shell& shell = session->shell();
    arrays.vertices.clear();
    for (const fabvdb::Vec3& p : shell.outer.vertices) arrays.vertices.insert(arrays.vertices.end(), p.begin(), p.end());
    arrays.triangles.clear();
    for (const fabvdb::Triangle& f : shell.outer.triangles)
        arrays.triangles.insert(arrays.triangles.end(), f.begin(), f.end());
}

void fabvdb_decomposition::fill_labels() const {
    const auto& d = session->decomposition();
    arrays.label.assign(d.part_of_triangle.begin(), d.part_of_triangle.end());
    const std::vector<char> upper = fabvdb::surface::outer_upper(session->shell(), d);
    arrays.side.assign(upper.begin(), upper.end());
}

void fabvdb_decomposition::fill_deformation() const {
    arrays.heat = fabvdb::surface::deformation_density(session->shell(), session->terms(), session->decomposition(),
                                                       session->options());
}

void fabvdb_decomposition::fill_lines() const {
    for (int kind = 0; kind < 2; ++kind) {
        arrays.line_points[kind].clear();
        arrays.line_starts[kind].assign(1, 0);
        arrays.line_parts[kind].clear();
    }
    const auto& d = session->decomposition();
    for (size_t p = 0; p < d.parts.size(); ++p) {
        const fabvdb::surface::PartLines lines = fabvdb::surface::part_lines(session->shell(), d, p);
        for (int kind = 0; kind < 2; ++kind)
            for (const auto& line : kind == FABVDB_LINES_PARTING ? lines.parting : lines.boundaries) {
                for (const fabvdb::Vec3& q : line)
                    arrays.line_points[kind].insert(arrays.line_points[kind].end(), q.begin(), q.end());
                arrays.line_starts[kind].push_back(arrays.line_points[kind].size() / 3);
                arrays.line_parts[kind].push_back(int32_t(p));
            }
    }
}

extern "C" {

void fabvdb_edit_init(fabvdb_edit* edit) {
    if (!edit) return;
    *edit = fabvdb_edit{};
    edit->struct_size = sizeof(fabvdb_edit);
    edit->type = FABVDB_EDIT_NO_CUT;
}

void fabvdb_decomposition_info_init(fabvdb_decomposition_info* info) {
    if (!info) return;
    *info = fabvdb_decomposition_info{};
    info->struct_size = sizeof(fabvdb_decomposition_info);
}

void fabvdb_part_info_init(fabvdb_part_info* info) {
    if (!info) return;
    *info = fabvdb_part_info{};
    info->struct_size = sizeof(fabvdb_part_info);
}

fabvdb_status fabvdb_decomposition_new(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, const fabvdb_decompose_options* opts,
                                       fabvdb_decomposition** out) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(mesh, "mesh");
        fabvdb::api::require(out, "out");
        const fabvdb_decompose_options options =
            fabvdb::api::options_from(opts, fabvdb_decompose_options_init, "fabvdb_decompose_options");
        fabvdb::surface::DecomposeSettings settings = fabvdb::api::decompose_settings(ctx, mesh->mesh, options);
        settings.shell.input_name = mesh->name;
        fabvdb::Progress progress = ctx->make_progress();
        const auto start = std::chrono::steady_clock::now();
        auto handle = std::make_unique<fabvdb_decomposition>();
        handle->session.emplace(mesh->mesh, settings, progress);
        fabvdb::api::require_faithful_low_res(mesh->mesh, handle->session->shell().outer, mesh->name, progress);
        handle->made_with = options;
        handle->made_with.shell_thickness = handle->session->shell().thickness;
        handle->last_seconds = fabvdb::seconds_since(start);
        *out = handle.release();
    });
}

fabvdb_status fabvdb_decomposition_read(fabvdb_ctx* ctx, const fabvdb_mesh* mesh, const char* path,
                                        fabvdb_decomposition** out) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(mesh, "mesh");
        fabvdb::api::require(path, "path");
        fabvdb::api::require(out, "out");
        std::ifstream in(path);
        if (!in) throw Error(FABVDB_ERR_IO, std::string(path) + ": cannot open the decomposition");
        nlohmann::json document;
        try {
            in >> document;
        } catch (const nlohmann::json::exception& e) {
            throw Error(FABVDB_ERR_BAD_INPUT, std::string(path) + ": not valid JSON (" + e.what() + ")");
        }
        fabvdb::Progress progress = ctx->make_progress();
        const auto start = std::chrono::steady_clock::now();
        auto handle = std::make_unique<fabvdb_decomposition>();
        handle->session.emplace(mesh->mesh, document, path, progress);
        fabvdb_decompose_options_init(&handle->made_with);
        const DecompositionSession& s = *handle->session;
        handle->made_with.shell_thickness = s.shell().thickness;
        handle->made_with.gamma = s.options().gamma;
        handle->made_with.parts = s.options().parts;
        handle->made_with.draft_degrees = s.draft() * 180.0 / M_PI;
        handle->made_with.w_overhang = s.options().weights.overhang;
        handle->made_with.w_overlap = s.options().weights.overlap;
        handle->made_with.w_coarse_overlap = s.options().overlap_weight;
        handle->made_with.low_res_triangles = int(s.shell().triangle_count());
        handle->last_seconds = fabvdb::seconds_since(start);
        *out = handle.release();
    });
}

void fabvdb_decomposition_free(fabvdb_decomposition* session) { delete session; }

fabvdb_status fabvdb_decomposition_apply(fabvdb_ctx* ctx, fabvdb_decomposition* session, const fabvdb_edit* edit) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(session, "session");
        fabvdb::api::require(edit, "edit");
        const fabvdb_edit given = fabvdb::api::options_from(edit, fabvdb_edit_init, "fabvdb_edit");
        edit = &given;
        Edit e;
        switch (edit->type) {
            case FABVDB_EDIT_NO_CUT: e.type = Edit::no_cut; break;
            case FABVDB_EDIT_CUT: e.type = Edit::cut; break;
            case FABVDB_EDIT_MERGE: e.type = Edit::merge; break;
            case FABVDB_EDIT_SMOOTH: e.type = Edit::smooth; break;
            default: throw Error(FABVDB_ERR_INVALID_ARGUMENT, "edit: unknown type " + std::to_string(int(edit->type)));
        }
        if (edit->point_count > 0) fabvdb::api::require(edit->points, "edit->points");
        for (size_t i = 0; i < edit->point_count; ++i)
            e.points.push_back({edit->points[3 * i], edit->points[3 * i + 1], edit->points[3 * i + 2]});
        e.radius = edit->radius;
        e.closed = (edit->flags & FABVDB_EDIT_CLOSED) != 0;
        fabvdb::Progress progress = ctx->make_progress();
        const auto start = std::chrono::steady_clock::now();
        session->session->apply(e, progress);
        session->last_seconds = fabvdb::seconds_since(start);
        session->changed(e.type == Edit::smooth);
    });
}

fabvdb_status fabvdb_decomposition_apply_json(fabvdb_ctx* ctx, fabvdb_decomposition* session,
                                              const char* edit_json) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(session, "session");
        fabvdb::api::require(edit_json, "edit_json");
        nlohmann::json item;
        try {
            item = nlohmann::json::parse(edit_json);
        } catch (const nlohmann::json::exception& e) {
            throw Error(FABVDB_ERR_BAD_INPUT, std::string("edit: not valid JSON (") + e.what() + ")");
        }
        const Edit e = fabvdb::surface::parse_edit(item, "edit");
        fabvdb::Progress progress = ctx->make_progress();
        const auto start = std::chrono::steady_clock::now();
        session->session->apply(e, progress);
        session->last_seconds = fabvdb::seconds_since(start);
        session->changed(e.type == Edit::smooth);
    });
}

fabvdb_status fabvdb_decomposition_rerun(fabvdb_ctx* ctx, fabvdb_decomposition* session,
                                         const fabvdb_decompose_options* opts) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(session, "session");
        fabvdb::api::require(opts, "opts");
        const fabvdb_decompose_options given =
            fabvdb::api::options_from(opts, fabvdb_decompose_options_init, "fabvdb_decompose_options");
        opts = &given;
        // The fields rerun does not read are those the session was made with.
        fabvdb_decompose_options merged = session->made_with;
        merged.gamma = opts->gamma;
        merged.parts = opts->parts;
        merged.max_parts = opts->max_parts;
        merged.draft_degrees = opts->draft_degrees;
        merged.w_overhang = opts->w_overhang;
        merged.w_overlap = opts->w_overlap;
        merged.w_coarse_overlap = opts->w_coarse_overlap;
        merged.smoothing_iterations = opts->smoothing_iterations;
        merged.w_smooth = opts->w_smooth;
        const fabvdb::surface::DecomposeSettings settings =
            fabvdb::api::decompose_settings(ctx, session->session->input(), merged);
        fabvdb::Progress progress = ctx->make_progress();
        const auto start = std::chrono::steady_clock::now();
        session->session->rerun(settings.decomposition, settings.draft_radians, progress);
        session->last_seconds = fabvdb::seconds_since(start);
        session->changed(true);
    });
}

fabvdb_status fabvdb_decomposition_get_options(fabvdb_ctx* ctx, const fabvdb_decomposition* session,
                                               fabvdb_decompose_options* out) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(session, "session");
        fabvdb::api::require(out, "out");
        const DecompositionSession& s = *session->session;
        fabvdb_decompose_options o = session->made_with;
        o.gamma = s.options().gamma;
        o.parts = s.options().parts;
        o.max_parts = s.options().max_parts;
        o.draft_degrees = s.draft() * 180.0 / M_PI;
        o.w_overhang = s.options().weights.overhang;
        o.w_overlap = s.options().weights.overlap;
        o.w_coarse_overlap = s.options().overlap_weight;
        o.smoothing_iterations = s.options().smoothing_iterations;
        o.w_smooth = s.options().smoothness_weight;
        fabvdb::api::write_to(o, out, "fabvdb_decompose_options");
    });
}

static fabvdb_status step(fabvdb_ctx* ctx, fabvdb_decomposition* session, bool forward) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(session, "session");
        const auto start = std::chrono::steady_clock::now();
        const bool done = forward ? session->session->redo() : session->session->undo();
        if (!done) throw Error(FABVDB_ERR_NOT_FOUND, forward ? "nothing to redo" : "nothing to undo");
        session->last_seconds = fabvdb::seconds_since(start);
        session->changed(true);
    });
}

fabvdb_status fabvdb_decomposition_undo(fabvdb_ctx* ctx, fabvdb_decomposition* session) {
    return step(ctx, session, false);
}

fabvdb_status fabvdb_decomposition_redo(fabvdb_ctx* ctx, fabvdb_decomposition* session) {
    return step(ctx, session, true);
}

fabvdb_status fabvdb_decomposition_get_info(fabvdb_ctx* ctx, const fabvdb_decomposition* session,
                                            fabvdb_decomposition_info* out) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(session, "session");
        fabvdb::api::require(out, "out");
        const DecompositionSession& s = *session->session;
        fabvdb_decomposition_info info;
        fabvdb_decomposition_info_init(&info);
        info.part_count = s.decomposition().parts.size();
        info.total_energy = s.decomposition().total_energy();
        info.gamma = s.options().gamma;
        info.over_gamma = !(info.total_energy < info.gamma);
        info.draft_degrees = s.draft() * 180.0 / M_PI;
        info.undo_steps = s.undo_steps();
        info.redo_steps = s.redo_steps();
        info.edit_count = s.edits().size();
        info.last_step_seconds = session->last_seconds;
        fabvdb::api::write_to(info, out, "fabvdb_decomposition_info");
    });
}

fabvdb_status fabvdb_decomposition_get_part(fabvdb_ctx* ctx, const fabvdb_decomposition* session, size_t part,
                                            fabvdb_part_info* out) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(session, "session");
        fabvdb::api::require(out, "out");
        const DecompositionSession& s = *session->session;
        const auto& d = s.decomposition();
        if (part >= d.parts.size())
            throw Error(FABVDB_ERR_NOT_FOUND, "part " + std::to_string(part) + " does not exist (" +
                                                  std::to_string(d.parts.size()) + " parts)");
        const fabvdb::surface::PartMolding& p = d.parts[part];
        fabvdb_part_info info;
        fabvdb_part_info_init(&info);
        const fabvdb::Vec3& dir = s.terms().directions.directions[p.direction];
        for (int k = 0; k < 3; ++k) info.direction[k] = dir[k];
        info.energy = p.energy.total;
        info.overhang_energy = p.energy.overhang;
        info.overlap_energy = p.energy.overlap;
        double area = 0;
        for (size_t i = 0; i < p.surface.size(); ++i)
            if (p.surface.kind[i] == fabvdb::surface::PartSurface::outer) {
                area += p.surface.area[i];
                ++info.triangle_count;
            }
        info.area = area / (s.shell().unit_scale * s.shell().unit_scale);
        fabvdb::api::write_to(info, out, "fabvdb_part_info");
    });
}

size_t fabvdb_decomposition_vertex_count(const fabvdb_decomposition* session) {
    return session ? session->session->shell().outer.vertices.size() : 0;
}

size_t fabvdb_decomposition_triangle_count(const fabvdb_decomposition* session) {
    return session ? session->session->shell().triangle_count() : 0;
}

const double* fabvdb_decomposition_vertices(const fabvdb_decomposition* session) {
    if (!session) return nullptr;
    try {
        fill_if(session->arrays.mesh, [&] { session->fill_mesh(); });
        return session->arrays.vertices.data();
    } catch (...) {
        return nullptr;
    }
}

const uint32_t* fabvdb_decomposition_triangles(const fabvdb_decomposition* session) {
    if (!session) return nullptr;
    try {
        fill_if(session->arrays.mesh, [&] { session->fill_mesh(); });
        return session->arrays.triangles.data();
    } catch (...) {
        return nullptr;
    }
}

const int32_t* fabvdb_decomposition_labels(const fabvdb_decomposition* session) {
    if (!session) return nullptr;
    try {
        fill_if(session->arrays.labels, [&] { session->fill_labels(); });
        return session->arrays.label.data();
    } catch (...) {
        return nullptr;
    }
}

const uint8_t* fabvdb_decomposition_sides(const fabvdb_decomposition* session) {
    if (!session) return nullptr;
    try {
        fill_if(session->arrays.labels, [&] { session->fill_labels(); });
        return session->arrays.side.data();
    } catch (...) {
        return nullptr;
    }
}

const float* fabvdb_decomposition_deformation(const fabvdb_decomposition* session) {
    if (!session) return nullptr;
    try {
        fill_if(session->arrays.deformation, [&] { session->fill_deformation(); });
        return session->arrays.heat.data();
    } catch (...) {
        return nullptr;
    }
}

fabvdb_status fabvdb_decomposition_lines(fabvdb_ctx* ctx, const fabvdb_decomposition* session, int kind,
                                         const double** points, size_t* point_count, const size_t** starts,
                                         const int32_t** parts, size_t* line_count) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(session, "session");
        fabvdb::api::require(points, "points");
        fabvdb::api::require(point_count, "point_count");
        fabvdb::api::require(starts, "starts");
        fabvdb::api::require(parts, "parts");
        fabvdb::api::require(line_count, "line_count");
        if (kind != FABVDB_LINES_PARTING && kind != FABVDB_LINES_BOUNDARY)
            throw Error(FABVDB_ERR_INVALID_ARGUMENT, "kind must be FABVDB_LINES_PARTING or FABVDB_LINES_BOUNDARY");
        fill_if(session->arrays.lines, [&] { session->fill_lines(); });
        *points = session->arrays.line_points[kind].data();
        *point_count = session->arrays.line_points[kind].size() / 3;
        *starts = session->arrays.line_starts[kind].data();
        *parts = session->arrays.line_parts[kind].data();
        *line_count = session->arrays.line_parts[kind].size();
    });
}

fabvdb_status fabvdb_decomposition_draft_map(fabvdb_ctx* ctx, const fabvdb_decomposition* session,
                                             const double direction[3], double draft_degrees, uint8_t* out) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(session, "session");
        fabvdb::api::require(direction, "direction");
        fabvdb::api::require(out, "out");
        const fabvdb::Vec3 d{direction[0], direction[1], direction[2]};
        const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (!(length > 0) || !std::isfinite(length))
            throw Error(FABVDB_ERR_INVALID_ARGUMENT, "direction must be a finite non-zero vector");
        if (!(draft_degrees >= 0 && draft_degrees <= 30))
            throw Error(FABVDB_ERR_INVALID_ARGUMENT, "draft_degrees must be in [0, 30]");
        const std::vector<uint8_t> classes =
            fabvdb::surface::draft_map(session->session->shell(), d, draft_degrees * M_PI / 180.0);
        std::copy(classes.begin(), classes.end(), out);
    });
}

fabvdb_status fabvdb_decomposition_write(fabvdb_ctx* ctx, const fabvdb_decomposition* session, const char* out_dir) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(session, "session");
        fabvdb::api::require(out_dir, "out_dir");
        const DecompositionSession& s = *session->session;
        fabvdb::surface::write_decomposition(out_dir, s.input(), s.shell(), s.terms(), s.decomposition(), s.options());
    });
}

fabvdb_status fabvdb_decomposition_write_edits(fabvdb_ctx* ctx, const fabvdb_decomposition* session,
                                               const char* path) {
    return fabvdb::api::guard(ctx, [&] {
        fabvdb::api::require(session, "session");
        fabvdb::api::require(path, "path");
        const DecompositionSession& s = *session->session;
        nlohmann::json document = fabvdb::surface::edits_document(s.edits());
        document["settings"] = s.settings_document();
        fabvdb::write_text_file_atomically(path, document.dump(1) + "\n");
    });
}

}  // extern "C"
