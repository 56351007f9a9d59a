//! The powder samples as the turns of a cleaning routine see them, built
//! once for the drainability model: the first (as printed) turn on every
//! sample, the later turns on a grid coarser by a whole stride (a uniform
//! subsample of about 2500). Per turn: each sample's height along −gravity,
//! the sublevel forest of those heights (where powder flows without
//! climbing, sublevel_forest.h) and its ancestor chains as runs of ranks;
//! for the later grid also each sample's floor height, its links to the
//! 26 cells around it and the links powder slides down, and the first
//! turn's forest and floors on it too.
//! Per sample: its cavity, its rank in its cavity. Keeps a pointer to
//! `powder` (it must outlive the result). Costs one sublevel forest per turn
//! (in parallel).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/mesh.h"
#include "powder/cavity_patches.h"
#include "powder/orientation_flows.h"
#include "powder/powder_drop.h"
#include "powder/sample_grid.h"
#include "powder/sublevel_forest.h"

namespace fabvdb::powder {

//! The steps to the 26 cells around a sample, in the order of TurnSamples::later_links.
inline constexpr int kLinkOffsets[26][3] = {
    {1, 0, 0},   {-1, 0, 0},  {0, 1, 0},   {0, -1, 0},  {0, 0, 1},   {0, 0, -1},  {1, 1, 0},
    {1, -1, 0},  {-1, 1, 0},  {-1, -1, 0}, {1, 0, 1},   {1, 0, -1},  {-1, 0, 1},  {-1, 0, -1},
    {0, 1, 1},   {0, 1, -1},  {0, -1, 1},  {0, -1, -1}, {1, 1, 1},   {1, 1, -1},  {1, -1, 1},
    {1, -1, -1}, {-1, 1, 1},  {-1, 1, -1}, {-1, -1, 1}, {-1, -1, -1}};

//! A sublevel forest's ancestor chains as runs of samples of consecutive
//! ranks within their cavity (lowest first), so that a walk up a chain reads
//! its samples in order: the chain from grid sample a begins with the
//! samples of ranks rank[a] to run_end[a] − 1 and goes on from after_run[a]
//! (kNoSample: it ends there, at the root or where the chain would leave
//! the cavity).
struct SampleChains {
    std::vector<uint32_t> rank, run_end, after_run;
    //! Per cavity: the powder samples by rank.
    std::vector<std::vector<uint32_t>> by_rank;
};

//! The later-turn samples for one gravity: height along −gravity, and the
//! height of the floor each rests on: halfway to the lowest empty cell
//! around it down the way (a step with a part along gravity that holds no
//! sample), −∞ if none.
struct SampleRelief {
    std::vector<float> height, floor;
};

//! Where powder slides in one later turn (settle_powder.h): the links
//! (kLinkOffsets) one step down steeper than the angle of repose, deepest
//! first, and per cavity its later-turn samples' places in
//! TurnSamples::later_local's order, lowest first.
struct SampleSlides {
    std::vector<uint8_t> steps;
    std::vector<std::vector<uint32_t>> order;
};

struct TurnSamples {
    const PowderSamples* powder = nullptr;
    uint32_t cavity_count = 0;
    Vec3 first_gravity{0, 0, -1};
    std::vector<Vec3> later_gravity;  //!< per turn of the orientation set
    SampleGrid first_grid, later_grid;
    //! Per later-grid sample: the sample of each of the 26 cells around it
    //! (kLinkOffsets), kNoSample if none or if no path of face steps within
    //! the sample's cavity leads there (a diagonal step never cuts through a
    //! wall's edge or corner, no step crosses into another cavity).
    std::vector<std::array<uint32_t, 26>> later_links;
    SampleChains first_chains;
    //! Per later turn.
    std::vector<SublevelForest> later_forests;
    std::vector<SampleChains> later_chains;
    std::vector<SampleRelief> later_relief;
    std::vector<SampleSlides> later_slides;
    //! Per cavity, per later-turn sample by its place in later_local's
    //! order: the places of the samples it links to (later_links).
    std::vector<std::vector<std::array<uint32_t, 26>>> later_local_links;
    //! The first turn on the later grid too (for the surface of repose), and
    //! per first-grid sample the later-grid sample nearest it (kNoSample if none).
    SublevelForest first_later_forest;
    SampleRelief first_later_relief;
    std::vector<uint32_t> later_of_first;
    //! Per sample of each grid: its cavity. Per cavity: sample count of each grid.
    std::vector<uint32_t> first_cavity, later_cavity;
    std::vector<uint32_t> first_count, later_count;
    //! Per powder sample: its rank among its cavity's first-turn samples,
    //! and its place in its cavity's later-turn samples (the order of
    //! later_chains[0].by_rank; kNoSample if none).
    std::vector<uint32_t> first_rank, later_local;
};

//! `turns`: the orientation set (non-empty); `first`: as printed;
//! `repose_radians`: the powder's angle of repose (the slides' slope).
TurnSamples turn_samples(const CavityPatches& patches, const std::vector<OrientationFlow>& turns,
                         const OrientationFlow& first, const PowderSamples& powder, double repose_radians);

}  // namespace fabvdb::powder
