//! The fidelity gate (see input_fidelity.h): area samples of the input to
//! the output's surface, the far ones told apart by the input's winding
//! number, and the enclosed volumes compared.
#include "volume/input_fidelity.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <sstream>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "core/error.h"
#include "core/figure_text.h"
#include "core/vec3_ops.h"
#include "volume/closest_point_on_triangle.h"
#include "volume/orient_soup.h"
#include "volume/surface_distance.h"
#include "volume/winding_number.h"

namespace fabvdb::volume {

namespace {

struct Sample {
    Vec3 point;
    Vec3 normal;  // unit; zero on a degenerate triangle
    uint32_t triangle;
};

//! kFidelitySamples points uniform by area over the input's triangles.
std::vector<Sample> area_samples(const Mesh& mesh) {
    std::vector<double> cumulative(mesh.triangles.size());
    double total = 0.0;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        total += triangle_area(mesh, mesh.triangles[t]);
        cumulative[t] = total;
    }
    std::vector<Sample> samples;
    if (!(total > 0.0)) return samples;
    std::mt19937_64 random(20261207);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    samples.reserve(kFidelitySamples);
    for (size_t i = 0; i < kFidelitySamples; ++i) {
        const double at = unit(random) * total;
        const size_t t = size_t(std::upper_bound(cumulative.begin(), cumulative.end(), at) - cumulative.begin());
        const size_t index = std::min(t, mesh.triangles.size() - 1);
        const Triangle& tri = mesh.triangles[index];
        const Vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
        double u = unit(random), v = unit(random);
        if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
        const Vec3 n = cross(b - a, c - a);
        const double length = norm(n);
        samples.push_back({a + u * (b - a) + v * (c - a), length > 0.0 ? (1.0 / length) * n : Vec3{0, 0, 0},
                           uint32_t(index)});
    }
    return samples;
}

//! A triangle's corners as a float file stores them, hashed in no order:
//! the same for a triangle an output kept from the input (rounded to floats
//! or not, turned round or not); 64 bits make a collision negligible.
uint64_t corner_hash(const Mesh& mesh, const Triangle& t) {
    uint64_t sum = 0;
    for (uint32_t v : t) {
        uint64_t h = 0x9e3779b97f4a7c15ull;
        for (double x : mesh.vertices[v]) {
            const float f = float(x);
            uint32_t bits;
            std::memcpy(&bits, &f, sizeof bits);
            h = (h ^ bits) * 0xbf58476d1ce4e5b9ull;
            h ^= h >> 31;
        }
        sum += h;
    }
    return sum;
}

//! Which of the input's triangles the output kept (the same corners as
//! floats), and the output's triangles it did not keep (indices).
struct KeptTriangles {
    std::vector<char> input_kept;
    std::vector<uint32_t> output_added;
};

KeptTriangles kept_triangles(const Mesh& input, const Mesh& output) {
    std::vector<std::pair<uint64_t, uint32_t>> input_hashes(input.triangles.size());
    tbb::parallel_for(size_t(0), input.triangles.size(),
                      [&](size_t t) { input_hashes[t] = {corner_hash(input, input.triangles[t]), uint32_t(t)}; });
    tbb::parallel_sort(input_hashes.begin(), input_hashes.end());
    // Per output triangle, where its hash starts among the input's (or none).
    constexpr size_t none = std::numeric_limits<size_t>::max();
    std::vector<size_t> match(output.triangles.size(), none);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, output.triangles.size(), 4096),
                      [&](const tbb::blocked_range<size_t>& r) {
                          for (size_t t = r.begin(); t != r.end(); ++t) {
                              const uint64_t h = corner_hash(output, output.triangles[t]);
                              const auto at = std::lower_bound(input_hashes.begin(), input_hashes.end(),
                                                               std::pair<uint64_t, uint32_t>{h, 0});
                              if (at != input_hashes.end() && at->first == h) match[t] = size_t(at - input_hashes.begin());
                          }
                      });
    KeptTriangles kept;
    kept.input_kept.assign(input.triangles.size(), 0);
    for (uint32_t t = 0; t < output.triangles.size(); ++t) {
        if (match[t] == none) {
            kept.output_added.push_back(t);
            continue;
        }
        for (size_t k = match[t]; k < input_hashes.size() && input_hashes[k].first == input_hashes[match[t]].first; ++k)
            kept.input_kept[input_hashes[k].second] = 1;
    }
    return kept;
}

//! The radical inverse of i in `base`: the Halton sequence's coordinate.
double radical_inverse(size_t i, unsigned base) {
    double inverse = 0.0, digit = 1.0 / base;
    for (; i > 0; i /= base, digit /= base) inverse += double(i % base) * digit;
    return inverse;
}

//! Triangles of a mesh, for the distance to the nearest of them within
//! `reach`. Those no wider than twice `reach` (a level set's, a voxel
//! across) are bucketed by the cell of their centroid, cells as wide as
//! `reach` plus the farthest any of their corners lies from its centroid:
//! every such triangle with a point within `reach` of p has its centroid in
//! the 27 cells around p's. Wider ones (a mesh's own, cut or kept) go to an
//! AABB tree. Costs a sort of the narrow triangles by cell, a tree of the
//! wide ones.
class NearbyTriangles {
public:
    NearbyTriangles(const Mesh& mesh, const std::vector<uint32_t>& triangles, double reach)
        : mesh_(mesh), reach_(reach) {
        std::vector<Vec3> centroids(triangles.size());
        std::vector<double> spreads(triangles.size());
        tbb::parallel_for(size_t(0), triangles.size(), [&](size_t k) {
            const Triangle& t = mesh.triangles[triangles[k]];
            centroids[k] = (1.0 / 3.0) * (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]);
            double spread = 0.0;
            for (uint32_t v : t) spread = std::max(spread, squared_distance(centroids[k], mesh.vertices[v]));
            spreads[k] = std::sqrt(spread);
        });
        lo_ = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
               std::numeric_limits<double>::infinity()};
        std::vector<size_t> narrow;
        Mesh wide{{}, {}};
        for (size_t k = 0; k < triangles.size(); ++k) {
            if (spreads[k] > 2.0 * reach) {
                wide.triangles.push_back(mesh.triangles[triangles[k]]);
                continue;
            }
            narrow.push_back(k);
            spread_ = std::max(spread_, spreads[k]);
            for (int a = 0; a < 3; ++a) lo_[a] = std::min(lo_[a], centroids[k][a]);
        }
        if (!wide.triangles.empty()) {
            wide.vertices = mesh.vertices;
            wide_ = std::make_unique<SurfaceDistance>(wide);
        }
        cell_ = reach + spread_;
        cells_.resize(narrow.size());
        tbb::parallel_for(size_t(0), narrow.size(), [&](size_t j) {
            cells_[j] = {key(cell_of(centroids[narrow[j]])), triangles[narrow[j]]};
        });
        tbb::parallel_sort(cells_.begin(), cells_.end());
    }

    //! The distance from p to the nearest of the triangles when it is at
    //! most `reach`, else infinity. Its own cell first; a neighbour only
    //! when its triangles, none farther than the spread from a centroid in
    //! it, may come nearer than the best so far.
    double distance_within(const Vec3& p) const {
        double best = wide_ ? wide_->nearest(p).distance : std::numeric_limits<double>::infinity();
        if (!cells_.empty()) {
            const std::array<int64_t, 3> centre = cell_of(p);
            const openvdb::Vec3d q(p[0], p[1], p[2]);
            for (int ring = 0; ring <= 1; ++ring)
                for (int64_t dx = -ring; dx <= ring; ++dx)
                    for (int64_t dy = -ring; dy <= ring; ++dy)
                        for (int64_t dz = -ring; dz <= ring; ++dz) {
                            if (ring == 1 && dx == 0 && dy == 0 && dz == 0) continue;
                            const std::array<int64_t, 3> cell{centre[0] + dx, centre[1] + dy, centre[2] + dz};
                            if (cell[0] < 0 || cell[1] < 0 || cell[2] < 0) continue;
                            if (ring == 1 && box_distance(p, cell) - spread_ >= std::min(best, reach_)) continue;
                            best = std::min(best, nearest_in(cell, q));
                        }
        }
        return best <= reach_ ? best : std::numeric_limits<double>::infinity();
    }

private:
    double nearest_in(const std::array<int64_t, 3>& cell, const openvdb::Vec3d& q) const {
        double best = std::numeric_limits<double>::infinity();
        const uint64_t k = key(cell);
        for (auto at = std::lower_bound(cells_.begin(), cells_.end(), std::pair<uint64_t, uint32_t>{k, 0});
             at != cells_.end() && at->first == k; ++at) {
            const Triangle& t = mesh_.triangles[at->second];
            const Vec3 &a = mesh_.vertices[t[0]], &b = mesh_.vertices[t[1]], &c = mesh_.vertices[t[2]];
            const openvdb::Vec3d on =
                closest_point_on_triangle(q, {a[0], a[1], a[2]}, {b[0], b[1], b[2]}, {c[0], c[1], c[2]}).point;
            best = std::min(best, (q - on).length());
        }
        return best;
    }
    std::array<int64_t, 3> cell_of(const Vec3& p) const {
        std::array<int64_t, 3> cell;
        for (int a = 0; a < 3; ++a) cell[a] = int64_t(std::floor((p[a] - lo_[a]) / cell_)) + 1;
        return cell;
    }
    //! 21 bits an axis: the cells are at least reach wide, and reach is at
    //! least 1e-4 of the diagonal, so an axis spans about 1e4 of them at
    //! most; a key that wraps only adds candidates.
    //! From p to the box of a cell (0 inside it).
    double box_distance(const Vec3& p, const std::array<int64_t, 3>& cell) const {
        double squared = 0.0;
        for (int a = 0; a < 3; ++a) {
            const double lo = lo_[a] + double(cell[a] - 1) * cell_, hi = lo + cell_;
            const double out = std::max({lo - p[a], 0.0, p[a] - hi});
            squared += out * out;
        }
        return std::sqrt(squared);
    }
    static uint64_t key(const std::array<int64_t, 3>& cell) {
        const uint64_t mask = (uint64_t(1) << 21) - 1;
        return (uint64_t(cell[0]) & mask) << 42 | (uint64_t(cell[1]) & mask) << 21 | (uint64_t(cell[2]) & mask);
    }

    const Mesh& mesh_;
    double reach_;
    double spread_ = 0.0;  // the farthest a corner of a narrow triangle lies from its centroid
    double cell_ = 1.0;
    Vec3 lo_{0, 0, 0};
    std::vector<std::pair<uint64_t, uint32_t>> cells_;  // (cell key, narrow triangle), sorted
    std::unique_ptr<SurfaceDistance> wide_;              // the wide triangles, if any
};

}  // namespace

FidelityLimits exact_limits(const Mesh& input) {
    FidelityLimits limits;
    limits.distance = 1e-4 * bounding_box(input).diagonal();
    limits.far_share = 0.005;
    limits.volume = false;
    return limits;
}

FidelityLimits voxel_limits(double voxel) {
    FidelityLimits limits;
    limits.distance = 2.0 * voxel;
    limits.far_share = 0.02;
    return limits;
}

void require_faithful(const Fidelity& fidelity, const std::string& input_name, const std::string& what) {
    if (fidelity.passed) return;
    throw Error(FABVDB_ERR_INTERNAL, input_name + ": the " + what + " is not the input's model: " + fidelity.defect +
                                         "; nothing was written");
}

namespace {

Fidelity measure_against(const Mesh& input, const Mesh& output, const FidelityLimits& limits, Progress& progress);

}  // namespace

Fidelity measure_fidelity(const Mesh& input, const Mesh& output, const FidelityLimits& limits,
                          Progress& progress) {
    progress.stage("fidelity to the input");
    Fidelity result = measure_against(input, output, limits, progress);
    if (result.passed || input.triangles.empty() || output.triangles.empty()) return result;
    // Shells wound every which way have no one solid by their winding
    // number (an inside-out box overlapping an outward one cancels it): the
    // input oriented as the repair orients it (orient_soup.h) decides.
    const Mesh oriented = orient_soup(input, progress);
    if (oriented.triangles.empty()) return result;
    Fidelity again = measure_against(oriented, output, limits, progress);
    if (!again.passed) return result;
    again.oriented_reference = true;
    return again;
}

namespace {

Fidelity measure_against(const Mesh& input, const Mesh& output, const FidelityLimits& limits, Progress& progress) {
    Fidelity result;
    if (input.triangles.empty() || output.triangles.empty()) {
        result.passed = false;
        result.defect = output.triangles.empty() ? "the output is empty" : "the input has no surface";
        return result;
    }
    const std::vector<Sample> samples = area_samples(input);
    result.samples = samples.size();
    const BoundingBox box = bounding_box(input);
    const double diagonal = box.diagonal();
    const double probe = 1e-4 * diagonal;

    // A first distance per sample, at no more cost than the output needs: 0
    // on a triangle it kept from the input, else the distance to the
    // triangles it did not keep when that is within the limit (an upper
    // bound, exact when it kept none). Samples beyond it are measured
    // exactly on the whole output where they count.
    std::vector<double> distance(samples.size(), 0.0);
    KeptTriangles kept = kept_triangles(input, output);
    const NearbyTriangles nearby(output, kept.output_added, limits.distance);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, samples.size(), 256), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i != r.end(); ++i)
            if (!kept.input_kept[samples[i].triangle]) distance[i] = nearby.distance_within(samples[i].point);
    });
    progress.check();
    progress.update(0.2);

    // Samples that may be far: those in an exempt ball, on inner faces or
    // on the wall of a narrow slit are left out; the others are measured
    // exactly.
    std::unique_ptr<WindingNumber> winding;
    const auto winding_tree = [&]() -> const WindingNumber& {
        if (!winding) winding = std::make_unique<WindingNumber>(input);
        return *winding;
    };
    const auto exempt = [&](const Vec3& p) {
        return std::any_of(limits.exempt.begin(), limits.exempt.end(), [&](const std::pair<Vec3, double>& ball) {
            return squared_distance(p, ball.first) <= ball.second * ball.second;
        });
    };
    std::vector<size_t> unsure;
    std::vector<char> bounds(samples.size(), 1), sheet(samples.size(), 0);
    for (size_t i = 0; i < samples.size(); ++i) {
        if (!(distance[i] > limits.distance)) continue;
        if (exempt(samples[i].point))
            bounds[i] = 0;
        else
            unsure.push_back(i);
    }
    if (!unsure.empty()) {
        const WindingNumber& w = winding_tree();
        tbb::parallel_for(tbb::blocked_range<size_t>(0, unsure.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t k = r.begin(); k != r.end(); ++k) {
                const Sample& s = samples[unsure[k]];
                const double front = std::abs(w(s.point + probe * s.normal));
                const double back = std::abs(w(s.point - probe * s.normal));
                if (front >= 0.5 && back >= 0.5) {  // an inner face
                    bounds[unsure[k]] = 0;
                    continue;
                }
                // No clear solid on either side (a sheet, whose winding
                // number is about ±½ on its two sides; a scan's loose flap):
                // surface the output must hold all the same.
                if (std::max(front, back) < 0.75) {
                    sheet[unsure[k]] = 1;
                    continue;
                }
                // The wall of a slit narrower than the far distance, whose
                // other side the solid holds again within it, may close.
                const double open = front >= 0.5 ? -1.0 : 1.0;  // towards the slit
                for (double along : {0.5 * limits.distance, limits.distance})
                    if (std::abs(w(s.point + open * along * s.normal)) >= 0.5) bounds[unsure[k]] = 0;
            }
        });
        progress.check();
        unsure.erase(std::remove_if(unsure.begin(), unsure.end(), [&](size_t i) { return !bounds[i]; }),
                     unsure.end());
    }
    progress.update(0.5);
    if (!unsure.empty()) {
        const SurfaceDistance surface(output);
        tbb::parallel_for(tbb::blocked_range<size_t>(0, unsure.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
            if (progress.cancelled()) return;
            for (size_t k = r.begin(); k != r.end(); ++k)
                distance[unsure[k]] = surface.nearest(samples[unsure[k]].point).distance;
        });
    }
    progress.check();
    progress.update(0.7);
    size_t counted = 0, far_counted = 0, far_sheet = 0;
    double sum = 0.0;
    for (size_t i = 0; i < samples.size(); ++i) {
        if (!bounds[i]) {
            ++result.left_out;
            continue;
        }
        ++counted;
        sum += distance[i];
        result.max = std::max(result.max, distance[i]);
        far_counted += distance[i] > limits.distance;
        far_sheet += sheet[i] && distance[i] > limits.distance;
    }
    result.mean = counted ? sum / double(counted) : 0.0;
    result.far_share = counted ? double(far_counted) / double(counted) : 0.0;
    result.far_sheet_share = counted ? double(far_sheet) / double(counted) : 0.0;
    std::ostringstream defect;
    if (result.far_share > limits.far_share) {
        defect << figure_text(100.0 * result.far_share) << "% of the input's surface lies farther than "
               << figure_text(limits.distance) << " mm from it (at most " << figure_text(result.max) << " mm)";
        if (far_sheet > 0)
            defect << ", " << figure_text(100.0 * result.far_sheet_share)
                   << "% on surface with no clear solid on either side (an open sheet, a loose flap)";
    }

    if (limits.volume) {
        const WindingNumber& w = winding_tree();
        const Vec3 size = box.max - box.min;
        std::atomic<size_t> inside{0}, unclear{0};
        tbb::parallel_for(tbb::blocked_range<size_t>(0, kFidelityVolumePoints, 64),
                          [&](const tbb::blocked_range<size_t>& r) {
                              size_t here = 0, vague = 0;
                              for (size_t i = r.begin(); i != r.end(); ++i) {
                                  const Vec3 unit{radical_inverse(i + 1, 2), radical_inverse(i + 1, 3),
                                                  radical_inverse(i + 1, 5)};
                                  const Vec3 p{box.min[0] + unit[0] * size[0], box.min[1] + unit[1] * size[1],
                                               box.min[2] + unit[2] * size[2]};
                                  const double magnitude = std::abs(w(p));
                                  here += magnitude >= 0.5;
                                  vague += magnitude > 0.25 && magnitude < 0.75;
                              }
                              inside += here;
                              unclear += vague;
                          });
        progress.check();
        // Where a tenth of the solid's points have a winding number between
        // ¼ and ¾ (a soup wound every which way, a scan's missing side), it
        // does not tell the solid's volume: not compared.
        result.volume_compared = double(unclear) <= 0.1 * double(std::max<size_t>(inside, 1));
        const double box_volume = size[0] * size[1] * size[2];
        const double n = double(kFidelityVolumePoints);
        const double share = std::clamp(double(inside) / n, 1.0 / n, 1.0 - 1.0 / n);
        double area = 0.0;
        for (const Triangle& t : input.triangles) area += triangle_area(input, t);
        result.input_volume = double(inside) / n * box_volume;
        result.output_volume = signed_volume(output);
        result.volume_tolerance = limits.distance * area + 4.0 * box_volume * std::sqrt(share * (1.0 - share) / n);
        if (result.volume_compared &&
            std::abs(result.output_volume - result.input_volume) > result.volume_tolerance) {
            if (defect.tellp() > 0) defect << "; ";
            defect << "it encloses " << figure_text(result.output_volume) << " mm³ where the input encloses about "
                   << figure_text(result.input_volume) << " mm³";
        }
    }
    result.defect = defect.str();
    result.passed = result.defect.empty();
    progress.update(1.0);
    return result;
}

}  // namespace

}  // namespace fabvdb::volume
