//! User edits of a mold decomposition (thesis §3.5), given in world
//! coordinates so that they survive remeshing, read from a JSON file:
//!   {"edits": [{"type": "no_cut", "points": [[x,y,z], ...], "radius": r},
//!              {"type": "cut", "points": [[x,y,z], ...], "closed": true|false},
//!              {"type": "merge", "points": [[x,y,z], [x,y,z]]},
//!              {"type": "smooth", "points": [[x,y,z], ...], "radius": r}]}
//! - no_cut: the S_low triangles within `radius` of the stroke (its largest
//!   edge-connected piece) become one element and the parts it touches are
//!   regrown together (§3.4.3), so the stroke ends up inside one part;
//! - cut: the polyline, snapped to S_low vertices and joined by shortest edge
//!   paths, splits every part it separates; each piece gets
//!   argmin_{d∈D} E_P(P, d);
//! - merge: the two (neighbouring) parts under the points become one, with
//!   argmin_{d∈D} E_P(P, d);
//! - smooth: the boundary smoothing of §3.4.5 (selective smoothing, §3.5)
//!   moving only the snake vertices within `radius` of the stroke's points.
//! Only the touched parts change; their parting lines are recomputed.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "surface/coarse_decomposition.h"

namespace fabvdb::surface {

struct Edit {
    enum Type { no_cut, cut, merge, smooth };
    Type type = no_cut;
    std::vector<Vec3> points;
    double radius = 0;
    bool closed = false;
};

//! Throws Error(IO) if the file cannot be read, Error(BAD_INPUT) naming the
//! file, the edit and the defect if it is malformed.
std::vector<Edit> read_edits(const std::string& path);

//! One edit object of the document; throws Error(BAD_INPUT) naming `what`
//! and the defect if it is malformed.
Edit parse_edit(const nlohmann::json& item, const std::string& what);

//! Throws Error(BAD_INPUT) naming `what` and the defect if `edit` is
//! malformed: no points, a point not finite, a no_cut or smooth stroke
//! without radius > 0, a cut of fewer than two points, a merge not of two.
void check_edit(const Edit& edit, const std::string& what);

//! The edits as the document read_edits reads (`{"edits": [...]}`).
nlohmann::json edits_document(const std::vector<Edit>& edits);

//! The edit type's name in the document ("no_cut", "cut", "merge", "smooth").
const char* edit_type_name(Edit::Type type);

//! Applies `edit` (number `index` in the file, for messages); returns a record
//! {type, parts_touched, parts_after, seconds, total_moldability_energy}.
//! A smooth edit moves S_low vertices, so it updates `shell` and `terms`.
//! Throws Error(BAD_INPUT) for an edit that does not apply (a cut that
//! separates nothing, a merge of one part or of parts that do not touch, a
//! smoothing stroke that reaches no part boundary).
nlohmann::json apply_edit(Shell& shell, MoldabilityTerms& terms, const DecompositionOptions& options,
                          const Edit& edit, size_t index, Decomposition& decomposition, Progress& progress);

}  // namespace fabvdb::surface
