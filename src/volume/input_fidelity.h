//! The fidelity gate: whether a solid a command derived from its input still
//! is the input's model, beside the validity check of what it writes
//! (clean_solid.h): a closed, outward, uncrossed mesh can still be an
//! 8-triangle sliver of the scan it came from.
//! Measures, at kFidelitySamples points spread over the input's surface by area (a
//! fixed seed: the same figures on every run), the distance to the output's
//! surface. A point farther than `limits.distance` counts against the output
//! unless it lies on an inner face (the generalized winding number,
//! winding_number.h, 1e-4 of the diagonal behind and in front of it along
//! its triangle's normal, is at least ½ in magnitude on both sides: a shell
//! inside another), on the wall of a slit narrower than `limits.distance`
//! (the solid on one side only, and again on the open side half or all of
//! `limits.distance` away: the gaps between the convex pieces of a VHACD
//! mesh may close) or in an exempt ball. Surface with no clear solid on
//! either side (|w| under ¾ on both: a sheet, whose winding number is about
//! ±½ on its two sides, or a scan's loose flap) counts: the model has it.
//! The output fails when more than `limits.far_share` of the counted surface
//! is far, or, with `limits.volume`, when the volume it
//! encloses and the input's solid {|w| ≥ ½} (estimated at kFidelityVolumePoints of a
//! Halton sequence over the input's bounding box) differ by more than
//! `limits.distance` × the input's area plus four standard errors of the
//! estimate — unless, at a tenth as many of those points as lie in the
//! solid, the winding number is between ¼ and ¾ (a soup wound every which
//! way, a scan missing a side): it does not tell the volume there, and the
//! volumes are not compared. An output that fails is measured again against
//! the input oriented as the repair orients it (orient_soup.h: each piece
//! outward, voids inward), whose winding number tells one solid where shells
//! wound every which way cancel (an inside-out box overlapping an outward
//! one): it passes when that passes.
//! Distances are measured on the output's triangles, never read from the
//! level set it was meshed from (shells dropped at extraction would not
//! show): 0 on a triangle the output kept from the input (the same corners
//! as floats), else the distance to the nearest of the triangles it did not
//! keep when that is within `limits.distance` (those no wider than twice
//! that, as a level set's are, found in a grid of cells of about that
//! width; wider ones in an AABB tree), and exactly on the whole output for
//! the far samples that count.
//! Costs a hash of both meshes' triangles, a sort by cell of the narrow
//! triangles the output did not keep and a tree of the wide ones, an AABB
//! tree over the whole output only when some sample that counts is far, a
//! winding-number tree over the input only when some sample is far or for
//! the volume, two to four winding numbers per far sample and
//! kFidelityVolumePoints for the volume; queries in parallel. Reports
//! progress; throws Error(CANCELLED).
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

struct FidelityLimits {
    double distance = 0.0;   //!< mm: input surface farther from the output is far
    double far_share = 0.0;  //!< the largest share of the solid's surface that may be far
    bool volume = true;      //!< also compare the enclosed volumes (outputs that keep the input's solid)
    //! Balls (centre, radius in mm) where the output differs from the input
    //! by design, such as drilled holes: samples in them are left out.
    std::vector<std::pair<Vec3, double>> exempt;
};

struct Fidelity {
    double max = 0.0;        //!< mm, over the samples on the solid's surface
    double mean = 0.0;       //!< mm, likewise
    double far_share = 0.0;  //!< of the samples on the solid's surface, the share farther than limits.distance
    //! of the same, the share far on surface with no clear solid on either
    //! side (sheets, loose flaps): what no voxel size brings back
    double far_sheet_share = 0.0;
    size_t samples = 0;      //!< taken on the input's surface
    size_t left_out = 0;     //!< far samples on inner faces, slit walls or in exempt balls
    double input_volume = 0.0;      //!< mm³, estimated (0 when not compared)
    double output_volume = 0.0;     //!< mm³, exact (0 when not compared)
    double volume_tolerance = 0.0;  //!< mm³
    //! false when the input's winding number does not tell its volume (see above)
    bool volume_compared = false;
    //! The figures are against the input oriented as the repair orients it
    //! (orient_soup.h): against the input as given it failed.
    bool oriented_reference = false;
    bool passed = true;
    //! When not passed: what is wrong, in words, with the figures.
    std::string defect;
};

//! Points taken on the input's surface.
constexpr size_t kFidelitySamples = 8192;
//! Points of the Halton sequence the input's volume is estimated at.
constexpr size_t kFidelityVolumePoints = 4096;

//! For an output cut out of the input's own triangles (mesh-level repair,
//! crossings resolved): far is 1e-4 of the input's diagonal, and at most
//! 0.5% of the surface may be; the volume is not compared (the output's
//! surface lies on the input's, and its validity is checked apart).
FidelityLimits exact_limits(const Mesh& input);
//! For an output meshed from a level set of voxel `voxel`: far is two
//! voxels, and at most 2% of the surface may be (features thinner than a
//! voxel close or vanish).
FidelityLimits voxel_limits(double voxel);

//! `output`: a closed, outward-oriented mesh (the solid as written; for a
//! hollowed part its outer shells). An empty input or output fails.
Fidelity measure_fidelity(const Mesh& input, const Mesh& output, const FidelityLimits& limits,
                          Progress& progress);

//! Whether the same output made at a finer voxel may pass: it failed, and
//! not on its far sheets alone (no voxel size makes a sheet solid).
inline bool finer_may_pass(const Fidelity& fidelity, const FidelityLimits& limits) {
    return !fidelity.passed && !(fidelity.far_sheet_share > limits.far_share);
}

//! Throws Error(INTERNAL), "NAME: the WHAT is not the input's model: DEFECT",
//! when `fidelity` did not pass.
void require_faithful(const Fidelity& fidelity, const std::string& input_name, const std::string& what);

}  // namespace fabvdb::volume
