//! The powder of a full cavity, dropped in the first orientation: samples the
//! cavity (the inside of its level set) on a regular grid of about
//! `max_samples` points (a cavity one voxel thin that this grid misses is
//! sampled at its own voxels), drops each along gravity onto the cavity surface
//! (Embree) and follows the settle matrix to the patch where it comes to rest.
//! Every sample stands for `sample_volume` mm³ of powder; their sum is the
//! cavity volume to within the sampling. Each sample keeps its grid cell
//! (position = origin + cell · spacing). A cavity that holds no sample is
//! Error(BAD_INPUT) naming `input_name`. Cancellable (Error(CANCELLED)).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"
#include "powder/cavity_patches.h"
#include "powder/orientation_flows.h"
#include "volume/surface_ray_caster.h"

namespace fabvdb::powder {

struct PowderSamples {
    std::vector<Vec3> position;
    //! The patch where the sample's powder comes to rest in the first orientation.
    std::vector<uint32_t> rest_patch;
    //! The sample's cell on the regular sampling grid.
    std::vector<std::array<int32_t, 3>> cell;
    Vec3 origin{0, 0, 0};
    double spacing = 0.0;
    double sample_volume = 0.0;

    double total_volume() const { return sample_volume * double(position.size()); }
};

PowderSamples drop_cavity_powder(const openvdb::FloatGrid& cavity, const CavityPatches& patches,
                                 const volume::SurfaceRayCaster& caster, const OrientationFlow& first, size_t max_samples,
                                 const std::string& input_name, Progress& progress);

}  // namespace fabvdb::powder
