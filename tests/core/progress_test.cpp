// Tests of Progress (stages, throttling, cancellation).
#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/progress.h"

namespace {

struct Calls {
    std::vector<std::string> stages;
    int count = 0;
    int cancel_after = -1;
};

int record(void* user, const char* stage, double) {
    auto* calls = static_cast<Calls*>(user);
    calls->stages.push_back(stage);
    ++calls->count;
    return calls->cancel_after >= 0 && calls->count >= calls->cancel_after;
}

TEST(Progress, ReportsStagesAndThrottles) {
    Calls calls;
    std::atomic<bool> flag{false};
    fabvdb::Progress progress(record, &calls, &flag);
    progress.stage("one");
    for (int i = 0; i <= 100000; ++i) progress.update(i / 100000.0);
    progress.stage("two");
    EXPECT_EQ(calls.stages.front(), "one");
    EXPECT_EQ(calls.stages.back(), "two");
    EXPECT_LT(calls.count, 1000);  // throttled to about every 0.2 %
    EXPECT_GT(calls.count, 100);
}

TEST(Progress, CallbackCancels) {
    Calls calls;
    calls.cancel_after = 3;
    fabvdb::Progress progress(record, &calls, nullptr);
    progress.stage("work");
    try {
        for (int i = 0; i <= 100; ++i) progress.update(i / 100.0);
        FAIL() << "not cancelled";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
    EXPECT_TRUE(progress.cancelled());
}

TEST(Progress, FlagCancels) {
    std::atomic<bool> flag{false};
    fabvdb::Progress progress(nullptr, nullptr, &flag);
    EXPECT_NO_THROW(progress.check());
    flag = true;
    EXPECT_THROW(progress.check(), fabvdb::Error);
}

}  // namespace
