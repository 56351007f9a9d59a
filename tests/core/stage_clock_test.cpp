// StageClock: each lap adds the time since the previous lap (or since the
// clock was made) to its stage, repeated stages add up, laps sum to at most the
// total, the map passed in is the one written, stages added from another clock
// stand in for the time since the previous lap, and seconds_since measures a
// single span.
#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <string>
#include <thread>

#include "core/stage_clock.h"

namespace {

using fabvdb::StageClock;
using namespace std::chrono_literals;

TEST(StageClock, LapMeasuresTheTimeSinceThePreviousLap) {
    std::map<std::string, double> seconds;
    const auto before = std::chrono::steady_clock::now();
    StageClock clock(seconds);
    EXPECT_TRUE(seconds.empty());
    std::this_thread::sleep_for(30ms);
    const double first = clock.lap("read");
    std::this_thread::sleep_for(10ms);
    const double second = clock.lap("voxelize");
    const double outer = std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count();
    // Sleeps last at least as long as asked; both laps fit in the outer span.
    EXPECT_GE(first, 0.030);
    EXPECT_GE(second, 0.010);
    EXPECT_LE(first + second, outer);
    ASSERT_EQ(seconds.size(), 2u);
    EXPECT_EQ(seconds.at("read"), first);
    EXPECT_EQ(seconds.at("voxelize"), second);
}

TEST(StageClock, ARepeatedStageAddsUp) {
    std::map<std::string, double> seconds;
    StageClock clock(seconds);
    std::this_thread::sleep_for(5ms);
    const double a = clock.lap("filter");
    std::this_thread::sleep_for(5ms);
    const double b = clock.lap("mesh");
    std::this_thread::sleep_for(5ms);
    const double c = clock.lap("filter");
    ASSERT_EQ(seconds.size(), 2u);
    EXPECT_DOUBLE_EQ(seconds.at("filter"), a + c);
    EXPECT_EQ(seconds.at("mesh"), b);
    EXPECT_GE(seconds.at("filter"), 0.010);
}

TEST(StageClock, TotalCoversAllLapsAndKeepsRunning) {
    std::map<std::string, double> seconds;
    StageClock clock(seconds);
    std::this_thread::sleep_for(5ms);
    const double a = clock.lap("one");
    std::this_thread::sleep_for(5ms);
    const double b = clock.lap("two");
    const double total = clock.total();
    EXPECT_GE(total, a + b);
    // total() does not lap: nothing new is written.
    EXPECT_EQ(seconds.size(), 2u);
    std::this_thread::sleep_for(5ms);
    EXPECT_GE(clock.total(), total + 0.005);
    // The next lap includes the time spent in and after total().
    const double c = clock.lap("three");
    EXPECT_GE(c, 0.005);
}

TEST(StageClock, AddsToTimesAlreadyInTheMap) {
    std::map<std::string, double> seconds{{"read", 100.0}, {"other", 7.0}};
    StageClock clock(seconds);
    const double lap = clock.lap("read");
    EXPECT_GE(lap, 0.0);
    EXPECT_DOUBLE_EQ(seconds.at("read"), 100.0 + lap);
    EXPECT_EQ(seconds.at("other"), 7.0);
}

TEST(StageClock, AddedLapsCountInPlaceOfTheTimeSinceThePreviousLap) {
    std::map<std::string, double> seconds;
    StageClock clock(seconds);
    std::this_thread::sleep_for(30ms);  // a step that times itself
    clock.add_laps({{"plan", 0.25}, {"read", 0.5}});
    clock.add_laps({{"plan", 0.25}});
    const double lap = clock.lap("drill");
    EXPECT_DOUBLE_EQ(seconds.at("plan"), 0.5);
    EXPECT_DOUBLE_EQ(seconds.at("read"), 0.5);
    // The drill's lap starts at the last add_laps, not before the step.
    EXPECT_LT(lap, 0.030);
    EXPECT_EQ(seconds.at("drill"), lap);
}

TEST(StageClock, AnImmediateLapIsTinyButNotNegative) {
    std::map<std::string, double> seconds;
    StageClock clock(seconds);
    const double lap = clock.lap("nothing");
    EXPECT_GE(lap, 0.0);
    EXPECT_LT(lap, 0.5);
    EXPECT_EQ(seconds.at("nothing"), lap);
}

TEST(StageClock, SecondsSinceSpansFromTheGivenTimeToNow) {
    const auto before = std::chrono::steady_clock::now();
    std::this_thread::sleep_for(20ms);
    const double span = fabvdb::seconds_since(before);
    const double outer = std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count();
    EXPECT_GE(span, 0.020);
    EXPECT_LE(span, outer);
}

}  // namespace
