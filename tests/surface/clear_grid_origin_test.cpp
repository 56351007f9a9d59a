// Grid lines placed clear of coordinates: the returned origin lies in
// (start − step, start], and no origin sampled finely over that range keeps
// its lines farther from the coordinates (distances measured here by
// rounding to the nearest line, not by the gaps the function sorts).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/error.h"
#include "surface/clear_grid_origin.h"

namespace {

double clearance(const std::vector<double>& coordinates, double origin, double step) {
    double nearest = HUGE_VAL;
    for (double c : coordinates) {
        const double line = origin + std::round((c - origin) / step) * step;
        nearest = std::min(nearest, std::abs(c - line));
    }
    return nearest;
}

void expect_clearest(const std::vector<double>& coordinates, double start, double step) {
    const double origin = fabvdb::surface::clear_grid_origin(coordinates, start, step);
    EXPECT_LE(origin, start);
    EXPECT_GT(origin, start - step);
    const double found = clearance(coordinates, origin, step);
    const int samples = 20000;
    for (int k = 0; k < samples; ++k) {
        const double sampled = start - step * k / samples;
        ASSERT_LE(clearance(coordinates, sampled, step), found + 1e-12) << "origin " << sampled;
    }
}

TEST(ClearGridOrigin, LinesAtTheBoundingBoxWouldRunThroughTheExtremeVertex) {
    // Lines a whole number of steps from the lowest coordinate (the block's
    // side a margin of 8 steps from it) would pass through it: they move off
    // by half a step, the widest gap of coordinates on one lattice.
    const std::vector<double> on_lattice{-33.951975000320004, -33.951975000320004 + 2.5, -33.951975000320004 + 10};
    const double start = on_lattice[0] - 10.0;
    const double origin = fabvdb::surface::clear_grid_origin(on_lattice, start, 1.25);
    EXPECT_NEAR(clearance(on_lattice, origin, 1.25), 0.625, 1e-9);
    expect_clearest(on_lattice, start, 1.25);
}

TEST(ClearGridOrigin, ScatteredCoordinatesAndAFlatAFloatStepThick) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(-40.0, 60.0);
    std::vector<double> coordinates;
    for (int k = 0; k < 300; ++k) coordinates.push_back(uniform(random));
    for (int k = 0; k < 20; ++k) coordinates.push_back(k % 2 ? std::nextafter(-40.5, 0.0) : -40.5);
    expect_clearest(coordinates, -50.5, 1.25);
    EXPECT_GT(clearance(coordinates, fabvdb::surface::clear_grid_origin(coordinates, -50.5, 1.25), 1.25), 1e-3);
}

TEST(ClearGridOrigin, NoCoordinatesKeepTheStart) {
    EXPECT_EQ(fabvdb::surface::clear_grid_origin({}, 3.5, 1.0), 3.5);
}

TEST(ClearGridOrigin, BadStepOrCoordinateIsRefused) {
    for (const double step : {0.0, -1.0, double(NAN)}) {
        try {
            fabvdb::surface::clear_grid_origin({1.0}, 0.0, step);
            FAIL() << "expected an invalid-argument error for step " << step;
        } catch (const fabvdb::Error& e) {
            EXPECT_EQ(e.status(), FABVDB_ERR_INVALID_ARGUMENT);
        }
    }
    try {
        fabvdb::surface::clear_grid_origin({1.0, INFINITY}, 0.0, 1.0);
        FAIL() << "expected an invalid-argument error";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_INVALID_ARGUMENT);
    }
}

}  // namespace
