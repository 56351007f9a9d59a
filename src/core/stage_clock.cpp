//! StageClock: see stage_clock.h.
#include "core/stage_clock.h"

namespace fabvdb {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

StageClock::StageClock(std::map<std::string, double>& seconds)
    : seconds_(seconds), start_(std::chrono::steady_clock::now()), since_(start_) {}

double StageClock::lap(const std::string& stage) {
    const auto now = std::chrono::steady_clock::now();
    const double lap = std::chrono::duration<double>(now - since_).count();
    seconds_[stage] += lap;
    since_ = now;
    return lap;
}

void StageClock::add_laps(const std::map<std::string, double>& stages) {
    for (const auto& [stage, seconds] : stages) seconds_[stage] += seconds;
    since_ = std::chrono::steady_clock::now();
}

double StageClock::total() const { return seconds_since(start_); }

}  // namespace fabvdb
