// corpus_check — the independent checker of bench/corpus (GPL-3.0-or-later).
//
// Measures what fabvdb wrote without using fabvdb's own validity, inspection
// or repair code: written STL files are read by a reader of its own (float
// coordinates exactly as stored, corners welded only where they are bit-equal);
// closedness, 2-manifoldness, float degeneracy and the height-field test come
// from tests/support (own ray casting), self-intersection and distances from
// CGAL (exact predicates, AABB tree), orientation from ray parity probes.
// Only the corpus *inputs* are read with fabvdb's file readers (3MF, PLY, …),
// scaled about the origin as `--fit` does. Each mode prints one JSON object:
//
//   corpus_check solid FILE [--reference IN --fit LEN] [--cavity-wall] [--direction X,Y,Z]
//       validity of FILE; with --reference, sampled distances input<->FILE (mm);
//       --cavity-wall: distances from the cavity shells to the outer shells
//       (the wall as built; with --reference, void shells lying on the
//       input's surface are the input's own, not cavities made, and count
//       on the walls' outer side); --direction: the double-height-field ray test.
//   corpus_check input IN --fit LEN
//       the same validity measures on a corpus input (is it a clean solid?);
//       mean_thickness = 2 volume / area, for telling a flat sliver.
//   corpus_check cover IN --fit LEN PART.stl...
//       distance from the input surface to the nearest of the parts (mold
//       faithfulness): max (and where it is) and area-weighted mean, mm, and
//       the input diagonal; leaving out input surface that the input's own
//       solid encloses on both sides (generalized winding number ≥ ½: a
//       shell inside another, or the walls of a slit narrower than 0.3 mm),
//       whose figures over all of it are under
//       all_surface; max_part: the part nearest to the farthest point, and
//       max_side: "buried" when that point lies inside the parts (a cast
//       part holds more than the input there), else "uncovered".
//       --exempt X,Y,Z,R (repeatable): input samples in these balls are left
//       out (a drilled hole's mouth, a cavity filled); --gap G (mm): the
//       walls of slits narrower than G (at least 0.3 mm) are left out too
//       (what a level set of voxel G / 2 may close); --far D (mm):
//       far_fraction, the share of the area samples left in that lie
//       farther than D.
//   corpus_check flip IN OUT.obj
//       writes the input turned inside out (every triangle reversed) as OBJ.
//   corpus_check obj IN OUT.obj [--fit LEN]
//       writes the input as read (scaled as --fit does) as OBJ, triangles in order.
//   corpus_check decomposition D.json
//       tests/support's decomposition checks (ownership, pieces, energies).
//
// Cost: O(n log n) in the triangles for the distance and orientation probes,
// plus CGAL's self-intersection test; seconds for a few 100k triangles.
#include <gtest/gtest.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>
#include <tbb/parallel_for.h>

#include "core/progress.h"
#include "io/mesh_io.h"
#include "support/decomposition_checks.h"
#include "support/check_vec3.h"
#include "support/ray_cast.h"
#include "support/winding_number.h"

namespace {

using fabvdb::Mesh;
using fabvdb::Vec3;
using nlohmann::json;

using Kernel = CGAL::Simple_cartesian<double>;
using Triangle3 = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle3>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

using fabvdb::test::cross;
using fabvdb::test::dot;
using fabvdb::test::norm;
using fabvdb::test::sub;
using fabvdb::test::winding_number;

struct Failure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

//! Binary or ASCII STL as stored: float coordinates, corners welded where their
//! three floats are bit-equal, nothing else changed.
Mesh read_stl_as_stored(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Failure("cannot open " + path);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::array<float, 3>> corners;
    bool binary = bytes.size() >= 84;
    uint32_t count = 0;
    if (binary) {
        std::memcpy(&count, bytes.data() + 80, 4);
        binary = bytes.size() == 84 + size_t(count) * 50;
    }
    if (binary) {
        for (uint32_t i = 0; i < count; ++i)
            for (int k = 0; k < 3; ++k) {
                std::array<float, 3> p;
                std::memcpy(p.data(), bytes.data() + 84 + size_t(i) * 50 + 12 + 12 * k, 12);
                corners.push_back(p);
            }
    } else {
        std::istringstream text(bytes);
        std::string word;
        while (text >> word)
            if (word == "vertex") {
                std::array<float, 3> p;
                if (!(text >> p[0] >> p[1] >> p[2])) throw Failure("malformed ASCII STL vertex in " + path);
                corners.push_back(p);
            }
        if (corners.size() % 3) throw Failure("ASCII STL with a partial facet: " + path);
    }
    Mesh mesh;
    std::map<std::array<uint32_t, 3>, uint32_t> index;
    for (size_t c = 0; c < corners.size(); c += 3) {
        fabvdb::Triangle t;
        for (int k = 0; k < 3; ++k) {
            std::array<uint32_t, 3> key;
            std::memcpy(key.data(), corners[c + k].data(), 12);
            auto [it, added] = index.emplace(key, uint32_t(mesh.vertices.size()));
            if (added) mesh.vertices.push_back({corners[c + k][0], corners[c + k][1], corners[c + k][2]});
            t[k] = it->second;
        }
        mesh.triangles.push_back(t);
    }
    return mesh;
}

//! A corpus input scaled as `fabvdb --fit LEN` scales it: about the origin, so
//! that the longest side of the box of all its vertices is `fit` (0: as read).
Mesh read_input(const std::string& path, double fit) {
    fabvdb::Progress progress;
    Mesh mesh = fabvdb::io::read_mesh(path, progress);
    if (fit <= 0) return mesh;
    double longest = 0;
    for (int k = 0; k < 3; ++k) {
        double lo = 1e300, hi = -1e300;
        for (const Vec3& p : mesh.vertices) lo = std::min(lo, p[k]), hi = std::max(hi, p[k]);
        longest = std::max(longest, hi - lo);
    }
    if (!(longest > 0) || !std::isfinite(longest)) throw Failure(path + ": no extent to fit");
    const double scale = fit / longest;
    for (Vec3& p : mesh.vertices)
        for (double& c : p) c *= scale;
    return mesh;
}

struct Box {
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    double diagonal() const { return norm(sub(hi, lo)); }
};
Box box_of(const Mesh& mesh) {
    Box b;
    for (const auto& t : mesh.triangles)
        for (uint32_t v : t)
            for (int k = 0; k < 3; ++k) {
                b.lo[k] = std::min(b.lo[k], mesh.vertices[v][k]);
                b.hi[k] = std::max(b.hi[k], mesh.vertices[v][k]);
            }
    return b;
}

bool finite(const Mesh& mesh) {
    for (const Vec3& p : mesh.vertices)
        for (double c : p)
            if (!std::isfinite(c)) return false;
    return true;
}

//! Connected pieces of triangles joined across shared (undirected) edges.
std::vector<uint32_t> shell_labels(const Mesh& mesh, uint32_t& count) {
    std::vector<uint32_t> parent(mesh.triangles.size());
    for (uint32_t i = 0; i < parent.size(); ++i) parent[i] = i;
    auto find = [&](uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> first;
    for (uint32_t i = 0; i < mesh.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            auto key = std::minmax(mesh.triangles[i][k], mesh.triangles[i][(k + 1) % 3]);
            auto [it, added] = first.emplace(key, i);
            if (!added) parent[find(i)] = find(it->second);
        }
    std::map<uint32_t, uint32_t> number;
    std::vector<uint32_t> label(parent.size());
    for (uint32_t i = 0; i < parent.size(); ++i) {
        auto [it, added] = number.emplace(find(i), uint32_t(number.size()));
        label[i] = it->second;
    }
    count = uint32_t(number.size());
    return label;
}

double area_of(const Mesh& m, const fabvdb::Triangle& t) {
    return 0.5 * norm(cross(sub(m.vertices[t[1]], m.vertices[t[0]]), sub(m.vertices[t[2]], m.vertices[t[0]])));
}

//! About `count` points spread over the triangles by area (fixed seed), plus
//! every vertex a triangle uses when `with_vertices`; `source` (may be null)
//! receives each point's triangle.
std::vector<Vec3> surface_samples(const Mesh& mesh, const std::vector<uint32_t>& triangles, size_t count,
                                  bool with_vertices, std::vector<uint32_t>* source = nullptr) {
    std::vector<Vec3> points;
    double total = 0;
    for (uint32_t i : triangles) total += area_of(mesh, mesh.triangles[i]);
    std::mt19937 random(2024);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double carry = 0;
    for (uint32_t i : triangles) {
        const auto& t = mesh.triangles[i];
        if (with_vertices) points.push_back(mesh.vertices[t[0]]);
        if (with_vertices && source) source->push_back(i);
        carry += total > 0 ? count * area_of(mesh, t) / total : 0;
        for (; carry >= 1; carry -= 1) {
            double a = unit(random), b = unit(random);
            if (a + b > 1) a = 1 - a, b = 1 - b;
            Vec3 p;
            for (int k = 0; k < 3; ++k)
                p[k] = mesh.vertices[t[0]][k] + a * (mesh.vertices[t[1]][k] - mesh.vertices[t[0]][k]) +
                       b * (mesh.vertices[t[2]][k] - mesh.vertices[t[0]][k]);
            points.push_back(p);
            if (source) source->push_back(i);
        }
    }
    return points;
}

std::vector<uint32_t> all_triangles(const Mesh& mesh) {
    std::vector<uint32_t> all(mesh.triangles.size());
    for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    return all;
}

struct Distances {
    double max = 0, mean = 0;
    size_t samples = 0;
    Vec3 max_at{0, 0, 0};  //!< the point farthest from the targets
};

//! Distances from `points` to the triangles `targets` of the meshes.
Distances distances(const std::vector<Vec3>& points, const std::vector<Triangle3>& targets,
                    std::vector<double>* each = nullptr) {
    Distances d;
    if (each) each->assign(points.size(), 0.0);
    if (targets.empty() || points.empty()) return d;
    Tree tree(targets.begin(), targets.end());
    tree.accelerate_distance_queries();
    double sum = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        const Vec3& p = points[i];
        const double r = std::sqrt(tree.squared_distance(Kernel::Point_3(p[0], p[1], p[2])));
        if (each) (*each)[i] = r;
        if (r > d.max) {
            d.max = r;
            d.max_at = p;
        }
        sum += r;
    }
    d.samples = points.size();
    d.mean = sum / points.size();
    return d;
}

std::vector<Triangle3> triangles_of(const Mesh& mesh, const std::vector<uint32_t>& which) {
    std::vector<Triangle3> out;
    for (uint32_t i : which) {
        const auto& t = mesh.triangles[i];
        auto p = [&](int k) {
            const Vec3& v = mesh.vertices[t[k]];
            return Kernel::Point_3(v[0], v[1], v[2]);
        };
        if (!Kernel::Triangle_3(p(0), p(1), p(2)).is_degenerate()) out.emplace_back(p(0), p(1), p(2));
    }
    return out;
}

json distance_json(const Distances& d) { return {{"max", d.max}, {"mean", d.mean}, {"samples", d.samples}}; }

//! Distance from `from` along `direction` (any length) to the nearest point
//! where the ray meets a triangle of `tree` farther than `skip`; infinity
//! where it meets none.
double free_distance(const Tree& tree, const Vec3& from, const Vec3& direction, double skip) {
    const Kernel::Point_3 start(from[0], from[1], from[2]);
    const Kernel::Ray_3 ray(start, Kernel::Vector_3(direction[0], direction[1], direction[2]));
    std::vector<Tree::Intersection_and_primitive_id<Kernel::Ray_3>::Type> hits;
    tree.all_intersections(ray, std::back_inserter(hits));
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& hit : hits)
        if (const auto* point = boost::get<Kernel::Point_3>(&hit.first)) {
            const double d = std::sqrt(CGAL::squared_distance(start, *point));
            if (d > skip) nearest = std::min(nearest, d);
        }
    return nearest;
}

//! Validity of a mesh as stored plus per-shell orientation by parity probes:
//! a point just in front of a triangle must be outside the solid and one just
//! behind it inside, on the majority of a shell's largest triangles. Each
//! probe lies at most halfway to the next surface on its side, so a sheet
//! thinner than the probe distance is probed inside it.
json validity(const Mesh& mesh, std::vector<uint32_t>& labels, std::vector<int>& shell_sign) {
    json out;
    out["triangles"] = mesh.triangles.size();
    out["vertices"] = mesh.vertices.size();
    if (mesh.triangles.empty()) {
        out["valid"] = false;
        out["defects"] = {"no triangles"};
        return out;
    }
    std::vector<std::string> defects;
    if (!finite(mesh)) defects.push_back("non-finite coordinate");
    const size_t degenerate = fabvdb::test::degenerate_triangle_count(fabvdb::test::stored_as_float(mesh));
    out["degenerate_triangles"] = degenerate;
    if (degenerate) defects.push_back(std::to_string(degenerate) + " degenerate triangles as float");
    const bool manifold = fabvdb::test::closed_two_manifold(mesh);
    out["closed_two_manifold"] = manifold;
    if (!manifold) defects.push_back("not closed, 2-manifold and consistently oriented");
    if (manifold && defects.empty()) {
        const bool crossing = fabvdb::test::self_intersects(mesh);
        out["self_intersects"] = crossing;
        if (crossing) defects.push_back("self-intersecting");
    }
    uint32_t shells = 0;
    labels = shell_labels(mesh, shells);
    out["shells"] = shells;
    shell_sign.assign(shells, 0);
    if (manifold && defects.empty()) {
        const Box box = box_of(mesh);
        fabvdb::test::LineCaster caster(mesh, Vec3{0.0123, 0.0371, 1.0});
        const auto all = triangles_of(mesh, all_triangles(mesh));
        Tree tree(all.begin(), all.end());
        std::vector<std::vector<std::pair<double, uint32_t>>> by_shell(shells);
        for (uint32_t i = 0; i < mesh.triangles.size(); ++i)
            by_shell[labels[i]].push_back({area_of(mesh, mesh.triangles[i]), i});
        size_t inward = 0, undecided = 0;
        for (uint32_t s = 0; s < shells; ++s) {
            auto& list = by_shell[s];
            std::partial_sort(list.begin(), list.begin() + std::min<size_t>(7, list.size()), list.end(),
                              [](auto& a, auto& b) { return a.first > b.first; });
            int votes = 0;
            for (size_t j = 0; j < std::min<size_t>(7, list.size()); ++j) {
                const auto& t = mesh.triangles[list[j].second];
                const Vec3 n = cross(sub(mesh.vertices[t[1]], mesh.vertices[t[0]]),
                                     sub(mesh.vertices[t[2]], mesh.vertices[t[0]]));
                const double length = norm(n);
                const double eps = std::min(1e-4 * box.diagonal(), 0.05 * std::sqrt(list[j].first));
                Vec3 centre, reverse;
                for (int k = 0; k < 3; ++k) {
                    centre[k] = (mesh.vertices[t[0]][k] + mesh.vertices[t[1]][k] + mesh.vertices[t[2]][k]) / 3;
                    reverse[k] = -n[k];
                }
                const double skip = 1e-9 * box.diagonal();
                const double ahead = std::min(eps, 0.5 * free_distance(tree, centre, n, skip));
                const double behind = std::min(eps, 0.5 * free_distance(tree, centre, reverse, skip));
                Vec3 front, back;
                for (int k = 0; k < 3; ++k) {
                    front[k] = centre[k] + ahead * n[k] / length;
                    back[k] = centre[k] - behind * n[k] / length;
                }
                const bool in_front = caster.inside(front), in_back = caster.inside(back);
                votes += (!in_front && in_back) ? 1 : (in_front && !in_back) ? -1 : 0;
            }
            shell_sign[s] = votes > 0 ? 1 : votes < 0 ? -1 : 0;
            inward += votes < 0;
            undecided += votes == 0;
        }
        out["inward_shells"] = inward;
        if (inward) defects.push_back(std::to_string(inward) + " shells facing inward");
        if (undecided) defects.push_back(std::to_string(undecided) + " shells of undecided orientation");
        double volume = 0, area = 0;
        for (const auto& t : mesh.triangles) {
            const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
            volume += dot(a, cross(b, c)) / 6;
            area += area_of(mesh, t);
        }
        out["volume"] = volume;
        out["mean_thickness"] = area > 0 ? 2 * volume / area : 0.0;
        if (!(volume > 0)) defects.push_back("volume not positive");
    }
    out["valid"] = defects.empty();
    out["defects"] = defects;
    return out;
}

//! Signed volume of each shell (divergence theorem).
std::vector<double> shell_volumes(const Mesh& mesh, const std::vector<uint32_t>& labels, size_t shells) {
    std::vector<double> volume(shells, 0.0);
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        const auto& t = mesh.triangles[i];
        const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
        volume[labels[i]] += dot(a, cross(b, c)) / 6;
    }
    return volume;
}

//! Points of the mesh's own surface that the solid it encloses holds on
//! both sides: |winding number| ≥ ½ at `step` behind the point along its
//! triangle's normal (in front, for a surface stored inside out, whose
//! normal is then taken the other way), and in front either at `step` (surface of a shell
//! inside another, e.g. overlapping shells) or at `step` past where the ray
//! along the normal meets the surface again within `gap` (the wall of a slit
//! narrower than `gap`, which no fabrication keeps open). Only the points
//! whose `distance` exceeds `floor` are tested (brute force: their count ×
//! the triangles, in parallel); the others stay false.
std::vector<char> enclosed(const Mesh& mesh, const Tree& tree, const std::vector<Vec3>& points,
                           const std::vector<uint32_t>& source, const std::vector<double>& distance, double floor,
                           double step, double gap) {
    std::vector<char> inside(points.size(), 0);
    const auto solid = [&](const Vec3& p, const Vec3& n, double along) {
        return std::abs(winding_number(mesh, {p[0] + along * n[0], p[1] + along * n[1], p[2] + along * n[2]})) >= 0.5;
    };
    tbb::parallel_for(size_t(0), points.size(), [&](size_t i) {
        if (!(distance[i] > floor)) return;
        const auto& t = mesh.triangles[source[i]];
        Vec3 n = cross(sub(mesh.vertices[t[1]], mesh.vertices[t[0]]), sub(mesh.vertices[t[2]], mesh.vertices[t[0]]));
        const double length = norm(n);
        if (length == 0) return;
        for (double& x : n) x /= length;
        // n points away from the solid: an input stored inside out has its
        // solid in front of its triangles.
        if (!solid(points[i], n, -step)) {
            if (!solid(points[i], n, step)) return;
            for (double& x : n) x = -x;
        }
        if (solid(points[i], n, step)) {
            inside[i] = 1;
            return;
        }
        const double across = free_distance(tree, points[i], n, 0.5 * step);
        inside[i] = across < gap && solid(points[i], n, across + step);
    });
    return inside;
}

//! Points inside a void shell's void: from each of its 7 largest triangles
//! (a void shell faces into its void), the middle of the segment along the
//! triangle's normal up to where it meets the shell again, so a void a
//! rebuild moved a little off the input's surface is still probed in its
//! middle; 1e-3 of `diagonal` in front when the segment meets nothing.
std::vector<Vec3> points_in_void(const Mesh& mesh, const std::vector<uint32_t>& labels, uint32_t shell,
                                 double diagonal) {
    std::vector<std::pair<double, uint32_t>> by_area;
    std::vector<uint32_t> members;
    for (uint32_t i = 0; i < mesh.triangles.size(); ++i)
        if (labels[i] == shell) {
            by_area.push_back({area_of(mesh, mesh.triangles[i]), i});
            members.push_back(i);
        }
    const size_t n = std::min<size_t>(7, by_area.size());
    std::partial_sort(by_area.begin(), by_area.begin() + long(n), by_area.end(),
                      [](auto& a, auto& b) { return a.first > b.first; });
    const auto triangles = triangles_of(mesh, members);
    Tree tree(triangles.begin(), triangles.end());
    std::vector<Vec3> points;
    for (size_t j = 0; j < n; ++j) {
        const auto& t = mesh.triangles[by_area[j].second];
        const Vec3 normal = cross(sub(mesh.vertices[t[1]], mesh.vertices[t[0]]), sub(mesh.vertices[t[2]], mesh.vertices[t[0]]));
        const double length = norm(normal);
        if (!(length > 0)) continue;
        Vec3 centre;
        for (int k = 0; k < 3; ++k)
            centre[k] = (mesh.vertices[t[0]][k] + mesh.vertices[t[1]][k] + mesh.vertices[t[2]][k]) / 3;
        double reach = free_distance(tree, centre, normal, 1e-9 * diagonal);
        if (!std::isfinite(reach)) reach = 2e-3 * diagonal;
        Vec3 p;
        for (int k = 0; k < 3; ++k) p[k] = centre[k] + 0.5 * reach * normal[k] / length;
        points.push_back(p);
    }
    return points;
}

std::string option(int argc, char** argv, const std::string& name, const std::string& fallback = "") {
    for (int i = 0; i + 1 < argc; ++i)
        if (name == argv[i]) return argv[i + 1];
    return fallback;
}
bool flag(int argc, char** argv, const std::string& name) {
    for (int i = 0; i < argc; ++i)
        if (name == argv[i]) return true;
    return false;
}

constexpr size_t kSamples = 40000;  // area samples per surface: ~0.5% miss chance per 1/8000 of the area

json check_solid(int argc, char** argv) {
    const std::string path = argv[2];
    const Mesh mesh = read_stl_as_stored(path);
    std::vector<uint32_t> labels;
    std::vector<int> sign;
    json out = validity(mesh, labels, sign);
    out["file"] = path;
    const Box box = box_of(mesh);
    out["diagonal"] = box.diagonal();
    const std::string reference = option(argc, argv, "--reference");
    if (!reference.empty()) {
        const Mesh input = read_input(reference, std::stod(option(argc, argv, "--fit", "0")));
        const auto input_triangles = triangles_of(input, all_triangles(input));
        const auto output_triangles = triangles_of(mesh, all_triangles(mesh));
        out["input_diagonal"] = box_of(input).diagonal();
        out["input_to_output"] =
            distance_json(distances(surface_samples(input, all_triangles(input), kSamples, true), output_triangles));
        out["output_to_input"] =
            distance_json(distances(surface_samples(mesh, all_triangles(mesh), kSamples, true), input_triangles));
    }
    if (flag(argc, argv, "--cavity-wall") && out["valid"].get<bool>()) {
        const auto volume = shell_volumes(mesh, labels, sign.size());
        // A void shell lying on the input's surface (the median distance of
        // its vertices to it under 1% of the diagonal: kept as it was, or as
        // a repair rebuilt it, while a cavity made lies a wall deep) whose
        // inside is outside the input (|winding number| under 1/2, so an
        // input stored inside out reads the same, at most
        // points just inside it: a soup's inner triangles may lie near a
        // cavity made, but do not enclose it) is the input's own void: the
        // cavities made are the others, and their wall is measured to the
        // outer shells and the input's voids alike.
        std::vector<char> made(volume.size(), 0);
        for (size_t s = 0; s < volume.size(); ++s) made[s] = volume[s] < 0;
        size_t own_voids = 0;
        if (!reference.empty()) {
            const Mesh input = read_input(reference, std::stod(option(argc, argv, "--fit", "0")));
            const auto input_triangles = triangles_of(input, all_triangles(input));
            Tree input_tree(input_triangles.begin(), input_triangles.end());
            input_tree.accelerate_distance_queries();
            std::vector<std::vector<double>> depth(volume.size());
            std::vector<char> seen(mesh.vertices.size(), 0);
            for (size_t i = 0; i < mesh.triangles.size(); ++i) {
                if (!made[labels[i]]) continue;
                for (uint32_t v : mesh.triangles[i]) {
                    if (seen[v]) continue;
                    seen[v] = 1;
                    const Vec3& p = mesh.vertices[v];
                    depth[labels[i]].push_back(std::sqrt(input_tree.squared_distance(Kernel::Point_3(p[0], p[1], p[2]))));
                }
            }
            for (size_t s = 0; s < volume.size(); ++s) {
                if (!made[s] || depth[s].empty()) continue;
                std::nth_element(depth[s].begin(), depth[s].begin() + long(depth[s].size() / 2), depth[s].end());
                if (depth[s][depth[s].size() / 2] >= 0.01 * box.diagonal()) continue;
                int outside = 0, inside = 0;
                for (const Vec3& p : points_in_void(mesh, labels, uint32_t(s), box.diagonal()))
                    (std::abs(winding_number(input, p)) < 0.5 ? outside : inside) += 1;
                if (outside > inside) {
                    made[s] = 0;
                    ++own_voids;
                }
            }
        }
        std::vector<uint32_t> cavity, outer;
        size_t cavities = 0;
        for (size_t s = 0; s < volume.size(); ++s) cavities += made[s];
        for (uint32_t i = 0; i < mesh.triangles.size(); ++i) (made[labels[i]] ? cavity : outer).push_back(i);
        out["cavity_shells"] = cavities;
        out["input_void_shells"] = own_voids;
        if (!cavity.empty()) {
            // The wall as built: from every cavity point to the nearest outer surface.
            const auto points = surface_samples(mesh, cavity, kSamples, true);
            Tree tree;
            const auto targets = triangles_of(mesh, outer);
            tree.insert(targets.begin(), targets.end());
            tree.accelerate_distance_queries();
            std::vector<double> r;
            for (const Vec3& p : points) r.push_back(std::sqrt(tree.squared_distance(Kernel::Point_3(p[0], p[1], p[2]))));
            std::sort(r.begin(), r.end());
            out["wall"] = {{"min", r.front()}, {"p01", r[r.size() / 100]}, {"median", r[r.size() / 2]},
                           {"max", r.back()}, {"samples", r.size()}};
        }
    }
    const std::string direction = option(argc, argv, "--direction");
    if (!direction.empty()) {
        Vec3 d;
        if (std::sscanf(direction.c_str(), "%lf,%lf,%lf", &d[0], &d[1], &d[2]) != 3) throw Failure("bad --direction");
        const auto lines = fabvdb::test::check_double_height_field(mesh, d, 150);
        out["height_field"] = {{"lines", lines.lines},
                               {"lines_over_two", lines.lines_over_two},
                               {"odd_lines", lines.odd_lines},
                               {"max_crossings", lines.max_crossings}};
    }
    return out;
}

json check_input(int argc, char** argv) {
    Mesh mesh = read_input(argv[2], std::stod(option(argc, argv, "--fit", "0")));
    json out;
    out["file"] = argv[2];
    // Judged as a binary STL would store it: corners rounded to float and welded.
    mesh = fabvdb::test::stored_as_float(mesh);
    std::map<Vec3, uint32_t> index;
    std::vector<uint32_t> remap(mesh.vertices.size());
    Mesh welded;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        auto [it, added] = index.emplace(mesh.vertices[v], uint32_t(welded.vertices.size()));
        if (added) welded.vertices.push_back(mesh.vertices[v]);
        remap[v] = it->second;
    }
    for (auto t : mesh.triangles) welded.triangles.push_back({remap[t[0]], remap[t[1]], remap[t[2]]});
    std::vector<uint32_t> labels;
    std::vector<int> sign;
    json v = validity(welded, labels, sign);
    v["file"] = argv[2];
    v["diagonal"] = box_of(welded).diagonal();
    return v;
}

json check_cover(int argc, char** argv) {
    const Mesh input = read_input(argv[2], std::stod(option(argc, argv, "--fit", "0")));
    std::vector<std::array<double, 4>> exempt;  // balls: x, y, z, radius
    const double far = std::stod(option(argc, argv, "--far", "0"));
    std::vector<Triangle3> parts;
    std::vector<Mesh> part_meshes;
    for (int i = 3; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--fit" || arg == "--exempt" || arg == "--far" || arg == "--gap") {
            if (arg == "--exempt" && i + 1 < argc) {
                std::array<double, 4> ball;
                if (std::sscanf(argv[i + 1], "%lf,%lf,%lf,%lf", &ball[0], &ball[1], &ball[2], &ball[3]) != 4)
                    throw Failure("bad --exempt (X,Y,Z,R)");
                exempt.push_back(ball);
            }
            ++i;
            continue;
        }
        part_meshes.push_back(read_stl_as_stored(arg));
        const auto t = triangles_of(part_meshes.back(), all_triangles(part_meshes.back()));
        parts.insert(parts.end(), t.begin(), t.end());
    }
    if (parts.empty()) throw Failure("no part surface to measure against");
    const size_t count = part_meshes.size();
    const double diagonal = box_of(input).diagonal();
    // Area samples for the mean (vertices would weight dense regions), all for the max.
    std::vector<uint32_t> area_source, vertex_source;
    const auto area = surface_samples(input, all_triangles(input), kSamples, false, &area_source);
    const auto with_vertices = surface_samples(input, all_triangles(input), kSamples, true, &vertex_source);
    std::vector<double> area_distance, vertex_distance;
    const Distances mean = distances(area, parts, &area_distance);
    const Distances max = distances(with_vertices, parts, &vertex_distance);
    json out = {{"parts", count},
                {"diagonal", diagonal},
                {"all_surface",
                 {{"max", max.max},
                  {"max_at", {max.max_at[0], max.max_at[1], max.max_at[2]}},
                  {"max_ratio", max.max / diagonal},
                  {"mean_ratio", mean.mean / diagonal}}}};
    // The figures proper leave out input surface enclosed by the input's own
    // solid (a shell inside another) or facing it across a slit narrower than
    // 0.3 mm (a mold blade that thin is under the narrowest recess resin
    // printing reproduces): no cast part can carry it. Only points farther
    // than 0.05% of the diagonal can change them, and only they are tested.
    const double floor = 5e-4 * diagonal, step = 1e-4 * diagonal;
    const double gap = std::max(0.3, std::stod(option(argc, argv, "--gap", "0")));
    const std::vector<Triangle3> input_triangles = triangles_of(input, all_triangles(input));
    const Tree input_tree(input_triangles.begin(), input_triangles.end());
    std::vector<char> area_in = enclosed(input, input_tree, area, area_source, area_distance, floor, step, gap);
    std::vector<char> vertex_in =
        enclosed(input, input_tree, with_vertices, vertex_source, vertex_distance, floor, step, gap);
    // Samples in an exempt ball (a drilled hole's mouth) are left out too.
    const auto in_ball = [&](const Vec3& p) {
        for (const auto& b : exempt)
            if (std::hypot(p[0] - b[0], p[1] - b[1], p[2] - b[2]) <= b[3]) return true;
        return false;
    };
    for (size_t i = 0; i < area.size(); ++i) area_in[i] = area_in[i] || in_ball(area[i]);
    for (size_t i = 0; i < with_vertices.size(); ++i) vertex_in[i] = vertex_in[i] || in_ball(with_vertices[i]);
    double sum = 0, top = 0;
    size_t kept = 0, left_out = 0;
    Vec3 top_at = with_vertices.empty() ? Vec3{0, 0, 0} : with_vertices[0];
    size_t beyond = 0;
    for (size_t i = 0; i < area.size(); ++i) {
        if (area_in[i]) continue;
        sum += area_distance[i];
        beyond += far > 0 && area_distance[i] > far;
        ++kept;
    }
    for (size_t i = 0; i < with_vertices.size(); ++i) {
        if (vertex_in[i]) {
            ++left_out;
            continue;
        }
        if (vertex_distance[i] > top) top = vertex_distance[i], top_at = with_vertices[i];
    }
    const double mean_kept = kept ? sum / kept : 0;
    out["enclosed_samples"] = left_out;
    out["max"] = top;
    out["max_at"] = {top_at[0], top_at[1], top_at[2]};
    out["mean"] = mean_kept;
    out["max_ratio"] = top / diagonal;
    out["mean_ratio"] = mean_kept / diagonal;
    if (far > 0) out["far_fraction"] = kept ? double(beyond) / double(kept) : 0.0;
    double winding = 0, nearest = std::numeric_limits<double>::infinity();
    size_t nearest_part = 0;
    for (size_t k = 0; k < count; ++k) {
        winding += winding_number(part_meshes[k], top_at);
        const Distances d = distances({top_at}, triangles_of(part_meshes[k], all_triangles(part_meshes[k])));
        if (d.max < nearest) nearest = d.max, nearest_part = k;
    }
    out["max_part"] = nearest_part;
    out["max_side"] = winding >= 0.5 ? "buried" : "uncovered";
    return out;
}

//! `mesh` as an OBJ file, every vertex in full precision, every triangle
//! reversed when `reverse`.
json write_obj(const Mesh& mesh, const std::string& path, bool reverse) {
    std::ofstream out(path);
    if (!out) throw Failure("cannot write " + path);
    out.precision(17);
    for (const Vec3& p : mesh.vertices) out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    for (const auto& t : mesh.triangles)
        out << "f " << t[0] + 1 << ' ' << t[reverse ? 2 : 1] + 1 << ' ' << t[reverse ? 1 : 2] + 1 << '\n';
    out.close();
    if (!out) throw Failure("cannot write " + path);
    return {{"file", path}, {"triangles", mesh.triangles.size()}, {"vertices", mesh.vertices.size()}};
}

//! The input turned inside out, as an OBJ file: every vertex as read (so
//! `--fit` scales it alike) in full precision, every triangle reversed.
json flip_input(int argc, char** argv) {
    if (argc < 4) throw Failure("usage: corpus_check flip IN OUT.obj");
    return write_obj(read_input(argv[2], 0), argv[3], true);
}

//! The input as fabvdb's readers give it, scaled as `--fit LEN` scales it
//! (none without), as an OBJ file: the same triangles in the same order, for
//! a program that cannot read every corpus format (Blender, bench/check_vs_blender.sh).
json copy_input(int argc, char** argv) {
    if (argc < 4) throw Failure("usage: corpus_check obj IN OUT.obj [--fit LEN]");
    return write_obj(read_input(argv[2], std::stod(option(argc, argv, "--fit", "0"))), argv[3], false);
}

json check_decomposition_file(const std::string& path) {
    json out;
    std::vector<double> areas;
    testing::RegisterTest("corpus", "decomposition", nullptr, nullptr, __FILE__, __LINE__, [&]() -> testing::Test* {
        struct Run : testing::Test {
            std::string path;
            std::vector<double>* areas;
            void TestBody() override { *areas = fabvdb::test::check_decomposition(fabvdb::test::read_decomposition(path)); }
        };
        auto* run = new Run;
        run->path = path;
        run->areas = &areas;
        return run;
    });
    // gtest prints its expectations' failures on stdout: send them to stderr.
    testing::GTEST_FLAG(brief) = true;
    std::fflush(stdout);
    const int saved = dup(1);
    dup2(2, 1);
    const int failed = RUN_ALL_TESTS();
    std::fflush(stdout);
    dup2(saved, 1);
    out["file"] = path;
    out["valid"] = failed == 0;
    out["parts"] = areas.size();
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::cerr << "usage: corpus_check solid|input|cover|flip|obj|decomposition FILE [options] (see the top of "
                     "bench/corpus/corpus_check.cpp)\n";
        return 1;
    }
    const std::string mode = argv[1];
    try {
        json out;
        if (mode == "solid") out = check_solid(argc, argv);
        else if (mode == "input") out = check_input(argc, argv);
        else if (mode == "cover") out = check_cover(argc, argv);
        else if (mode == "flip") out = flip_input(argc, argv);
        else if (mode == "obj") out = copy_input(argc, argv);
        else if (mode == "decomposition") {
            int none = 1;
            testing::InitGoogleTest(&none, argv);
            out = check_decomposition_file(argv[2]);
        } else {
            std::cerr << "corpus_check: unknown mode " << mode << "\n";
            return 1;
        }
        std::cout << out.dump() << "\n";
        return 0;
    } catch (const std::exception& e) {
        std::cout << json{{"error", e.what()}}.dump() << "\n";
        return 2;
    }
}
