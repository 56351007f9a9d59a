//! StageClock: the wall time of the consecutive stages of an operation, for
//! the `timings` object of its report (docs/reports.md). lap(name) adds the
//! time since the previous lap (or since the clock was made) to `name` in the
//! map it writes to, so a stage run several times adds up. total() is the time
//! since the clock was made; add_laps takes the stages of a step timed by its
//! own clock instead of a lap. Costs one steady_clock read per lap; not
//! thread-safe (one clock per operation). seconds_since times a single span
//! that has no stages.
#pragma once

#include <chrono>
#include <map>
#include <string>

namespace fabvdb {

//! Seconds from `start` to now on the steady clock.
double seconds_since(std::chrono::steady_clock::time_point start);

class StageClock {
public:
    //! Writes into `seconds` (stage name → seconds), which must outlive the clock.
    explicit StageClock(std::map<std::string, double>& seconds);
    //! Adds the time since the previous lap to `stage`; returns it (s).
    double lap(const std::string& stage);
    //! Adds stages another clock timed since the previous lap (a step with
    //! a report of its own) and starts the next lap now.
    void add_laps(const std::map<std::string, double>& stages);
    //! Seconds since the clock was made.
    double total() const;

private:
    std::map<std::string, double>& seconds_;
    std::chrono::steady_clock::time_point start_, since_;
};

}  // namespace fabvdb
