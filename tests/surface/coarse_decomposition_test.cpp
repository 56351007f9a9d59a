//! coarse_decomposition: the part count it starts from (two for a hollow
//! shell, two per piece of a surface of several pieces, one per piece when
//! cast solid, at least the requested count), when it stops (Σ E_P below γ,
//! the part cap, or fewer seeds than asked), that it keeps the attempt of
//! least energy, one log record per attempt, and that every triangle ends in
//! an edge-connected part that lies on a single piece. parting_lines gives
//! each part the direction asked for and the surface of exactly its prisms.
//! Counts, pieces and minima are worked out here by hand or by own flood fill.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <limits>
#include <set>

#include "core/error.h"
#include "shell_shapes.h"
#include "support/hemisphere_parts.h"
#include "surface/coarse_decomposition.h"
#include "surface/moldability_terms.h"

namespace {

using fabvdb::surface::Decomposition;
using fabvdb::surface::DecompositionOptions;
using fabvdb::surface::MoldabilityTerms;
using fabvdb::surface::Shell;

struct DecompositionRun {
    Decomposition decomposition;
    nlohmann::json log = nlohmann::json::array();
};

DecompositionRun decompose(const Shell& shell, const DecompositionOptions& options) {
    fabvdb::Progress progress;
    const MoldabilityTerms terms = fabvdb::surface::compute_moldability_terms(shell, 0.0, progress);
    DecompositionRun run;
    run.decomposition = fabvdb::surface::coarse_decomposition(shell, terms, options, run.log, progress);
    return run;
}

Shell sphere_shell(int levels) {
    return fabvdb::test::shell_of(fabvdb::test::make_sphere({0, 0, 0}, 20.0, levels), 1.0);
}

//! Two spheres of radius 10 apart along x: the first 20·4^levels triangles
//! are the first sphere's.
Shell two_spheres_shell(int levels) {
    return fabvdb::test::shell_of(fabvdb::test::merged(fabvdb::test::make_sphere({0, 0, 0}, 10.0, levels),
                                                       fabvdb::test::make_sphere({30, 0, 0}, 10.0, levels)),
                                  1.0);
}

std::vector<int> logged_part_counts(const nlohmann::json& log) {
    std::vector<int> counts;
    for (const auto& record : log) counts.push_back(record.at("parts").get<int>());
    return counts;
}

//! Every triangle has a part in [0, part count), each part is one
//! edge-connected piece, and Σ E_P is the sum of the parts' energies.
void expect_valid(const Shell& shell, const Decomposition& decomposition) {
    const int parts = int(decomposition.parts.size());
    ASSERT_EQ(decomposition.part_of_triangle.size(), shell.triangle_count());
    for (int part : decomposition.part_of_triangle) {
        EXPECT_GE(part, 0);
        EXPECT_LT(part, parts);
    }
    double sum = 0;
    for (int p = 0; p < parts; ++p) {
        EXPECT_EQ(fabvdb::test::connected_pieces(shell, decomposition.part_of_triangle, p), 1) << "part " << p;
        sum += decomposition.parts[p].energy.total;
    }
    EXPECT_DOUBLE_EQ(decomposition.total_energy(), sum);
}

}  // namespace

TEST(CoarseDecomposition, HollowSphereStartsFromTwoPartsAndStopsUnderGamma) {
    const Shell shell = sphere_shell(2);
    DecompositionOptions options;
    options.gamma = 1e9;  // any energy is under it: the first attempt ends the loop
    const DecompositionRun run = decompose(shell, options);
    ASSERT_EQ(run.log.size(), 1u);
    EXPECT_EQ(logged_part_counts(run.log), std::vector<int>{2});
    ASSERT_EQ(run.decomposition.parts.size(), 2u);
    expect_valid(shell, run.decomposition);
    const auto& record = run.log[0];
    const int iterations = record.at("iterations").get<int>();
    EXPECT_GE(iterations, 1);
    EXPECT_LE(iterations, options.max_iterations);
    EXPECT_EQ(record.at("region_cost_per_iteration").size(), size_t(iterations));
    EXPECT_DOUBLE_EQ(record.at("moldability_energy").get<double>(), run.decomposition.total_energy());
    EXPECT_GE(record.at("timings").at("per_iteration").get<double>(), 0.0);
    EXPECT_GE(record.at("timings").at("parting_line").get<double>(), 0.0);
}

TEST(CoarseDecomposition, UnreachableGammaTriesUpToTheCapAndKeepsTheLeastEnergy) {
    const Shell shell = sphere_shell(2);
    DecompositionOptions options;
    options.gamma = 0;  // E_P ≥ 0: never under it
    options.max_parts = 4;
    const DecompositionRun run = decompose(shell, options);
    EXPECT_EQ(logged_part_counts(run.log), (std::vector<int>{2, 3, 4}));
    double least = 1e300;
    for (const auto& record : run.log) least = std::min(least, record.at("moldability_energy").get<double>());
    EXPECT_DOUBLE_EQ(run.decomposition.total_energy(), least);
    expect_valid(shell, run.decomposition);
}

TEST(CoarseDecomposition, UndercutsOverTheBoundAddPartsAndKeepTheShallowest) {
    // No decomposition meets a negative bound: past the first attempt under γ
    // (the first: γ is huge) depth_attempts more are made, and the shallowest
    // is kept (the first on a tie).
    const Shell shell = fabvdb::test::shell_of(fabvdb::test::make_torus({0, 0, 0}, 20.0, 6.0, 24, 12), 1.0);
    DecompositionOptions options;
    options.gamma = 1e9;
    options.max_undercut_depth = -1;
    options.depth_attempts = 2;
    const DecompositionRun run = decompose(shell, options);
    EXPECT_EQ(logged_part_counts(run.log), (std::vector<int>{2, 3, 4}));
    double least = 1e300;
    for (const auto& record : run.log) least = std::min(least, record.at("undercut_depth").get<double>());
    fabvdb::Progress progress;
    const MoldabilityTerms terms = fabvdb::surface::compute_moldability_terms(shell, 0.0, progress);
    EXPECT_DOUBLE_EQ(fabvdb::surface::deepest_undercut(shell, terms, run.decomposition,
                                                          fabvdb::surface::undercut_reach(shell, options)),
                     least);
    expect_valid(shell, run.decomposition);

    // Without a bound the first attempt under γ ends the search.
    options.max_undercut_depth = std::numeric_limits<double>::infinity();
    EXPECT_EQ(logged_part_counts(decompose(shell, options).log), std::vector<int>{2});
}

TEST(CoarseDecomposition, RequestedCountIsTheOnlyAttempt) {
    const Shell shell = sphere_shell(2);
    DecompositionOptions options;
    options.gamma = 0;
    options.parts = 3;
    const DecompositionRun run = decompose(shell, options);
    EXPECT_EQ(logged_part_counts(run.log), std::vector<int>{3});
    EXPECT_EQ(run.decomposition.parts.size(), 3u);
    expect_valid(shell, run.decomposition);
}

TEST(CoarseDecomposition, AHollowShellAskedForOnePartGetsTwo) {
    // One part would be the whole closed shell, whose core it traps.
    const Shell shell = sphere_shell(2);
    DecompositionOptions options;
    options.gamma = 0;
    options.parts = 1;
    const DecompositionRun run = decompose(shell, options);
    EXPECT_EQ(logged_part_counts(run.log), std::vector<int>{2});
    EXPECT_EQ(run.decomposition.parts.size(), 2u);
    expect_valid(shell, run.decomposition);
}

TEST(CoarseDecomposition, CapBelowTheStartStillMakesOneAttempt) {
    const Shell shell = sphere_shell(2);
    DecompositionOptions options;
    options.gamma = 0;
    options.max_parts = 1;
    const DecompositionRun run = decompose(shell, options);
    EXPECT_EQ(logged_part_counts(run.log), std::vector<int>{2});
}

TEST(CoarseDecomposition, StopsWhenTheBoxRunsOutOfSeeds) {
    // A box has 12 triangles, so 12 elements: counts 2 … 12 get as many seeds,
    // 13 gets 12 and ends the search before the cap of 16.
    const Shell shell = fabvdb::test::shell_of(fabvdb::test::make_box({0, 0, 0}, {10, 10, 10}), 1.0);
    DecompositionOptions options;
    options.gamma = 0;
    const DecompositionRun run = decompose(shell, options);
    std::vector<int> expected;
    for (int count = 2; count <= 12; ++count) expected.push_back(count);
    expected.push_back(12);
    EXPECT_EQ(logged_part_counts(run.log), expected);
}

TEST(CoarseDecomposition, TwoPiecesGetTwoPartsEachWhateverWasAsked) {
    const Shell shell = two_spheres_shell(1);
    const size_t first_sphere = shell.triangle_count() / 2;
    DecompositionOptions options;
    options.gamma = 1e9;
    options.parts = 2;
    const DecompositionRun run = decompose(shell, options);
    EXPECT_EQ(logged_part_counts(run.log), std::vector<int>{4});
    ASSERT_EQ(run.decomposition.parts.size(), 4u);
    expect_valid(shell, run.decomposition);
    // Each part lies on one sphere, and each sphere holds two parts.
    std::set<int> on_first, on_second;
    for (size_t t = 0; t < shell.triangle_count(); ++t)
        (t < first_sphere ? on_first : on_second).insert(run.decomposition.part_of_triangle[t]);
    EXPECT_EQ(on_first.size(), 2u);
    EXPECT_EQ(on_second.size(), 2u);
    for (int part : on_first) EXPECT_EQ(on_second.count(part), 0u) << "part " << part << " on both spheres";
}

TEST(CoarseDecomposition, SolidShellStartsFromOnePartPerPiece) {
    Shell one = sphere_shell(1);
    one.solid = true;
    DecompositionOptions options;
    options.gamma = 1e9;
    const DecompositionRun single = decompose(one, options);
    EXPECT_EQ(logged_part_counts(single.log), std::vector<int>{1});
    for (int part : single.decomposition.part_of_triangle) EXPECT_EQ(part, 0);

    Shell two = two_spheres_shell(1);
    two.solid = true;
    const DecompositionRun pair = decompose(two, options);
    EXPECT_EQ(logged_part_counts(pair.log), std::vector<int>{2});
    // One part per sphere: all of the first sphere's triangles share a part.
    const size_t first_sphere = two.triangle_count() / 2;
    const auto& part_of = pair.decomposition.part_of_triangle;
    for (size_t t = 0; t < two.triangle_count(); ++t)
        EXPECT_EQ(part_of[t] == part_of[0], t < first_sphere) << "triangle " << t;
}

TEST(CoarseDecomposition, CancelledProgressThrowsCancelled) {
    const Shell shell = sphere_shell(1);
    fabvdb::Progress quiet;
    const MoldabilityTerms terms = fabvdb::surface::compute_moldability_terms(shell, 0.0, quiet);
    std::atomic<bool> cancel{true};
    fabvdb::Progress cancelled(nullptr, nullptr, &cancel);
    nlohmann::json log = nlohmann::json::array();
    try {
        fabvdb::surface::coarse_decomposition(shell, terms, {}, log, cancelled);
        FAIL() << "no exception";
    } catch (const fabvdb::Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_CANCELLED);
    }
}

TEST(PartingLines, EachPartGetsItsDirectionAndExactlyItsPrisms) {
    // Hemispheres z ≥ 0 (part 0) and z < 0 (part 1) along +z and −z.
    const Shell shell = sphere_shell(2);
    fabvdb::Progress progress;
    const MoldabilityTerms terms = fabvdb::surface::compute_moldability_terms(shell, 0.0, progress);
    const std::vector<int> part_of = fabvdb::test::hemisphere_parts(shell);
    const size_t upper_count = size_t(std::count(part_of.begin(), part_of.end(), 0));
    const std::vector<int> directions{fabvdb::test::nearest_direction(terms.directions.directions, {0, 0, 1}),
                                      fabvdb::test::nearest_direction(terms.directions.directions, {0, 0, -1})};
    const auto parts = fabvdb::surface::parting_lines(shell, terms, part_of, directions, {});
    ASSERT_EQ(parts.size(), 2u);
    for (int p = 0; p < 2; ++p) {
        EXPECT_EQ(parts[p].direction, directions[p]);
        size_t outer = 0;
        for (size_t i = 0; i < parts[p].surface.size(); ++i) {
            if (parts[p].surface.kind[i] != fabvdb::surface::PartSurface::outer) continue;
            ++outer;
            EXPECT_EQ(part_of[parts[p].surface.source[i]], p);
        }
        EXPECT_EQ(outer, p == 0 ? upper_count : shell.triangle_count() - upper_count);
        EXPECT_EQ(parts[p].upper.size(), parts[p].surface.size());
    }
}
