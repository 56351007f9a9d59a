// Edits of a mold decomposition on the shared sphere (thesis §3.5): a closed
// cut adds a part, a merge removes one, a no-cut stroke across a boundary
// moves the boundary out of the stroke, each piece of a cut gets the
// parting line best_parting_line gives it alone, a smooth stroke straightens the
// boundary under it and moves no vertex outside it, and parts an edit does
// not touch keep exactly their triangles, direction and energy. Triangle sets are compared as sets;
// the stroke and cap regions are measured geometrically in the test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/error.h"
#include "io/mesh_io.h"
#include "surface/decompose.h"
#include "core/vec3_ops.h"

namespace {

using namespace fabvdb;
using namespace fabvdb::surface;

struct Sphere {
    DecomposeResult result;
    Vec3 centre{0, 0, 0};
    double radius = 0;
};

const Sphere& sphere() {
    static const Sphere s = [] {
        Progress progress;
        const Mesh input = io::read_mesh(FABVDB_SHARED_DATA "/meshes/sphere.obj", progress);
        DecomposeSettings settings;
        settings.shell.target_triangles = 1500;
        settings.shell.thickness = 0.06;
        settings.decomposition.smoothing_iterations = 0;  // rough boundaries for the smooth edit
        Sphere made;
        made.result = decompose_mesh(input, settings, {}, progress);
        const auto& v = made.result.shell.outer.vertices;
        for (const Vec3& p : v) made.centre = made.centre + (1.0 / v.size()) * p;
        made.radius = norm(v[0] - made.centre);
        return made;
    }();
    return s;
}

using PartSet = std::set<uint32_t>;
std::set<std::pair<PartSet, int>> parts_of(const Decomposition& d) {
    std::vector<PartSet> sets(d.parts.size());
    for (size_t t = 0; t < d.part_of_triangle.size(); ++t) sets[d.part_of_triangle[t]].insert(uint32_t(t));
    std::set<std::pair<PartSet, int>> out;
    for (size_t p = 0; p < sets.size(); ++p) out.insert({sets[p], d.parts[p].direction});
    return out;
}

Vec3 centroid_of(const Shell& shell, size_t t) {
    const Triangle& f = shell.outer.triangles[t];
    return (1.0 / 3.0) * (shell.outer.vertices[f[0]] + shell.outer.vertices[f[1]] + shell.outer.vertices[f[2]]);
}

//! Unit axis from the centre through the centroid of part `p`.
Vec3 axis_of(const Sphere& s, const Decomposition& d, int p) {
    Vec3 sum{0, 0, 0};
    for (size_t t = 0; t < d.part_of_triangle.size(); ++t)
        if (d.part_of_triangle[t] == p) sum = sum + (centroid_of(s.result.shell, t) - s.centre);
    return normalized(sum);
}

//! The point at `angle` from `axis` towards `towards` on the sphere.
Vec3 on_sphere(const Sphere& s, const Vec3& axis, const Vec3& towards, double angle) {
    return s.centre + s.radius * (std::cos(angle) * axis + std::sin(angle) * towards);
}

Edit cap_cut(const Sphere& s, const Vec3& axis, double angle) {
    const Vec3 u = normalized(cross(axis, std::abs(axis[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
    const Vec3 v = cross(axis, u);
    Edit cut;
    cut.type = Edit::cut;
    cut.closed = true;
    for (int i = 0; i < 16; ++i) {
        const double phi = 2 * M_PI * i / 16;
        cut.points.push_back(on_sphere(s, axis, std::cos(phi) * u + std::sin(phi) * v, angle));
    }
    return cut;
}

TEST(DecompositionEdits, EachPieceOfACutGetsItsBestPartingLine) {
    // The pieces are labelled side by side; each must be what
    // best_parting_line gives it alone, with the cut part's direction as hint.
    const Sphere& s = sphere();
    Shell shell = s.result.shell;
    MoldabilityTerms terms = s.result.terms;
    Progress progress;
    Decomposition d = s.result.decomposition;
    const int former = d.parts[0].direction;
    const nlohmann::json record = apply_edit(shell, terms, {}, cap_cut(s, axis_of(s, d, 0), 0.6), 0, d, progress);
    ASSERT_EQ(d.parts.size(), 3u);
    EXPECT_EQ(record["parts_touched"], nlohmann::json({0, 2}));
    for (int p : {0, 2}) {
        const PartMolding alone = best_parting_line(shell, terms, d.part_of_triangle, p, {}, {former}, progress);
        EXPECT_EQ(d.parts[size_t(p)].direction, alone.direction) << "part " << p;
        EXPECT_EQ(d.parts[size_t(p)].energy.total, alone.energy.total) << "part " << p;
        EXPECT_EQ(d.parts[size_t(p)].upper, alone.upper) << "part " << p;
    }
}

TEST(DecompositionEdits, CutAddsAPartAndMergeRemovesItTouchingNothingElse) {
    const Sphere& s = sphere();
    Shell shell = s.result.shell;
    MoldabilityTerms terms = s.result.terms;
    ASSERT_EQ(s.result.decomposition.parts.size(), 2u);
    Progress progress;
    Decomposition d = s.result.decomposition;
    const auto before = parts_of(d);
    const Vec3 axis = axis_of(s, d, 0);
    apply_edit(shell, terms, {}, cap_cut(s, axis, 0.6), 0, d, progress);
    ASSERT_EQ(d.parts.size(), 3u);
    const auto after_cut = parts_of(d);
    // Part 1 of the automatic result is untouched.
    const auto untouched = *std::find_if(before.begin(), before.end(), [&](const auto& p) {
        return p.first.count(uint32_t(std::find(s.result.decomposition.part_of_triangle.begin(),
                                                s.result.decomposition.part_of_triangle.end(), 1) -
                                      s.result.decomposition.part_of_triangle.begin()));
    });
    EXPECT_TRUE(after_cut.count(untouched));
    for (const PartMolding& p : d.parts)
        if (p.direction == s.result.decomposition.parts[1].direction &&
            p.surface.size() == s.result.decomposition.parts[1].surface.size())
            EXPECT_EQ(p.energy.total, s.result.decomposition.parts[1].energy.total);
    // The new cap holds the triangles well inside the loop and none well outside.
    const int cap = d.part_of_triangle[std::max_element(shell.normal.begin(), shell.normal.end(),
                                                        [&](const Vec3& a, const Vec3& b) {
                                                            return dot(a, axis) < dot(b, axis);
                                                        }) -
                                       shell.normal.begin()];
    for (size_t t = 0; t < shell.triangle_count(); ++t) {
        const double angle = std::acos(std::clamp(dot(normalized(centroid_of(shell, t) - s.centre), axis), -1.0, 1.0));
        if (angle < 0.45) EXPECT_EQ(d.part_of_triangle[t], cap);
        if (angle > 0.8) EXPECT_NE(d.part_of_triangle[t], cap);
    }
    const Vec3 side = normalized(cross(axis, Vec3{0.3, 0.5, 0.8}));
    Edit merge;
    merge.type = Edit::merge;
    merge.points = {s.centre + s.radius * axis, on_sphere(s, axis, side, 1.0)};
    apply_edit(shell, terms, {}, merge, 1, d, progress);
    ASSERT_EQ(d.parts.size(), 2u);
    const auto after_merge = parts_of(d);
    EXPECT_TRUE(after_merge.count(untouched));
    std::set<PartSet> sets_before, sets_after;
    for (const auto& p : before) sets_before.insert(p.first);
    for (const auto& p : after_merge) sets_after.insert(p.first);
    EXPECT_EQ(sets_before, sets_after);
    EXPECT_GE(d.parts[0].energy.total, 0.0);
}

TEST(DecompositionEdits, NoCutStrokeMovesTheBoundaryOutOfItAndKeepsOtherParts) {
    const Sphere& s = sphere();
    Shell shell = s.result.shell;
    MoldabilityTerms terms = s.result.terms;
    Progress progress;
    Decomposition d = s.result.decomposition;
    const Vec3 axis = axis_of(s, d, 0);
    apply_edit(shell, terms, {}, cap_cut(s, axis, 0.5), 0, d, progress);
    ASSERT_EQ(d.parts.size(), 3u);
    const auto before = parts_of(d);
    // A stroke across the boundary between part 0's remainder and part 1, on a meridian.
    const Vec3 side = normalized(cross(axis, Vec3{0.3, 0.5, 0.8}));
    Edit stroke;
    stroke.type = Edit::no_cut;
    stroke.radius = 0.15 * s.radius;
    for (double a = 1.2; a <= 1.95; a += 0.05) stroke.points.push_back(on_sphere(s, axis, side, a));
    std::vector<uint32_t> brushed;
    std::set<int> parts_under;
    for (size_t t = 0; t < shell.triangle_count(); ++t)
        for (const Vec3& p : stroke.points)
            if (norm(centroid_of(shell, t) - p) <= stroke.radius) {
                brushed.push_back(uint32_t(t));
                parts_under.insert(d.part_of_triangle[t]);
                break;
            }
    ASSERT_EQ(parts_under.size(), 2u) << "the stroke must cross a boundary";
    const nlohmann::json record = apply_edit(shell, terms, {}, stroke, 0, d, progress);
    std::set<int> parts_after;
    for (uint32_t t : brushed) parts_after.insert(d.part_of_triangle[t]);
    EXPECT_EQ(parts_after.size(), 1u);
    // The cap, which the stroke does not reach, keeps its triangles and direction.
    const auto after = parts_of(d);
    size_t kept = 0;
    for (const auto& p : before) kept += after.count(p);
    EXPECT_GE(kept, 1u);
    EXPECT_EQ(record["type"], "no_cut");
}

TEST(DecompositionEdits, EditsThatDoNotApplyAreRefused) {
    const Sphere& s = sphere();
    Shell shell = s.result.shell;
    MoldabilityTerms terms = s.result.terms;
    Progress progress;
    Decomposition d = s.result.decomposition;
    const Vec3 axis = axis_of(s, d, 0);
    Edit merge;
    merge.type = Edit::merge;
    merge.points = {s.centre + s.radius * axis, on_sphere(s, axis, normalized(cross(axis, Vec3{0, 0, 1})), 0.3)};
    try {
        apply_edit(shell, terms, {}, merge, 0, d, progress);
        FAIL() << "a merge within one part was accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT);
    }
    Edit open_cut;
    open_cut.type = Edit::cut;
    open_cut.points = {s.centre + s.radius * axis, on_sphere(s, axis, normalized(cross(axis, Vec3{0, 0, 1})), 0.3)};
    EXPECT_THROW(apply_edit(shell, terms, {}, open_cut, 0, d, progress), Error);
    Edit far_smooth;
    far_smooth.type = Edit::smooth;
    far_smooth.radius = 0.05 * s.radius;
    far_smooth.points = {s.centre + s.radius * axis};
    try {
        apply_edit(shell, terms, {}, far_smooth, 0, d, progress);
        FAIL() << "a smoothing stroke away from every boundary was accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT);
    }
}

//! Sum, over boundary vertices with two boundary edges within `radius` of
//! `centre`, of the angle by which the boundary bends there.
double turning_near(const Shell& shell, const Decomposition& d, const Vec3& centre, double radius) {
    std::map<uint32_t, std::set<uint32_t>> ends;
    for (size_t t = 0; t < shell.triangle_count(); ++t) {
        const Triangle& f = shell.outer.triangles[t];
        for (int k = 0; k < 3; ++k)
            if (d.part_of_triangle[shell.neighbor[t][k]] != d.part_of_triangle[t]) {
                ends[f[k]].insert(f[(k + 1) % 3]);
                ends[f[(k + 1) % 3]].insert(f[k]);
            }
    }
    double turning = 0;
    for (const auto& [v, others] : ends) {
        const Vec3& x = shell.outer.vertices[v];
        if (others.size() != 2 || norm(x - centre) > radius) continue;
        const Vec3 a = shell.outer.vertices[*others.begin()] - x;
        const Vec3 b = shell.outer.vertices[*others.rbegin()] - x;
        turning += M_PI - std::acos(std::clamp(dot(a, b) / (norm(a) * norm(b)), -1.0, 1.0));
    }
    return turning;
}

TEST(DecompositionEdits, SmoothStrokeStraightensTheBoundaryUnderItOnly) {
    const Sphere& s = sphere();
    Shell shell = s.result.shell;
    MoldabilityTerms terms = s.result.terms;
    Progress progress;
    Decomposition d = s.result.decomposition;
    const Vec3 axis = axis_of(s, d, 0);
    apply_edit(shell, terms, {}, cap_cut(s, axis, 0.5), 0, d, progress);
    ASSERT_EQ(d.parts.size(), 3u);
    // A stroke on the boundary between the two halves, far from the cap.
    const Vec3 side = normalized(cross(axis, Vec3{0.3, 0.5, 0.8}));
    Vec3 on_boundary{0, 0, 0};
    double best = 1e300;
    for (size_t t = 0; t < shell.triangle_count(); ++t)
        for (int k = 0; k < 3; ++k) {
            const int a = d.part_of_triangle[t], b = d.part_of_triangle[shell.neighbor[t][k]];
            const Vec3& x = shell.outer.vertices[shell.outer.triangles[t][k]];
            if (a != b && norm(x - on_sphere(s, axis, side, M_PI / 2)) < best) {
                best = norm(x - on_sphere(s, axis, side, M_PI / 2));
                on_boundary = x;
            }
        }
    Edit stroke;
    stroke.type = Edit::smooth;
    stroke.radius = 0.5 * s.radius;
    stroke.points = {on_boundary};
    const Shell shell_before = shell;
    const Decomposition d_before = d;
    const double turning_before = turning_near(shell, d, on_boundary, stroke.radius);
    const nlohmann::json record = apply_edit(shell, terms, {}, stroke, 1, d, progress);
    EXPECT_EQ(record["type"], "smooth");
    EXPECT_LT(turning_near(shell, d, on_boundary, stroke.radius), 0.8 * turning_before);
    EXPECT_EQ(d.part_of_triangle, d_before.part_of_triangle);
    // Vertices outside the stroke stay; parts the stroke does not reach keep
    // their direction, surface and energy.
    std::set<int> reached;
    for (size_t v = 0; v < shell.outer.vertices.size(); ++v)
        if (shell.outer.vertices[v] != shell_before.outer.vertices[v]) {
            EXPECT_LE(norm(shell_before.outer.vertices[v] - on_boundary), stroke.radius);
            for (size_t t = 0; t < shell.triangle_count(); ++t)
                for (uint32_t c : shell.outer.triangles[t])
                    if (c == v) reached.insert(d.part_of_triangle[t]);
        }
    EXPECT_GE(reached.size(), 2u);
    for (size_t p = 0; p < d.parts.size(); ++p) {
        if (reached.count(int(p))) continue;
        EXPECT_EQ(d.parts[p].direction, d_before.parts[p].direction);
        EXPECT_EQ(d.parts[p].surface.corners, d_before.parts[p].surface.corners);
        EXPECT_EQ(d.parts[p].energy.total, d_before.parts[p].energy.total);
    }
    EXPECT_LT(d.total_energy(), DecompositionOptions{}.gamma);
    // The overlap terms updated for the moved triangles equal a full recomputation.
    const MoldabilityTerms fresh = compute_moldability_terms(shell, terms.draft, progress);
    ASSERT_EQ(fresh.overlaps.size(), terms.overlaps.size());
    for (size_t a = 0; a < fresh.overlaps.size(); ++a) {
        std::map<std::pair<uint32_t, uint32_t>, double> expected, updated;
        for (size_t t = 0; t + 1 < fresh.overlaps[a].offset.size(); ++t)
            for (uint32_t k = fresh.overlaps[a].offset[t]; k < fresh.overlaps[a].offset[t + 1]; ++k)
                expected[{uint32_t(t), fresh.overlaps[a].partner[k]}] = fresh.overlaps[a].area[k];
        for (size_t t = 0; t + 1 < terms.overlaps[a].offset.size(); ++t)
            for (uint32_t k = terms.overlaps[a].offset[t]; k < terms.overlaps[a].offset[t + 1]; ++k)
                updated[{uint32_t(t), terms.overlaps[a].partner[k]}] = terms.overlaps[a].area[k];
        for (const auto& [pair, area] : expected) {
            const auto it = updated.find(pair);
            const double got = it == updated.end() ? 0.0 : it->second;
            EXPECT_NEAR(got, area, 1e-6 * area + 1e-12) << "axis " << a << " pair " << pair.first << "," << pair.second;
        }
        for (const auto& [pair, area] : updated)
            if (!expected.count(pair)) EXPECT_LT(area, 1e-12) << "axis " << a << " extra pair";
    }
}

}  // namespace
