//! decomposition_check FILE.json — runs the independent checks of
//! tests/support/decomposition_checks (parts disjoint and covering, each part
//! connected, M⁺ and M⁻ of each part connected, overhang energies measured
//! again) on a decomposition.json written by someone else: the studio's
//! browser test calls it on what the page saved. Exit 0 when every check
//! passes, 1 otherwise (gtest prints which).
#include <gtest/gtest.h>

#include <cstdio>

#include "support/decomposition_checks.h"

namespace {

std::string checked_path;

TEST(SavedDecomposition, PassesTheIndependentChecks) {
    const nlohmann::json document = fabvdb::test::read_decomposition(checked_path);
    const std::vector<double> areas = fabvdb::test::check_decomposition(document);
    EXPECT_GE(areas.size(), 1u);
    for (double area : areas) EXPECT_GT(area, 0.0);
}

}  // namespace

int main(int argc, char** argv) {
    testing::InitGoogleTest(&argc, argv);
    if (argc != 2) {
        fprintf(stderr, "usage: decomposition_check FILE.json\n");
        return 2;
    }
    checked_path = argv[1];
    return RUN_ALL_TESTS();
}
