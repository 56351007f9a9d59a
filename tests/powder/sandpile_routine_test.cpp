//! operator_routine: the first orientation, then turns − 1 draws from the set
//! by a 64-bit Mersenne twister taken modulo the set's size. The draws are
//! checked against the published MT19937-64 outputs for seed 5489
//! (Matsumoto–Nishimura's reference mt19937-64.c), so the routine is the same
//! on every machine; a long routine uses every orientation about equally; a
//! single turn needs no set; no turns or an empty set are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "core/error.h"
#include "powder/sandpile_routine.h"

namespace {

using fabvdb::Vec3;

const Vec3 down{0, 0, -1};
const std::vector<Vec3> six_axes{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

void expect_invalid(const std::vector<Vec3>& set, int turns, const std::string& text) {
    try {
        fabvdb::powder::operator_routine(down, set, turns, 1);
        ADD_FAILURE() << "no exception";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_INVALID_ARGUMENT);
        EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
}

}  // namespace

TEST(OperatorRoutine, DrawsAreTheReferenceTwisterModuloTheSetSize) {
    // MT19937-64 seeded with 5489: 14514284786278117030, 4620546740167642908,
    // 13109570281517897720; modulo 6: 4, 0, 2; modulo 7: 1, 1, 1.
    EXPECT_EQ(fabvdb::powder::operator_routine(down, six_axes, 4, 5489),
              (std::vector<Vec3>{down, six_axes[4], six_axes[0], six_axes[2]}));

    std::vector<Vec3> seven = six_axes;
    seven.push_back({0.6, 0.8, 0});
    const std::vector<Vec3> other = fabvdb::powder::operator_routine(down, seven, 4, 5489);
    EXPECT_EQ(other, (std::vector<Vec3>{down, seven[1], seven[1], seven[1]}));
}

TEST(OperatorRoutine, LongRoutineUsesEveryOrientationAboutEqually) {
    const std::vector<Vec3> routine = fabvdb::powder::operator_routine({0, 0, 1}, six_axes, 6001, 42);
    ASSERT_EQ(routine.size(), 6001u);
    EXPECT_EQ(routine[0], (Vec3{0, 0, 1}));
    for (const Vec3& axis : six_axes) {
        const long count = std::count(routine.begin() + 1, routine.end(), axis);
        EXPECT_NEAR(double(count), 1000.0, 150.0) << axis[0] << " " << axis[1] << " " << axis[2];  // σ ≈ 29
    }
    EXPECT_NE(fabvdb::powder::operator_routine({0, 0, 1}, six_axes, 50, 43),
              std::vector<Vec3>(routine.begin(), routine.begin() + 50));
}

TEST(OperatorRoutine, OneTurnIsTheFirstOrientationAlone) {
    EXPECT_EQ(fabvdb::powder::operator_routine(down, {}, 1, 7), std::vector<Vec3>{down});
}

TEST(OperatorRoutine, RefusesNoTurnsAndAnEmptySet) {
    expect_invalid(six_axes, 0, "at least one turn");
    expect_invalid(six_axes, -3, "at least one turn");
    expect_invalid({}, 2, "orientation set is empty");
}
