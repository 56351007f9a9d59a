//! A mold decomposition being edited (thesis §3.5, the studio): made once
//! from a mesh (pre-computation, automatic decomposition, boundary
//! smoothing) or from a decomposition.json, then changed one step at a time —
//! an edit (no_cut, cut, merge, smooth; only the parts it touches are
//! recomputed) or a re-run of the automatic decomposition with another γ,
//! part count or draft — with undo and redo over every step. Each step is
//! atomic: it succeeds whole or, on a refused edit or a cancel, leaves the
//! session exactly as it was. A step keeps the decomposition by value and
//! S_low by shared pointer (only smoothing moves S_low); moving through the
//! history to a step with another S_low measures the overlap terms of the
//! moved triangles again (update_moldability_terms), so the O(N²)-per-axis
//! terms are never copied. Not thread-safe: one caller at a time.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "surface/decompose.h"
#include "surface/decomposition_edits.h"

namespace fabvdb::surface {

class DecompositionSession {
public:
    //! Runs the pre-computation and the automatic decomposition (throws
    //! Error(CANCELLED), BAD_INPUT, OUT_OF_BUDGET as decompose_mesh does).
    DecompositionSession(const Mesh& input, const DecomposeSettings& settings, Progress& progress);
    //! Takes a decomposition.json (written by fabvdb decompose or a session)
    //! of `input`: its S_low, part labels and directions; the moldability
    //! terms are computed again and the parting lines recomputed for the
    //! written directions. Throws Error(BAD_INPUT) naming `name` and the defect.
    DecompositionSession(const Mesh& input, const nlohmann::json& document, const std::string& name,
                         Progress& progress);

    //! Applies one edit; returns its record (see apply_edit). Throws
    //! Error(BAD_INPUT) for a malformed edit or one that does not apply,
    //! leaving the session unchanged; clears the redo steps on success.
    nlohmann::json apply(const Edit& edit, Progress& progress);
    //! Runs the automatic decomposition again, from S_low as it was before
    //! any smoothing, with `options` (γ, part count, weights, smoothing) and
    //! the draft angle; the edit list starts anew. One undoable step.
    void rerun(const DecompositionOptions& options, double draft_radians, Progress& progress);
    //! Steps back / forward; false (nothing changed) when there is no step.
    bool undo();
    bool redo();
    size_t undo_steps() const { return current_; }
    size_t redo_steps() const { return history_.size() - 1 - current_; }

    const Mesh& input() const { return input_; }
    const Shell& shell() const { return shell_; }
    const MoldabilityTerms& terms() const { return terms_; }
    const Decomposition& decomposition() const { return step().decomposition; }
    const DecompositionOptions& options() const { return step().options; }
    double draft() const { return step().draft; }
    //! The edits since the last automatic decomposition, in order.
    const std::vector<Edit>& edits() const { return step().edits; }
    //! What the last automatic decomposition ran with (γ, part count, draft,
    //! weights), for replaying edits() with fabvdb decompose.
    nlohmann::json settings_document() const;

private:
    struct Step {
        std::shared_ptr<const Shell> shell;
        Decomposition decomposition;
        DecompositionOptions options;
        double draft = 0;
        std::vector<Edit> edits;
    };
    const Step& step() const { return history_[current_]; }
    void push(Step next);
    //! Makes shell_ equal `target`, measuring again the overlaps of every
    //! triangle with a moved corner, and sets the draft angle.
    void move_to(const std::shared_ptr<const Shell>& target, double draft);

    Mesh input_;
    std::shared_ptr<const Shell> unsmoothed_;  //!< S_low before any smoothing
    Shell shell_;                              //!< always equal to *step().shell
    MoldabilityTerms terms_;                   //!< always matches shell_
    std::vector<Step> history_;
    size_t current_ = 0;
};

}  // namespace fabvdb::surface
