//! guess_units: the longest side against the readings of other units.
#include "check/units_guess.h"

#include <algorithm>

namespace fabvdb::check {

namespace {

constexpr double kSmallest = 10.0;   // mm: under this a part is suspiciously small
constexpr double kLargest = 1000.0;  // mm: over this suspiciously large

}  // namespace

UnitsGuess guess_units(const BoundingBox& box) {
    UnitsGuess guess;
    for (int k = 0; k < 3; ++k) guess.longest = std::max(guess.longest, box.max[k] - box.min[k]);
    guess.suspicious = guess.longest < kSmallest || guess.longest > kLargest;
    if (!guess.suspicious || !(guess.longest > 0.0)) return guess;
    const UnitsReading small[] = {{"m", 1000.0, 0.0}, {"in", 25.4, 0.0}, {"cm", 10.0, 0.0}};
    const UnitsReading large[] = {{"um", 0.001, 0.0}};
    const bool is_small = guess.longest < kSmallest;
    for (const UnitsReading& candidate : is_small ? std::vector<UnitsReading>(std::begin(small), std::end(small))
                                                  : std::vector<UnitsReading>(std::begin(large), std::end(large))) {
        UnitsReading reading = candidate;
        reading.longest = guess.longest * reading.scale;
        if (reading.longest >= kSmallest && reading.longest <= kLargest) guess.readings.push_back(reading);
    }
    return guess;
}

}  // namespace fabvdb::check
