//! A fresh narrow band around one iso-surface of a scalar grid: the surface
//! {value = isovalue} is extracted (volumeToMesh), its unsigned distance is
//! computed in a narrow band (meshToVolume), and each band voxel takes its
//! sign from the input grid at the same voxel, so the result is the signed
//! distance of that surface (isovalue 0: the grid's own surface made exact;
//! > 0: grown by that distance) — exact within a voxel of the surface, within
//! about 0.8 voxel farther out in the band (meshToVolume's unsigned band is
//! not a true distance there) — that keeps every enclosed cavity, unlike OpenVDB's
//! levelSetRebuild, whose exterior flood fills cavities. Off the band, signs
//! come from signedFloodFill. Level set class, name and transform kept.
//! Cancellable.
#pragma once

#include <openvdb/openvdb.h>

#include "core/progress.h"

namespace fabvdb::volume {

openvdb::FloatGrid::Ptr rebuild_band(const openvdb::FloatGrid& grid, double isovalue, int half_band_voxels,
                                     Progress& progress);

}  // namespace fabvdb::volume
