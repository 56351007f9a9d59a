// settle_matrix on hand-built transfer matrices: a chain ending on one floor,
// splits and merges whose limits are worked by hand, a patch keeping part of
// its powder, heights along a sideways gravity; the `max_entries` largest
// and `min_weight` cuts, renormalised; and on a random acyclic T, the exact
// limit of T^k (by dense powers) with no cuts, row-stochastic rows onto
// fixed points with the default cuts.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "powder/settle_matrix.h"

namespace {

using fabvdb::Vec3;
using fabvdb::powder::CavityPatches;
using fabvdb::powder::settle_matrix;
using fabvdb::powder::StochasticMatrix;
using Row = std::map<uint32_t, double>;

//! A matrix from its rows (column → weight).
StochasticMatrix matrix(const std::vector<Row>& rows) {
    StochasticMatrix m;
    for (const Row& row : rows) {
        for (const auto& [column, weight] : row) {
            m.column.push_back(column);
            m.weight.push_back(float(weight));
        }
        m.row_start.push_back(uint32_t(m.column.size()));
    }
    return m;
}

//! Patches with only the centroids settle_matrix reads.
CavityPatches at_heights(const std::vector<Vec3>& centroids) {
    CavityPatches patches;
    patches.centroid = centroids;
    patches.area.assign(centroids.size(), 1.0);
    return patches;
}

Row row(const StochasticMatrix& m, size_t i) {
    Row r;
    for (uint32_t e = m.row_start[i]; e < m.row_start[i + 1]; ++e) r[m.column[e]] += m.weight[e];
    return r;
}

void expect_row(const StochasticMatrix& m, size_t i, const Row& expected, double tolerance = 1e-6) {
    const Row actual = row(m, i);
    ASSERT_EQ(actual.size(), expected.size()) << "row " << i;
    for (const auto& [column, weight] : expected) {
        ASSERT_TRUE(actual.count(column)) << "row " << i << " lacks column " << column;
        EXPECT_NEAR(actual.at(column), weight, tolerance) << "row " << i << " column " << column;
    }
}

bool fixed_point(const StochasticMatrix& t, uint32_t i) {
    return t.row_start[i + 1] - t.row_start[i] == 1 && t.column[t.row_start[i]] == i;
}

}  // namespace

TEST(SettleMatrix, AChainEndsOnItsFloor) {
    // Heights: patch 0 at 3 → 2 at 2 → 3 at 1 → 1 at 0, a floor.
    const auto patches = at_heights({{0, 0, 3}, {0, 0, 0}, {0, 0, 2}, {0, 0, 1}});
    const auto settle = settle_matrix(matrix({{{2, 1}}, {{1, 1}}, {{3, 1}}, {{1, 1}}}), patches, {0, 0, -1});
    ASSERT_EQ(settle.rows(), 4u);
    for (size_t i = 0; i < 4; ++i) expect_row(settle, i, {{1, 1.0}});
}

TEST(SettleMatrix, SplitsAndMergesMultiply) {
    // Floors 0 (z 0) and 1 (z 0.5); wall 2 (z 2) sends 1/4 to 0 and 3/4 to 1;
    // wall 3 (z 3) half to wall 2, half to floor 1; overhang 4 (z 5) 0.6 to 3, 0.4 to 2.
    const auto patches = at_heights({{0, 0, 0}, {0, 0, 0.5}, {0, 0, 2}, {0, 0, 3}, {0, 0, 5}});
    const auto transfer = matrix({{{0, 1}}, {{1, 1}}, {{0, 0.25}, {1, 0.75}}, {{2, 0.5}, {1, 0.5}}, {{3, 0.6}, {2, 0.4}}});
    const auto settle = settle_matrix(transfer, patches, {0, 0, -1});
    expect_row(settle, 0, {{0, 1.0}});
    expect_row(settle, 1, {{1, 1.0}});
    expect_row(settle, 2, {{0, 0.25}, {1, 0.75}});
    // 0.5·(1/4, 3/4) + 0.5·(0, 1)
    expect_row(settle, 3, {{0, 0.125}, {1, 0.875}});
    // 0.6·row 3 + 0.4·row 2
    expect_row(settle, 4, {{0, 0.6 * 0.125 + 0.4 * 0.25}, {1, 0.6 * 0.875 + 0.4 * 0.75}});
}

TEST(SettleMatrix, PowderKeptOnAPatchMovesOnInTheLimit) {
    // Patch 1 keeps half of its powder each step: T^k leaves 2^-k on it.
    const auto patches = at_heights({{0, 0, 0}, {0, 0, 1}});
    const auto settle = settle_matrix(matrix({{{0, 1}}, {{1, 0.5}, {0, 0.5}}}), patches, {0, 0, -1});
    expect_row(settle, 1, {{0, 1.0}});
}

TEST(SettleMatrix, HeightsAreAlongGravity) {
    // Along +x gravity, x = 0 is highest: 0 → 1 → 2 (fixed), and 3 → 2 and 1 half each.
    const auto patches = at_heights({{0, 5, 9}, {1, -5, 0}, {2, 0, 20}, {0.5, 0, -7}});
    const auto transfer = matrix({{{1, 1}}, {{2, 1}}, {{2, 1}}, {{1, 0.5}, {2, 0.5}}});
    for (const Vec3& gravity : {Vec3{1, 0, 0}, Vec3{9.81, 0, 0}}) {
        const auto settle = settle_matrix(transfer, patches, gravity);
        for (size_t i = 0; i < 4; ++i) expect_row(settle, i, {{2, 1.0}});
    }
}

TEST(SettleMatrix, KeepsTheLargestDestinationsRenormalised) {
    // Patch 10 (z 20) spreads over ten floors (z 0..9) with distinct weights.
    const double w[10] = {0.28, 0.2, 0.15, 0.1, 0.08, 0.06, 0.05, 0.04, 0.025, 0.015};
    std::vector<Vec3> centroids;
    std::vector<Row> rows;
    Row spread;
    for (uint32_t i = 0; i < 10; ++i) {
        centroids.push_back({0, 0, double(i)});
        rows.push_back({{i, 1.0}});
        spread[i] = w[i];
    }
    centroids.push_back({0, 0, 20});
    rows.push_back(spread);
    const auto transfer = matrix(rows);
    const auto patches = at_heights(centroids);

    // Default: 8 entries, the last two go; the rest sum to 0.96.
    Row eight;
    for (uint32_t i = 0; i < 8; ++i) eight[i] = w[i] / 0.96;
    expect_row(settle_matrix(transfer, patches, {0, 0, -1}), 10, eight);
    Row three{{0, 0.28 / 0.63}, {1, 0.2 / 0.63}, {2, 0.15 / 0.63}};
    expect_row(settle_matrix(transfer, patches, {0, 0, -1}, 3), 10, three);
    // A weight floor of 0.07 cuts from 0.06 down (the first 5 sum to 0.81).
    Row five;
    for (uint32_t i = 0; i < 5; ++i) five[i] = w[i] / 0.81;
    expect_row(settle_matrix(transfer, patches, {0, 0, -1}, 8, 0.07f), 10, five);
    // However high the floor, the largest destination stays.
    expect_row(settle_matrix(transfer, patches, {0, 0, -1}, 8, 0.9f), 10, {{0, 1.0}});
    // No cuts: all ten, as they were.
    expect_row(settle_matrix(transfer, patches, {0, 0, -1}, 10, 0.0f), 10, spread);
}

TEST(SettleMatrix, TinyShareIsDroppedUnderTheDefaultFloor) {
    const auto patches = at_heights({{0, 0, 0}, {0, 0, 1}, {0, 0, 2}});
    const auto transfer = matrix({{{0, 1}}, {{1, 1}}, {{0, 0.9995}, {1, 0.0005}}});
    expect_row(settle_matrix(transfer, patches, {0, 0, -1}), 2, {{0, 1.0}});
    expect_row(settle_matrix(transfer, patches, {0, 0, -1}, 8, 1e-4f), 2, {{0, 0.9995}, {1, 0.0005}});
}

TEST(SettleMatrix, NoPatchesNoRows) {
    const auto settle = settle_matrix(StochasticMatrix{}, CavityPatches{}, {0, 0, -1});
    EXPECT_EQ(settle.rows(), 0u);
    EXPECT_TRUE(settle.column.empty());
}

TEST(SettleMatrix, IsTheLimitOfTransferPowersOnARandomAcyclicMatrix) {
    // 60 patches at random heights; a fifth are fixed, the others send powder
    // to up to four lower patches (the lowest is always fixed).
    const size_t n = 60;
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Vec3> centroids(n);
    for (Vec3& c : centroids) c = {unit(random), unit(random), 100.0 * unit(random)};
    std::vector<Row> rows(n);
    for (uint32_t i = 0; i < n; ++i) {
        std::vector<uint32_t> lower;
        for (uint32_t j = 0; j < n; ++j)
            if (centroids[j][2] < centroids[i][2]) lower.push_back(j);
        if (lower.empty() || unit(random) < 0.2) {
            rows[i] = {{i, 1.0}};
            continue;
        }
        const int count = 1 + int(unit(random) * 4);
        double total = 0;
        for (int k = 0; k < count; ++k) {
            const double w = 0.05 + unit(random);
            rows[i][lower[size_t(unit(random) * double(lower.size()))]] += w;
            total += w;
        }
        for (auto& entry : rows[i]) entry.second /= total;
    }
    const StochasticMatrix transfer = matrix(rows);
    const CavityPatches patches = at_heights(centroids);

    // T^k by dense squaring: every path is at most n steps, so T^64 is the limit.
    std::vector<std::vector<double>> power(n, std::vector<double>(n, 0.0));
    for (size_t i = 0; i < n; ++i)
        for (uint32_t e = transfer.row_start[i]; e < transfer.row_start[i + 1]; ++e)
            power[i][transfer.column[e]] += transfer.weight[e];
    for (int square = 0; square < 6; ++square) {
        std::vector<std::vector<double>> next(n, std::vector<double>(n, 0.0));
        for (size_t i = 0; i < n; ++i)
            for (size_t k = 0; k < n; ++k)
                if (power[i][k] != 0.0)
                    for (size_t j = 0; j < n; ++j) next[i][j] += power[i][k] * power[k][j];
        power = next;
    }
    const StochasticMatrix exact = settle_matrix(transfer, patches, {0, 0, -1}, n, 0.0f);
    ASSERT_EQ(exact.rows(), n);
    for (size_t i = 0; i < n; ++i) {
        const Row actual = row(exact, i);
        for (uint32_t j = 0; j < n; ++j)
            EXPECT_NEAR(actual.count(j) ? actual.at(j) : 0.0, power[i][j], 1e-5) << "row " << i << " column " << j;
    }

    // With the default cuts: rows sum to 1, hold at most 8 entries, all fixed points of T.
    const StochasticMatrix settle = settle_matrix(transfer, patches, {0, 0, -1});
    ASSERT_EQ(settle.rows(), n);
    EXPECT_EQ(settle.row_start.front(), 0u);
    for (size_t i = 0; i < n; ++i) {
        double sum = 0;
        for (uint32_t e = settle.row_start[i]; e < settle.row_start[i + 1]; ++e) {
            sum += settle.weight[e];
            EXPECT_GT(settle.weight[e], 0.0f);
            EXPECT_TRUE(fixed_point(transfer, settle.column[e])) << "row " << i << " to " << settle.column[e];
        }
        EXPECT_NEAR(sum, 1.0, 1e-5) << "row " << i;
        EXPECT_LE(settle.row_start[i + 1] - settle.row_start[i], 8u);
        EXPECT_GE(settle.row_start[i + 1] - settle.row_start[i], 1u);
    }
}
