//! The volume side of the mold decomposition's pre-computation (thesis
//! §3.4.2): the robust signed distance of the input at a voxel size chosen for
//! the S_low target, S_low from its zero level set (low_res_surface), and the
//! prism inner vertices and medial depths (shell_prisms). Plain types only,
//! so callers outside the volume module need no OpenVDB. `solid`: prisms
//! reach the medial axis (depths up to half the longest side), and ω is the
//! depth of the solid's deepest point, plus two voxels. A closed input
//! thinner on average than two voxels (its mean thickness 2V/A, a plate's
//! own) gets a voxel of half that mean, at most 8 times finer than the
//! automatic one, so that voxel centres lie inside it. Cancellable;
//! refuses with Error(OUT_OF_BUDGET) before exceeding the memory budget.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

struct LowResShellOptions {
    size_t target_triangles = 10000;  //!< S_low size N_Δ
    double thickness = 0;             //!< ω in mm (ignored when solid)
    bool solid = false;
    //! mm the band reaches inside when solid; 0: half the longest side. A
    //! caller that knows the part is nowhere deeper (decompose_mesh, for a
    //! part thin everywhere) keeps the band, and the memory, small.
    double solid_depth = 0;
    uint64_t memory_budget_bytes = 0;
    std::string input_name = "mesh";
};

struct LowResShell {
    Mesh outer;                  //!< S_low
    std::vector<Vec3> inner;     //!< inner vertex per outer vertex
    std::vector<double> depth;   //!< medial depth per outer vertex (capped at 2ω, or the solid depth)
    double thickness = 0;        //!< the ω used; when solid, the solid's deepest point + 2 voxels
    double voxel_size = 0;
    int half_band_voxels = 0;
    std::map<std::string, double> seconds;  //!< per stage
};

LowResShell low_res_shell(const Mesh& input, const LowResShellOptions& options, Progress& progress);

}  // namespace fabvdb::volume
