// Edits of a mold decomposition on the shared sphere (thesis §3.5): a closed
// cut adds a part, a merge removes one, a no-cut stroke across a boundary
// moves the boundary out of the stroke, and parts an edit does not touch keep
// exactly their triangles and direction. Triangle sets are compared as sets;
// the stroke and cap regions are measured geometrically in the test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.h"
#include "io/mesh_io.h"
#include "surface/decompose.h"
#include "surface/vec3_ops.h"

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

TEST(DecompositionEdits, CutAddsAPartAndMergeRemovesItTouchingNothingElse) {
    const Sphere& s = sphere();
    const Shell& shell = s.result.shell;
    ASSERT_EQ(s.result.decomposition.parts.size(), 2u);
    Progress progress;
    Decomposition d = s.result.decomposition;
    const auto before = parts_of(d);
    const Vec3 axis = axis_of(s, d, 0);
    apply_edit(shell, s.result.terms, {}, cap_cut(s, axis, 0.6), 0, d, progress);
    ASSERT_EQ(d.parts.size(), 3u);
    const auto after_cut = parts_of(d);
    // Part 1 of the automatic result is untouched.
    const auto untouched = *std::find_if(before.begin(), before.end(), [&](const auto& p) {
        return p.first.count(uint32_t(std::find(s.result.decomposition.part_of_triangle.begin(),
                                                s.result.decomposition.part_of_triangle.end(), 1) -
                                      s.result.decomposition.part_of_triangle.begin()));
    });
    EXPECT_TRUE(after_cut.count(untouched));
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
    apply_edit(shell, s.result.terms, {}, merge, 1, d, progress);
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
    const Shell& shell = s.result.shell;
    Progress progress;
    Decomposition d = s.result.decomposition;
    const Vec3 axis = axis_of(s, d, 0);
    apply_edit(shell, s.result.terms, {}, cap_cut(s, axis, 0.5), 0, d, progress);
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
    const nlohmann::json record = apply_edit(shell, s.result.terms, {}, stroke, 0, d, progress);
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
    Progress progress;
    Decomposition d = s.result.decomposition;
    const Vec3 axis = axis_of(s, d, 0);
    Edit merge;
    merge.type = Edit::merge;
    merge.points = {s.centre + s.radius * axis, on_sphere(s, axis, normalized(cross(axis, Vec3{0, 0, 1})), 0.3)};
    try {
        apply_edit(s.result.shell, s.result.terms, {}, merge, 0, d, progress);
        FAIL() << "a merge within one part was accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), FABVDB_ERR_BAD_INPUT);
    }
    Edit open_cut;
    open_cut.type = Edit::cut;
    open_cut.points = {s.centre + s.radius * axis, on_sphere(s, axis, normalized(cross(axis, Vec3{0, 0, 1})), 0.3)};
    EXPECT_THROW(apply_edit(s.result.shell, s.result.terms, {}, open_cut, 0, d, progress), Error);
}

}  // namespace
