//! The reference powder simulation that keeps the drainability model honest.
//! It shares no code with the model: a voxel sand pile. The cavity of the
//! part (the empty space the outside cannot reach once the holes are plugged)
//! is filled with powder; the holes are drilled cylinders open to the
//! outside. For each turn of the routine the part is voxelised in a frame
//! whose z axis points up (against that turn's gravity); then, until nothing
//! moves, a grain falls while the cell below it is free, and a grain with a
//! free cell beside it (on the pile's top, or on a face the pile shows
//! sideways, as over an opening in a side wall: grains above do not hold a
//! face up) topples one cell sideways toward the steepest
//! direction where the ground, within `slope_window` cells, lies lower than
//! the angle of repose allows (drops in whole cells, rounded up, so a
//! staircase drawn at exactly the angle stays; the ground seen ahead falls
//! away at most one cell per step, so a pit or cliff a few cells away does
//! not pull a grain resting on flat ground). Grains that reach the outside are
//! gone. Between turns the grains keep their world positions; a grain that
//! finds no free cell near its place in the next turn's frame (a nearly full
//! cavity voxelises to a few cells fewer in a turned frame) waits inside and
//! is placed once the pile has moved. Reports the powder left inside after
//! each turn. Cancellable (Error(CANCELLED)). Cost: each pass of a settling
//! visits only the grains that are not buried (the pile's surface); the
//! passes grow with the powder that must leave through the holes.
#pragma once

#include <vector>

#include <openvdb/openvdb.h>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::powder {

struct SandpileHole {
    Vec3 center{0, 0, 0};  //!< where the drill meets the cavity
    Vec3 axis{0, 0, 1};    //!< unit, out of the cavity
    double diameter = 4.0;
    double depth = 0.0;    //!< drilled length along the axis from the center
};

struct SandpileOptions {
    double cell_size = 0.0;  //!< mm; 0: the solid grid's voxel size
    double repose_radians = 0.6108652381980153;  // 35°
    int slope_window = 4;
    //! Gravity of each turn, in order.
    std::vector<Vec3> routine{{0, 0, -1}};
};

struct SandpileResult {
    double initial_volume = 0.0;   //!< mm³ of powder in the full cavity
    double residual_volume = 0.0;  //!< mm³ left inside after the routine
    std::vector<double> residual_after_turn;
    double residual_fraction() const { return initial_volume > 0 ? residual_volume / initial_volume : 0.0; }
};

//! `solid` is the part's level set, negative in its material (the hollow
//! shell, drilled or not).
SandpileResult simulate_sandpile(const openvdb::FloatGrid& solid, const std::vector<SandpileHole>& holes,
                                 const SandpileOptions& options, Progress& progress);

}  // namespace fabvdb::powder
