// A decomposition session on the shared sphere, looking inside what the C API
// test sees from outside: after a smoothing stroke and its undo, S_low and the
// per-axis overlap terms are those of a fresh session (the same pairs, areas
// up to rounding), so the energies the session reports after undo are those of a run
// that never smoothed; a refused smoothing stroke leaves them untouched too;
// a re-run cancelled half-way leaves the session as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <map>
#include <tuple>

#include "core/error.h"
#include "io/mesh_io.h"
#include "surface/decomposition_session.h"

namespace {

using namespace fabvdb;
using namespace fabvdb::surface;

DecomposeSettings settings() {
    DecomposeSettings s;
    s.shell.target_triangles = 1500;
    s.shell.thickness = 0.06;
    s.decomposition.parts = 2;
    s.decomposition.smoothing_iterations = 0;
    return s;
}

Mesh sphere() {
    Progress progress;
    return io::read_mesh(FABVDB_SHARED_DATA "/meshes/sphere.obj", progress);
}

//! The overlaps of every axis as (triangle, partner) -> area.
std::map<std::tuple<size_t, uint32_t, uint32_t>, float> pairs(const MoldabilityTerms& terms) {
    std::map<std::tuple<size_t, uint32_t, uint32_t>, float> all;
    for (size_t a = 0; a < terms.overlaps.size(); ++a) {
        const auto& o = terms.overlaps[a];
        for (uint32_t t = 0; t + 1 < o.offset.size(); ++t)
            for (uint32_t i = o.offset[t]; i < o.offset[t + 1]; ++i) all[{a, t, o.partner[i]}] = o.area[i];
    }
    return all;
}

//! Same pairs; areas equal up to the rounding of measuring a pair from its other side.
void expect_same_pairs(const std::map<std::tuple<size_t, uint32_t, uint32_t>, float>& a,
                       const std::map<std::tuple<size_t, uint32_t, uint32_t>, float>& b) {
    ASSERT_EQ(a.size(), b.size());
    auto j = b.begin();
    for (auto i = a.begin(); i != a.end(); ++i, ++j) {
        ASSERT_EQ(i->first, j->first);
        EXPECT_NEAR(i->second, j->second, 1e-5f * std::max(i->second, 1e-6f));
    }
}

TEST(DecompositionSession, SmoothingUndoneRestoresTheTerms) {
    Progress progress;
    const Mesh input = sphere();
    DecompositionSession session(input, settings(), progress);
    const auto fresh_pairs = pairs(session.terms());
    const std::vector<Vec3> fresh_vertices = session.shell().outer.vertices;
    const double fresh_energy = session.decomposition().total_energy();
    // A stroke at a boundary vertex.
    const Decomposition& d = session.decomposition();
    Vec3 at{0, 0, 0};
    for (size_t t = 0; t < session.shell().triangle_count(); ++t)
        if (d.part_of_triangle[size_t(session.shell().neighbor[t][0])] != d.part_of_triangle[t]) {
            at = session.shell().outer.vertices[session.shell().outer.triangles[t][0]];
            break;
        }
    session.apply(Edit{Edit::smooth, {at}, 0.5, false}, progress);
    EXPECT_NE(session.shell().outer.vertices, fresh_vertices);
    ASSERT_TRUE(session.undo());
    EXPECT_EQ(session.shell().outer.vertices, fresh_vertices);
    expect_same_pairs(pairs(session.terms()), fresh_pairs);
    EXPECT_EQ(session.decomposition().total_energy(), fresh_energy);
    ASSERT_TRUE(session.redo());
    EXPECT_NE(session.shell().outer.vertices, fresh_vertices);
    ASSERT_TRUE(session.undo());
    // A stroke that reaches no boundary is refused and changes nothing.
    EXPECT_THROW(session.apply(Edit{Edit::smooth, {{100, 100, 100}}, 0.01, false}, progress), Error);
    EXPECT_EQ(session.undo_steps(), 0u);
    expect_same_pairs(pairs(session.terms()), fresh_pairs);
}

TEST(DecompositionSession, CancelledRerunLeavesTheSession) {
    Progress quiet;
    const Mesh input = sphere();
    DecomposeSettings s = settings();
    s.decomposition.smoothing_iterations = 5;
    DecompositionSession session(input, s, quiet);
    const std::vector<int> labels = session.decomposition().part_of_triangle;
    const std::vector<Vec3> vertices = session.shell().outer.vertices;
    const auto before = pairs(session.terms());
    std::atomic<bool> cancel{false};
    struct Hook {
        std::atomic<bool>* flag;
    } hook{&cancel};
    Progress progress(
        [](void* user, const char* stage, double) {
            if (std::string(stage) == "boundary smoothing") static_cast<Hook*>(user)->flag->store(true);
            return 0;
        },
        &hook, &cancel);
    DecompositionOptions three = s.decomposition;
    three.parts = 3;
    EXPECT_THROW(session.rerun(three, 2 * M_PI / 180, progress), Error);
    EXPECT_EQ(session.decomposition().part_of_triangle, labels);
    EXPECT_EQ(session.shell().outer.vertices, vertices);
    EXPECT_EQ(session.terms().draft, s.draft_radians);
    expect_same_pairs(pairs(session.terms()), before);
    EXPECT_EQ(session.undo_steps(), 0u);
}

}  // namespace
