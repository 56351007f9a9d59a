//! DecompositionSession: the history of steps, each edit applied to a copy
//! of the current decomposition, S_low restored by position comparison.
#include "surface/decomposition_session.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.h"
#include "surface/boundary_smoothing.h"
#include "surface/decomposition_parts.h"
#include "surface/shell_from_mesh.h"

namespace fabvdb::surface {

namespace {

//! Steps kept for undo; the oldest are dropped beyond (a step is a copy of
//! the decomposition, about 1 MB at N = 10 000).
constexpr size_t max_history = 256;

template <class T>
T field(const nlohmann::json& document, const char* key, const std::string& name) {
    if (!document.contains(key)) throw Error(FABVDB_ERR_BAD_INPUT, name + ": no \"" + key + "\"");
    try {
        return document.at(key).get<T>();
    } catch (const nlohmann::json::exception&) {
        throw Error(FABVDB_ERR_BAD_INPUT, name + ": \"" + key + "\" has the wrong type");
    }
}

}  // namespace

DecompositionSession::DecompositionSession(const Mesh& input, const DecomposeSettings& settings,
                                           Progress& progress)
    : input_(input) {
    shell_ = shell_from_mesh(input, settings.shell, progress, nullptr);
    terms_ = compute_moldability_terms(shell_, settings.draft_radians, progress);
    unsmoothed_ = std::make_shared<const Shell>(shell_);
    nlohmann::json log = nlohmann::json::array();
    Step first;
    first.options = settings.decomposition;
    first.draft = settings.draft_radians;
    first.decomposition = coarse_decomposition(shell_, terms_, first.options, log, progress);
    if (first.options.smoothing_iterations > 0) progress.stage("boundary smoothing");
    smooth_boundaries(shell_, terms_, first.decomposition, first.options, nullptr, progress);
    first.shell = std::make_shared<const Shell>(shell_);
    history_.push_back(std::move(first));
}

DecompositionSession::DecompositionSession(const Mesh& input, const nlohmann::json& document,
                                           const std::string& name, Progress& progress)
    : input_(input) {
    // Validates the format, the indices, closed parts and that S_low lies on `input`.
    const DecomposedModel model = decomposed_parts(document, name, input);
    progress.stage("read decomposition");
    const nlohmann::json& low = document.at("low_res_surface");
    Mesh outer;
    outer.vertices = field<std::vector<Vec3>>(low, "vertices", name + ": low_res_surface");
    outer.triangles = field<std::vector<Triangle>>(low, "triangles", name + ": low_res_surface");
    std::vector<Vec3> inner = field<std::vector<Vec3>>(low, "inner_vertices", name + ": low_res_surface");
    std::vector<int> thin = field<std::vector<int>>(low, "thin_segment", name + ": low_res_surface");
    shell_ = make_shell(std::move(outer), std::move(inner), std::move(thin), model.shell_thickness, name);
    shell_.solid = document.value("solid", false);
    Step first;
    first.options.gamma = field<double>(document, "gamma", name);
    const double draft_degrees = field<double>(document, "draft_degrees", name);
    if (!(first.options.gamma > 0) || !(draft_degrees >= 0 && draft_degrees <= 30))
        throw Error(FABVDB_ERR_BAD_INPUT, name + ": gamma must be > 0 and draft_degrees in [0, 30]");
    if (document.contains("weights")) {
        const nlohmann::json& w = document["weights"];
        first.options.weights.overhang = field<double>(w, "w_H", name + ": weights");
        first.options.weights.overlap = field<double>(w, "w_L", name + ": weights");
        first.options.overlap_weight = field<double>(w, "w_O", name + ": weights");
    }
    first.draft = draft_degrees * M_PI / 180.0;
    terms_ = compute_moldability_terms(shell_, first.draft, progress);
    first.decomposition.part_of_triangle = field<std::vector<int>>(document, "part_of_triangle", name);
    std::vector<int> directions;
    for (const DecomposedPart& part : model.parts) directions.push_back(closest_direction(terms_, part.direction));
    first.decomposition.parts = parting_lines(shell_, terms_, first.decomposition.part_of_triangle, directions,
                                              first.options.weights);
    first.options.parts = int(directions.size());
    unsmoothed_ = std::make_shared<const Shell>(shell_);
    first.shell = unsmoothed_;
    history_.push_back(std::move(first));
}

nlohmann::json DecompositionSession::apply(const Edit& edit, Progress& progress) {
    check_edit(edit, "edit " + std::to_string(edits().size() + 1));
    Step next{step().shell, step().decomposition, step().options, step().draft, step().edits};
    nlohmann::json record;
    try {
        record = apply_edit(shell_, terms_, next.options, edit, next.edits.size(), next.decomposition, progress);
    } catch (...) {
        if (edit.type == Edit::smooth) move_to(step().shell, step().draft);
        throw;
    }
    if (edit.type == Edit::smooth) next.shell = std::make_shared<const Shell>(shell_);
    next.edits.push_back(edit);
    push(std::move(next));
    return record;
}

void DecompositionSession::rerun(const DecompositionOptions& options, double draft_radians, Progress& progress) {
    const std::shared_ptr<const Shell> before = step().shell;
    const double before_draft = step().draft;
    try {
        move_to(unsmoothed_, draft_radians);
        Step next;
        next.options = options;
        next.draft = draft_radians;
        nlohmann::json log = nlohmann::json::array();
        next.decomposition = coarse_decomposition(shell_, terms_, options, log, progress);
        if (options.smoothing_iterations > 0) progress.stage("boundary smoothing");
        smooth_boundaries(shell_, terms_, next.decomposition, options, nullptr, progress);
        next.shell = std::make_shared<const Shell>(shell_);
        push(std::move(next));
    } catch (...) {
        move_to(before, before_draft);
        throw;
    }
}

bool DecompositionSession::undo() {
    if (current_ == 0) return false;
    move_to(history_[current_ - 1].shell, history_[current_ - 1].draft);
    --current_;
    return true;
}

bool DecompositionSession::redo() {
    if (current_ + 1 >= history_.size()) return false;
    move_to(history_[current_ + 1].shell, history_[current_ + 1].draft);
    ++current_;
    return true;
}

nlohmann::json DecompositionSession::settings_document() const {
    const DecompositionOptions& o = options();
    return {{"gamma", o.gamma},
            {"parts", o.parts},
            {"max_parts", o.max_parts},
            {"draft_degrees", draft() * 180.0 / M_PI},
            {"w_H", o.weights.overhang},
            {"w_L", o.weights.overlap},
            {"w_O", o.overlap_weight},
            {"smoothing_iterations", o.smoothing_iterations},
            {"w_smooth", o.smoothness_weight},
            {"shell_thickness", shell_.thickness},
            {"low_res_triangles", shell_.triangle_count()}};
}

void DecompositionSession::push(Step next) {
    history_.resize(current_ + 1);
    history_.push_back(std::move(next));
    if (history_.size() > max_history) history_.erase(history_.begin());
    current_ = history_.size() - 1;
}

void DecompositionSession::move_to(const std::shared_ptr<const Shell>& target, double draft) {
    terms_.draft = draft;
    const Shell& to = *target;
    std::vector<char> moved(to.outer.vertices.size(), 0);
    bool any = false;
    for (size_t v = 0; v < moved.size(); ++v) {
        moved[v] = shell_.outer.vertices[v] != to.outer.vertices[v] || shell_.inner[v] != to.inner[v];
        any |= moved[v] != 0;
    }
    if (!any) return;
    std::vector<uint32_t> changed;
    for (size_t t = 0; t < to.triangle_count(); ++t) {
        const Triangle& f = to.outer.triangles[t];
        if (moved[f[0]] || moved[f[1]] || moved[f[2]]) changed.push_back(uint32_t(t));
    }
    shell_ = to;
    std::vector<int> axes(terms_.axes.size());
    std::iota(axes.begin(), axes.end(), 0);
    update_moldability_terms(shell_, changed, axes, terms_);
}

}  // namespace fabvdb::surface
