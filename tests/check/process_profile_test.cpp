// process_profile: the three built-in profiles hold the values docs/check.md
// cites, a JSON profile overrides its base key by key, and every defect of a
// name or a file is the documented status with a message naming the source.
#include "check/process_profile.h"

#include <gtest/gtest.h>

#include <functional>

#include "core/error.h"
#include "support/temp_files.h"

namespace fabvdb::check {
namespace {

Error failure(const std::function<void()>& run) {
    try {
        run();
    } catch (const Error& e) {
        return e;
    }
    ADD_FAILURE() << "no error";
    return Error(FABVDB_OK, "");
}

TEST(ProcessProfile, BuiltInValuesAreTheCitedOnes) {
    const ProcessProfile sla = builtin_profile("sla");
    EXPECT_EQ(sla.min_wall, 0.5);
    EXPECT_EQ(sla.min_pin, 0.5);
    EXPECT_EQ(sla.min_hole, 0.5);
    EXPECT_EQ(sla.escape_hole, 3.5);
    EXPECT_EQ(sla.overhang_degrees, 45.0);
    EXPECT_TRUE(sla.cups);
    const ProcessProfile powder = builtin_profile("powder");
    EXPECT_EQ(powder.min_wall, 0.7);
    EXPECT_EQ(powder.min_pin, 1.0);
    EXPECT_EQ(powder.min_hole, 1.5);
    EXPECT_EQ(powder.escape_hole, 3.5);
    EXPECT_EQ(powder.overhang_degrees, 90.0);
    EXPECT_FALSE(powder.cups);
    const ProcessProfile fdm = builtin_profile("fdm");
    EXPECT_EQ(fdm.min_wall, 0.8);
    EXPECT_EQ(fdm.min_pin, 3.0);
    EXPECT_EQ(fdm.min_feature, 2.0);
    EXPECT_EQ(fdm.min_hole, 2.0);
    EXPECT_EQ(fdm.escape_hole, 0.0);
    EXPECT_EQ(fdm.overhang_degrees, 45.0);
    EXPECT_FALSE(fdm.cups);
    for (const char* name : {"sla", "powder", "fdm"}) {
        EXPECT_EQ(builtin_profile(name).name, name);
        EXPECT_EQ(read_profile(name).min_wall, builtin_profile(name).min_wall);
        EXPECT_EQ(profile_json(builtin_profile(name))["name"], name);
        EXPECT_EQ(profile_json(builtin_profile(name))["cups"], builtin_profile(name).cups);
    }
}

TEST(ProcessProfile, JsonOverridesItsBase) {
    const ProcessProfile p = profile_from_json(R"({"base": "powder", "name": "farm MJF", "min_wall": 0.9,
                                                  "margin_fraction": 0.1})",
                                               "farm.json");
    EXPECT_EQ(p.name, "farm MJF");
    EXPECT_EQ(p.min_wall, 0.9);
    EXPECT_EQ(p.margin_fraction, 0.1);
    EXPECT_EQ(p.min_hole, 1.5);  // the base's
    EXPECT_FALSE(p.cups);        // the base's
    EXPECT_TRUE(profile_from_json(R"({"base": "powder", "cups": true})", "vat.json").cups);
    EXPECT_FALSE(profile_from_json(R"({"cups": false})", "novat.json").cups);
    EXPECT_EQ(profile_from_json("{}", "plain.json").name, "plain.json");
    EXPECT_EQ(profile_from_json("{}", "plain.json").min_wall, 0.5);  // base sla

    test::TempDir dir;
    const std::string path = test::write_bytes(dir.file("own.json"), R"({"min_hole": 0.8})");
    EXPECT_EQ(read_profile(path).min_hole, 0.8);
}

TEST(ProcessProfile, DefectsAreNamed) {
    const Error unknown = failure([] { builtin_profile("laser"); });
    EXPECT_EQ(unknown.status(), FABVDB_ERR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(unknown.what()).find("laser"), std::string::npos);
    EXPECT_EQ(failure([] { read_profile("/no/such/profile.json"); }).status(), FABVDB_ERR_IO);
    for (const char* text : {"not json", "[1, 2]", R"({"min_wall": -1})", R"({"min_wall": "thin"})",
                             R"({"base": "wood"})", R"({"min_walls": 1})", R"({"overhang_degrees": 120})",
                             R"({"name": 3})", R"({"cups": 1})", R"({"cups": "yes"})"}) {
        const Error e = failure([&] { profile_from_json(text, "bad.json"); });
        EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT) << text;
        EXPECT_NE(std::string(e.what()).find("bad.json"), std::string::npos) << text;
    }
}

}  // namespace
}  // namespace fabvdb::check
