//! Writes a heat map of a per-patch value on the cavity surface: a binary
//! little-endian PLY whose vertices carry the value as a float `quality`
//! property and as viridis colours over [low, high] (clamped), as MeshLab
//! and Blender read them. A vertex's value is the area-weighted mean over
//! its triangles' patches. With `reverse_faces` (the default) the faces face
//! the powder (the cavity surface turned inside out); without, they keep the
//! surface's own orientation (an outer surface, as `fabvdb check`'s thickness
//! map). Written atomically (Error(IO) on failure, no
//! partial file). heatmap_colours gives the same colours as data (the C
//! API's fabvdb_heatmap).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "powder/cavity_patches.h"

namespace fabvdb::powder {

//! The per-vertex values of `per_patch` (area-weighted means).
std::vector<double> vertex_values(const Mesh& surface, const CavityPatches& patches,
                                  const std::vector<double>& per_patch);

//! The viridis colour of each value over [low, high] (clamped; an empty
//! range spans [low, low + 1]): the colours write_heatmap_ply writes.
std::vector<std::array<uint8_t, 3>> heatmap_colours(const std::vector<double>& vertex_value, double low, double high);

void write_heatmap_ply(const Mesh& surface, const std::vector<double>& vertex_value, double low, double high,
                       const std::string& description, const std::string& path, bool reverse_faces = true);

}  // namespace fabvdb::powder
