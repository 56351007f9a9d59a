//! The voxel sand-pile reference simulation (see sandpile_simulation.h).
#include "powder/sandpile_simulation.h"

#include <cmath>
#include <cstdint>
#include <string>

#include <Eigen/Geometry>
#include <tbb/parallel_for.h>

#include "core/error.h"

namespace fabvdb::powder {

namespace {

enum Cell : uint8_t { kFree = 0, kSolid = 1, kOutside = 2, kGrain = 3 };
constexpr int kMaxWindow = 16;

struct Drill {
    Eigen::Vector3d center, axis;
    double radius, depth;
    //! Within the drill widened by `margin` sideways.
    bool contains(const Eigen::Vector3d& p, double margin = 0.0) const {
        const Eigen::Vector3d v = p - center;
        const double t = v.dot(axis);
        const double r = radius + margin;
        return t >= -radius && t <= depth && (v - t * axis).squaredNorm() <= r * r;
    }
};

//! The part voxelised in a frame whose third axis points up.
class Frame {
public:
    Frame(const openvdb::FloatGrid& solid, const std::vector<Drill>& drills, const Eigen::Vector3d& gravity,
          double h, std::vector<char>* cavity_fill)
        : h_(h) {
        const Eigen::Vector3d up = -gravity.normalized();
        const Eigen::Vector3d e1 = up.unitOrthogonal(), e2 = up.cross(e1);
        axes_.col(0) = e1;
        axes_.col(1) = e2;
        axes_.col(2) = up;
        const openvdb::CoordBBox box = solid.evalActiveVoxelBoundingBox();
        Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL), hi = -lo;
        for (int corner = 0; corner < 8; ++corner) {
            const openvdb::Coord ijk((corner & 1) ? box.max().x() : box.min().x(),
                                     (corner & 2) ? box.max().y() : box.min().y(),
                                     (corner & 4) ? box.max().z() : box.min().z());
            const openvdb::Vec3d w = solid.indexToWorld(ijk);
            const Eigen::Vector3d q = axes_.transpose() * Eigen::Vector3d(w[0], w[1], w[2]);
            lo = lo.cwiseMin(q);
            hi = hi.cwiseMax(q);
        }
        // The drills reach past the outer surface: the frame holds them whole.
        for (const Drill& drill : drills)
            for (const Eigen::Vector3d& end : {Eigen::Vector3d(drill.center - drill.radius * drill.axis),
                                               Eigen::Vector3d(drill.center + drill.depth * drill.axis)}) {
                const Eigen::Vector3d q = axes_.transpose() * end;
                lo = lo.cwiseMin(q - Eigen::Vector3d::Constant(drill.radius));
                hi = hi.cwiseMax(q + Eigen::Vector3d::Constant(drill.radius));
            }
        lo -= Eigen::Vector3d::Constant(3 * h);
        hi += Eigen::Vector3d::Constant(3 * h);
        origin_ = lo;
        n_ = {int((hi.x() - lo.x()) / h) + 1, int((hi.y() - lo.y()) / h) + 1, int((hi.z() - lo.z()) / h) + 1};
        cells_.assign(size_t(n_[0]) * n_[1] * n_[2], kFree);
        std::vector<char> barrier(cells_.size(), 0);
        tbb::parallel_for(0, n_[0], [&](int x) {
            auto accessor = solid.getConstAccessor();
            for (int y = 0; y < n_[1]; ++y)
                for (int z = 0; z < n_[2]; ++z) {
                    const Eigen::Vector3d p = world(x, y, z);
                    const openvdb::Coord ijk = openvdb::Coord::round(solid.worldToIndex(openvdb::Vec3d(p.x(), p.y(), p.z())));
                    // The plug is a little wider than the drill, so an already
                    // drilled part's tunnel, voxelised again, is plugged whole.
                    bool drilled = false, plugged = false;
                    for (const Drill& drill : drills) {
                        drilled = drilled || drill.contains(p);
                        plugged = plugged || drill.contains(p, 2.0 * h);
                    }
                    const size_t i = index(x, y, z);
                    if (accessor.getValue(ijk) < 0.0f && !drilled) cells_[i] = kSolid;
                    barrier[i] = cells_[i] == kSolid || plugged;
                }
        });
        // The outside: what the border reaches with the holes plugged.
        std::vector<size_t> stack;
        for (int x = 0; x < n_[0]; ++x)
            for (int y = 0; y < n_[1]; ++y)
                for (int z = 0; z < n_[2]; ++z)
                    if (x == 0 || y == 0 || z == 0 || x == n_[0] - 1 || y == n_[1] - 1 || z == n_[2] - 1) {
                        const size_t i = index(x, y, z);
                        if (!barrier[i] && cells_[i] == kFree) {
                            cells_[i] = kOutside;
                            stack.push_back(i);
                        }
                    }
        while (!stack.empty()) {
            const size_t i = stack.back();
            stack.pop_back();
            int x, y, z;
            coordinates(i, x, y, z);
            const int step[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
            for (const auto& s : step) {
                const int a = x + s[0], b = y + s[1], c = z + s[2];
                if (!inside(a, b, c)) continue;
                const size_t j = index(a, b, c);
                if (!barrier[j] && cells_[j] == kFree) {
                    cells_[j] = kOutside;
                    stack.push_back(j);
                }
            }
        }
        if (cavity_fill) {
            cavity_fill->assign(cells_.size(), 0);
            for (size_t i = 0; i < cells_.size(); ++i) (*cavity_fill)[i] = cells_[i] == kFree && !barrier[i];
        }
    }

    size_t index(int x, int y, int z) const { return (size_t(x) * n_[1] + y) * n_[2] + z; }
    void coordinates(size_t i, int& x, int& y, int& z) const {
        z = int(i % n_[2]);
        y = int((i / n_[2]) % n_[1]);
        x = int(i / (size_t(n_[2]) * n_[1]));
    }
    bool inside(int x, int y, int z) const {
        return x >= 0 && y >= 0 && z >= 0 && x < n_[0] && y < n_[1] && z < n_[2];
    }
    Eigen::Vector3d world(int x, int y, int z) const {
        return axes_ * (origin_ + h_ * Eigen::Vector3d(x + 0.5, y + 0.5, z + 0.5));
    }
    Eigen::Vector3d world(size_t i) const {
        int x, y, z;
        coordinates(i, x, y, z);
        return world(x, y, z);
    }
    //! The cell holding world point p, or false if p is outside the frame.
    bool cell_of(const Eigen::Vector3d& p, int& x, int& y, int& z) const {
        const Eigen::Vector3d q = (axes_.transpose() * p - origin_) / h_;
        x = int(std::floor(q.x()));
        y = int(std::floor(q.y()));
        z = int(std::floor(q.z()));
        return inside(x, y, z);
    }

    const std::array<int, 3>& size() const { return n_; }
    std::vector<uint8_t>& cells() { return cells_; }
    const std::vector<uint8_t>& cells() const { return cells_; }

private:
    double h_;
    Eigen::Matrix3d axes_;
    Eigen::Vector3d origin_;
    std::array<int, 3> n_{0, 0, 0};
    std::vector<uint8_t> cells_;
};

//! Places a grain at world point p, or in the nearest free cell around it.
bool place_grain(Frame& frame, const Eigen::Vector3d& p, std::vector<size_t>& grains) {
    int x, y, z;
    if (!frame.cell_of(p, x, y, z)) return false;
    auto& cells = frame.cells();
    for (int radius = 0; radius <= 3; ++radius)
        for (int dz = -radius; dz <= radius; ++dz)
            for (int dy = -radius; dy <= radius; ++dy)
                for (int dx = -radius; dx <= radius; ++dx) {
                    if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != radius) continue;
                    if (!frame.inside(x + dx, y + dy, z + dz)) continue;
                    const size_t i = frame.index(x + dx, y + dy, z + dz);
                    if (cells[i] != kFree) continue;
                    cells[i] = kGrain;
                    grains.push_back(i);
                    return true;
                }
    return false;
}

constexpr int kDirections[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, -1}, {1, -1}, {-1, 1}};

//! How far the ground may drop along each of the 8 directions before a grain
//! topples. Heights are whole cells: the ground s steps away is too low when
//! it lies more than s · run · tan θ below, rounded up (a staircase drawn
//! from a slope of exactly θ stays). The full window sets the angle on open
//! ground (35°, window 4: 3 cells over 4, 4 over 4√2, that is 36.9° and
//! 35.3°); shorter distances let grains run down narrow steep tunnels.
struct ReposeSteps {
    ReposeSteps(double tan_repose, int window) : window(window) {
        for (int d = 0; d < 8; ++d)
            for (int s = 1; s <= window; ++s) {
                run[d][s] = s * (d < 4 ? 1.0 : std::sqrt(2.0));
                allowed_drop[d][s] = int(std::ceil(run[d][s] * tan_repose - 1e-9));
            }
    }
    int window;
    double run[8][kMaxWindow + 1];
    int allowed_drop[8][kMaxWindow + 1];
};

//! Lets the grain in cell `i` (height z) fall through free cells; stops on
//! support or in the outside, which it then has left (the cell stays
//! outside). Returns whether it moved; `i` and `z` follow it.
bool fall(std::vector<uint8_t>& cells, size_t& i, int& z) {
    bool fell = false;
    while (z > 0 && (cells[i - 1] == kFree || cells[i - 1] == kOutside)) {
        cells[i] = kFree;
        --i;
        --z;
        fell = true;
        if (cells[i] == kOutside) break;
        cells[i] = kGrain;
    }
    return fell;
}

//! The direction (index into kDirections) in which the grain at (x, y, z)
//! topples: the steepest whose ground lies lower than the repose allows, or
//! −1. Directions are tried from `start` round, so ties go a different way
//! for different grains and passes.
int steepest_topple(const Frame& frame, const std::vector<uint8_t>& cells, const ReposeSteps& steps, int x, int y,
                    int z, int start) {
    int best = -1;
    double best_slope = 0.0;
    for (int k = 0; k < 8; ++k) {
        const int d = (start + k) & 7;
        const int dx = kDirections[d][0], dy = kDirections[d][1];
        // Ground heights along the way, as drops below the grain. The
        // ground ahead may fall away at most one cell per step: at an
        // edge (a deeper drop, a bottomless column, the outside) the
        // grain sees only the edge, so a pit or cliff a few cells away
        // does not pull a grain resting on flat ground.
        int previous_drop = 1;  // the grain's own support
        for (int s = 1; s <= steps.window; ++s) {
            const int ax = x + s * dx, ay = y + s * dy;
            if (!frame.inside(ax, ay, z)) break;
            const uint8_t c = cells[frame.index(ax, ay, z)];
            if (c != kFree && c != kOutside) break;  // the way is blocked
            int drop = previous_drop + 1;
            bool edge = true;
            if (c == kFree)
                for (int zz = z - 1; zz >= std::max(0, z - previous_drop - 1); --zz) {
                    const uint8_t below = cells[frame.index(ax, ay, zz)];
                    if (below == kOutside) break;
                    if (below != kFree) {
                        drop = z - zz;
                        edge = false;
                        break;
                    }
                }
            if (drop > steps.allowed_drop[d][s]) {
                const double slope = drop / steps.run[d][s];
                if (best < 0 || slope > best_slope) {
                    best = d;
                    best_slope = slope;
                }
            }
            if (edge) break;
            previous_drop = drop;
        }
    }
    return best;
}

//! Whether the grain in cell `i` at (x, y, z) is buried: nothing below it
//! nor beside it is free or outside, so it can neither fall nor topple.
bool buried(const Frame& frame, const std::vector<uint8_t>& cells, size_t i, int x, int y, int z) {
    const auto open = [&](size_t c) { return cells[c] == kFree || cells[c] == kOutside; };
    if (z > 0 && open(i - 1)) return false;
    for (const auto& d : kDirections)
        if (frame.inside(x + d[0], y + d[1], z) && open(frame.index(x + d[0], y + d[1], z))) return false;
    return true;
}

//! The grains a pass visits. Every pass visits the grains in order, as one
//! sweep over all of them would, but skips the buried ones (a visit to them
//! changes nothing): a grain is active until a visit finds it buried, and
//! active again when the cell below it or beside it is vacated. The pile's
//! interior thus costs nothing per pass, only its surface does.
class ActiveGrains {
public:
    ActiveGrains(const Frame& frame, const std::vector<size_t>& grains)
        : frame_(frame), count_(grains.size()), slot_of_(frame.cells().size(), kNoSlot),
          bits_((grains.size() + 63) / 64, ~uint64_t(0)) {
        for (size_t g = 0; g < grains.size(); ++g) slot_of_[grains[g]] = uint32_t(g);
        if (count_ % 64) bits_.back() = (uint64_t(1) << (count_ % 64)) - 1;
    }
    //! The next active grain at or after slot g, or the grain count.
    size_t next(size_t g) const {
        for (size_t w = g / 64; w < bits_.size(); ++w) {
            uint64_t bits = bits_[w];
            if (w == g / 64) bits &= ~uint64_t(0) << (g % 64);
            if (bits) return w * 64 + size_t(__builtin_ctzll(bits));
        }
        return count_;
    }
    void deactivate(size_t g) { bits_[g / 64] &= ~(uint64_t(1) << (g % 64)); }
    //! Grain g now lies in cell i.
    void moved(size_t g, size_t i) { slot_of_[i] = uint32_t(g); }
    //! Activates the grains that may move now that cell c at (x, y, z) is vacated.
    void wake_around(size_t c, int x, int y, int z) {
        const auto& cells = frame_.cells();
        const auto wake = [&](size_t k) {
            if (cells[k] == kGrain && slot_of_[k] != kNoSlot) bits_[slot_of_[k] / 64] |= uint64_t(1) << (slot_of_[k] % 64);
        };
        if (z + 1 < frame_.size()[2]) wake(c + 1);
        for (const auto& d : kDirections)
            if (frame_.inside(x + d[0], y + d[1], z)) wake(frame_.index(x + d[0], y + d[1], z));
    }

private:
    static constexpr uint32_t kNoSlot = UINT32_MAX;
    const Frame& frame_;
    size_t count_;
    std::vector<uint32_t> slot_of_;
    std::vector<uint64_t> bits_;
};

enum class Visit { rested, buried, toppled, fell, left };

//! One visit to the grain in cell `i`: it falls through free cells, or else
//! topples one cell the steepest way the repose allows (ties broken by `pass`
//! and the cell, so they go different ways), or rests. `i` follows the grain;
//! a grain that reaches the outside has left (the cell stays outside).
Visit visit_grain(Frame& frame, const ReposeSteps& steps, ActiveGrains& active, size_t pass, size_t& i) {
    auto& cells = frame.cells();
    int x, y, z;
    frame.coordinates(i, x, y, z);
    const size_t from = i;
    const int from_z = z;
    if (fall(cells, i, z)) {
        active.wake_around(from, x, y, from_z);
        return cells[i] == kOutside ? Visit::left : Visit::fell;
    }
    const int best = steepest_topple(frame, cells, steps, x, y, z, int((i * 2654435761u + pass) & 7u));
    if (best < 0) return buried(frame, cells, i, x, y, z) ? Visit::buried : Visit::rested;
    i = frame.index(x + kDirections[best][0], y + kDirections[best][1], z);
    cells[from] = kFree;
    active.wake_around(from, x, y, z);
    if (cells[i] == kOutside) return Visit::left;
    cells[i] = kGrain;
    return Visit::toppled;
}

//! Runs falls and topples until the pile rests; returns how many grains left
//! (they are taken out of `grains`).
size_t settle_pile(Frame& frame, std::vector<size_t>& grains, double tan_repose, int window, Progress& progress) {
    const ReposeSteps steps(tan_repose, window);
    ActiveGrains active(frame, grains);
    const size_t removed_mark = SIZE_MAX;
    size_t removed = 0;
    // A grain that topples is above lower ground within `window` steps, so it
    // falls or leaves within that many passes unless the pile is only
    // jiggling: stop after that many passes with no fall and no exit.
    int passes_without_descent = 0;
    for (size_t pass = 0; passes_without_descent <= window + 1; ++pass) {
        if (progress.cancelled()) break;
        size_t moved = 0, descended = 0;
        for (size_t g = active.next(0); g < grains.size(); g = active.next(g + 1)) {
            size_t i = grains[g];
            const Visit visit = visit_grain(frame, steps, active, pass, i);
            if (visit == Visit::rested) continue;
            if (visit == Visit::buried) {
                active.deactivate(g);
                continue;
            }
            ++moved;
            if (visit != Visit::toppled) ++descended;
            if (visit == Visit::left) {
                grains[g] = removed_mark;
                active.deactivate(g);
                ++removed;
            } else {
                grains[g] = i;
                active.moved(g, i);
            }
        }
        if (moved == 0) break;
        passes_without_descent = descended > 0 ? 0 : passes_without_descent + 1;
    }
    if (removed) {
        size_t kept = 0;
        for (size_t g = 0; g < grains.size(); ++g)
            if (grains[g] != removed_mark) grains[kept++] = grains[g];
        grains.resize(kept);
    }
    progress.check();
    return removed;
}

}  // namespace

SandpileResult simulate_sandpile(const openvdb::FloatGrid& solid, const std::vector<SandpileHole>& holes,
                                 const SandpileOptions& options, Progress& progress) {
    progress.stage("powder simulation");
    if (options.routine.empty()) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the routine has no turn");
    if (!(options.repose_radians > 0.0 && options.repose_radians < M_PI / 2))
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the angle of repose must be between 0 and 90 degrees");
    if (options.slope_window < 1 || options.slope_window > kMaxWindow)
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the slope window must be 1 to " + std::to_string(kMaxWindow) + " cells");
    const double h = options.cell_size > 0.0 ? options.cell_size : solid.voxelSize()[0];
    std::vector<Drill> drills;
    for (const SandpileHole& hole : holes) {
        const Eigen::Vector3d axis(hole.axis[0], hole.axis[1], hole.axis[2]);
        if (!(axis.norm() > 0.0) || !(hole.diameter > 0.0))
            throw Error(FABVDB_ERR_INVALID_ARGUMENT, "a hole needs a direction and a positive diameter");
        drills.push_back({Eigen::Vector3d(hole.center[0], hole.center[1], hole.center[2]), axis.normalized(),
                          0.5 * hole.diameter, hole.depth});
    }
    const double tan_repose = std::tan(options.repose_radians);
    const double cell_volume = h * h * h;

    SandpileResult result;
    // Where the grains inside lie, carried from turn to turn. Voxelised in
    // the next turn's frame a nearly full cavity may hold fewer cells than
    // grains: a grain that finds no free cell near its place waits (still
    // inside) and is placed again once the pile has moved and made room.
    std::vector<Eigen::Vector3d> positions;
    for (size_t turn = 0; turn < options.routine.size(); ++turn) {
        progress.update(double(turn) / double(options.routine.size()));
        const Vec3& g = options.routine[turn];
        const Eigen::Vector3d gravity(g[0], g[1], g[2]);
        if (!(gravity.norm() > 0.0)) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "a turn's gravity is zero");
        std::vector<char> fill;
        Frame frame(solid, drills, gravity, h, turn == 0 ? &fill : nullptr);
        std::vector<size_t> grains;
        std::vector<Eigen::Vector3d> waiting;
        if (turn == 0) {
            auto& cells = frame.cells();
            for (size_t i = 0; i < cells.size(); ++i)
                if (fill[i]) {
                    cells[i] = kGrain;
                    grains.push_back(i);
                }
            result.initial_volume = double(grains.size()) * cell_volume;
        } else {
            for (const Eigen::Vector3d& p : positions)
                if (!place_grain(frame, p, grains)) waiting.push_back(p);
        }
        progress.check();
        settle_pile(frame, grains, tan_repose, options.slope_window, progress);
        while (!waiting.empty()) {
            std::vector<Eigen::Vector3d> still;
            for (const Eigen::Vector3d& p : waiting)
                if (!place_grain(frame, p, grains)) still.push_back(p);
            if (still.size() == waiting.size()) break;
            waiting.swap(still);
            settle_pile(frame, grains, tan_repose, options.slope_window, progress);
        }
        positions = std::move(waiting);
        for (size_t i : grains) positions.push_back(frame.world(i));
        result.residual_after_turn.push_back(double(positions.size()) * cell_volume);
    }
    result.residual_volume = result.residual_after_turn.back();
    progress.update(1.0);
    return result;
}

}  // namespace fabvdb::powder
