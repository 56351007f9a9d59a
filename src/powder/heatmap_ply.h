//! Writes the drainability heat map: the cavity surface as a binary
//! little-endian PLY whose vertices carry the drainability (0 = powder stays,
//! 1 = it drains) as colours (red → yellow → green) and as a float `quality`
//! property, as MeshLab and Blender read them. A vertex's value is the
//! area-weighted mean over its triangles' patches. Written atomically
//! (Error(IO) on failure, no partial file).
#pragma once

#include <string>
#include <vector>

#include "core/mesh.h"
#include "powder/cavity_patches.h"

namespace fabvdb::powder {

void write_heatmap_ply(const Mesh& surface, const CavityPatches& patches, const std::vector<double>& drainability,
                       const std::string& path);

}  // namespace fabvdb::powder
