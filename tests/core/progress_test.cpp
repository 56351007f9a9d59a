// Tests of Progress (stages, throttling, cancellation) and AtomicOutput (no
// partial files).
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/atomic_output.h"
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

TEST(AtomicOutput, NoFileUnlessCommitted) {
    const auto dir = std::filesystem::temp_directory_path() / "fabvdb_atomic_test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string target = (dir / "out.txt").string();
    {
        fabvdb::AtomicOutput out(target);
        std::ofstream(out.temp_path()) << "half";
    }
    EXPECT_FALSE(std::filesystem::exists(target));
    EXPECT_TRUE(std::filesystem::is_empty(dir));
    fabvdb::write_text_file_atomically(target, "whole");
    std::ifstream in(target);
    std::string text;
    in >> text;
    EXPECT_EQ(text, "whole");
    EXPECT_THROW(fabvdb::write_text_file_atomically((dir / "missing" / "x.txt").string(), "x"), fabvdb::Error);
    std::filesystem::remove_all(dir);
}

}  // namespace
