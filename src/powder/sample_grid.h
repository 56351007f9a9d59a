//! The powder samples on a grid coarser by a whole `stride` (every
//! stride-th cell along each axis), as a graph: each kept sample with its six
//! face neighbours on that grid (kNoSample where the cell holds none), and a
//! lookup of the kept sample nearest a point. Stride 1 keeps every sample.
//! Guarantees: `sample[k]` indexes PowderSamples; neighbours are symmetric.
#pragma once

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/mesh.h"
#include "powder/powder_drop.h"

namespace fabvdb::powder {

constexpr uint32_t kNoSample = UINT32_MAX;

struct SampleGrid {
    int stride = 1;
    std::vector<uint32_t> sample;
    std::vector<std::array<uint32_t, 6>> neighbours;

    size_t size() const { return sample.size(); }
    //! The kept sample nearest `point` within two strides of its cell, or kNoSample.
    uint32_t nearest(const Vec3& point) const;

private:
    friend SampleGrid sample_grid(const PowderSamples& powder, int stride);
    const PowderSamples* powder_ = nullptr;
    std::unordered_map<uint64_t, uint32_t> index_;
};

//! Keeps a reference to `powder`: it must outlive the grid.
SampleGrid sample_grid(const PowderSamples& powder, int stride);

}  // namespace fabvdb::powder
