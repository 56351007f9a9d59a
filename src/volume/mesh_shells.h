//! Splits a triangle mesh into its shells: the connected components of
//! triangles sharing vertices, numbered in the order of their first triangle,
//! each with its signed volume (divergence theorem: positive for a closed
//! shell facing out, negative for one facing in); tells flat shells. Pure.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::volume {

struct MeshShell {
    std::vector<uint32_t> triangles;  //!< indices into the mesh's triangles
    double volume = 0.0;              //!< mm³, signed
};

std::vector<MeshShell> split_shells(const Mesh& mesh);

//! The triangles of `mesh` listed in `triangles`, with only the vertices they use.
Mesh sub_mesh(const Mesh& mesh, const std::vector<uint32_t>& triangles);

struct MeshShellCounts {
    uint64_t kept = 0;
    uint64_t dropped = 0;
};

//! Whether a shell is flat: its mean thickness 2|V|/A is under 1e-4 of
//! `diagonal` (the whole mesh's bounding-box diagonal; 0.01 mm on a 100 mm
//! part) and under 1% of its own diagonal (a sheet, not a crumb). Such a
//! shell bounds no volume worth printing and a ray test cannot tell its inside.
bool is_flat_shell(const Mesh& mesh, const MeshShell& shell, double diagonal);

//! Removes from `mesh` its shells, solid or void, whose volume is under
//! `min_volume` mm³ in magnitude or that are flat (`mesh` is left as it is
//! when none is).
MeshShellCounts drop_small_or_flat_shells(Mesh& mesh, double min_volume);

}  // namespace fabvdb::volume
