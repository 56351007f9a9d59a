//! decomposition_edits: JSON parsing, brute-force nearest queries on S_low
//! (edits touch a handful of points), local regrowth for no-cut strokes,
//! Dijkstra paths for cuts, unions for merges, the snake smoothing restricted
//! to the stroke for smooth edits.
#include "surface/decomposition_edits.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <queue>
#include <set>

#include <tbb/parallel_for.h>

#include "core/error.h"
#include "core/stage_clock.h"
#include "surface/boundary_smoothing.h"
#include "core/vec3_ops.h"

namespace fabvdb::surface {

namespace {

double squared(const Vec3& v) { return dot(v, v); }

Vec3 centroid(const Shell& shell, size_t t) {
    const Triangle& f = shell.outer.triangles[t];
    return (1.0 / 3.0) * (shell.outer.vertices[f[0]] + shell.outer.vertices[f[1]] + shell.outer.vertices[f[2]]);
}

size_t nearest_triangle(const Shell& shell, const Vec3& p) {
    size_t best = 0;
    double best_d = 1e300;
    for (size_t t = 0; t < shell.triangle_count(); ++t) {
        const double d = squared(centroid(shell, t) - p);
        if (d < best_d) {
            best_d = d;
            best = t;
        }
    }
    return best;
}

uint32_t nearest_vertex(const Shell& shell, const Vec3& p) {
    uint32_t best = 0;
    double best_d = 1e300;
    for (uint32_t v = 0; v < shell.outer.vertices.size(); ++v) {
        const double d = squared(shell.outer.vertices[v] - p);
        if (d < best_d) {
            best_d = d;
            best = v;
        }
    }
    return best;
}

//! The S_low edges a cut runs along: a vertex flag to reject the other edges
//! at once, then the edges (as sorted vertex pairs).
struct CutEdges {
    std::vector<char> on_cut;  //!< per S_low vertex
    std::set<std::pair<uint32_t, uint32_t>> edges;
    bool contains(uint32_t a, uint32_t b) const { return on_cut[a] && on_cut[b] && edges.count(std::minmax(a, b)); }
};

//! Connected pieces of `members` (triangles) across edges not in `blocked`
//! (may be null: none), largest first.
std::vector<std::vector<uint32_t>> pieces_of(const Shell& shell, const std::vector<uint32_t>& members,
                                             const CutEdges* blocked) {
    std::vector<char> in(shell.triangle_count(), 0), seen(shell.triangle_count(), 0);
    for (uint32_t t : members) in[t] = 1;
    std::vector<std::vector<uint32_t>> pieces;
    std::vector<uint32_t> stack;
    for (uint32_t start : members) {
        if (seen[start]) continue;
        pieces.emplace_back();
        stack.assign(1, start);
        seen[start] = 1;
        while (!stack.empty()) {
            const uint32_t t = stack.back();
            stack.pop_back();
            pieces.back().push_back(t);
            const Triangle& f = shell.outer.triangles[t];
            for (int k = 0; k < 3; ++k) {
                const int other = shell.neighbor[t][k];
                if (!in[other] || seen[other] || (blocked && blocked->contains(f[k], f[(k + 1) % 3]))) continue;
                seen[other] = 1;
                stack.push_back(uint32_t(other));
            }
        }
    }
    std::sort(pieces.begin(), pieces.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
    return pieces;
}

std::vector<uint32_t> triangles_of_part(const Decomposition& decomposition, int part) {
    std::vector<uint32_t> members;
    for (size_t t = 0; t < decomposition.part_of_triangle.size(); ++t)
        if (decomposition.part_of_triangle[t] == part) members.push_back(uint32_t(t));
    return members;
}

//! Removes parts that own no triangle any more and renumbers the rest in order.
void drop_empty_parts(Decomposition& decomposition) {
    std::vector<size_t> size(decomposition.parts.size(), 0);
    for (int p : decomposition.part_of_triangle) ++size[p];
    std::vector<int> renumber(size.size(), -1);
    std::vector<PartMolding> kept;
    for (size_t p = 0; p < size.size(); ++p)
        if (size[p] > 0) {
            renumber[p] = int(kept.size());
            kept.push_back(std::move(decomposition.parts[p]));
        }
    for (int& p : decomposition.part_of_triangle) p = renumber[p];
    decomposition.parts = std::move(kept);
}

std::vector<int> apply_no_cut(const Shell& shell, const MoldabilityTerms& terms, const DecompositionOptions& options,
                              const Edit& edit, const std::string& what, Decomposition& decomposition,
                              Progress& progress) {
    std::vector<uint32_t> brushed;
    const double r2 = edit.radius * edit.radius;
    for (size_t t = 0; t < shell.triangle_count(); ++t) {
        const Vec3 c = centroid(shell, t);
        for (const Vec3& p : edit.points)
            if (squared(c - p) <= r2) {
                brushed.push_back(uint32_t(t));
                break;
            }
    }
    if (brushed.empty()) brushed.push_back(uint32_t(nearest_triangle(shell, edit.points.front())));
    const std::vector<uint32_t> stroke = pieces_of(shell, brushed, nullptr).front();
    std::set<int> touched;
    for (uint32_t t : stroke) touched.insert(decomposition.part_of_triangle[t]);
    if (touched.size() < 2) return {*touched.begin()};
    std::vector<int> parts(touched.begin(), touched.end());
    std::vector<char> domain(shell.triangle_count(), 0);
    for (size_t t = 0; t < shell.triangle_count(); ++t) domain[t] = touched.count(decomposition.part_of_triangle[t]);
    const Elements elements = make_elements(shell, {stroke}, domain);
    const int stroke_element = elements.element_of_triangle[stroke.front()];
    // Seed each touched part at its element most facing its direction, off the stroke.
    std::vector<int> seeds, directions, region_part;
    for (int p : parts) {
        const Vec3& d = terms.directions.directions[decomposition.parts[p].direction];
        int best = -1;
        double best_cost = 1e300;
        for (size_t t = 0; t < shell.triangle_count(); ++t) {
            const int e = elements.element_of_triangle[t];
            if (decomposition.part_of_triangle[t] != p || e == stroke_element) continue;
            const double cost = -dot(shell.normal[t], d);
            if (cost < best_cost) {
                best_cost = cost;
                best = e;
            }
        }
        if (best < 0 || std::find(seeds.begin(), seeds.end(), best) != seeds.end()) continue;
        seeds.push_back(best);
        directions.push_back(decomposition.parts[p].direction);
        region_part.push_back(p);
    }
    if (seeds.empty()) throw Error(FABVDB_ERR_BAD_INPUT, what + ": the stroke covers whole parts");
    const Regions regions = grow_regions(shell, terms, elements, seeds, directions, options.overlap_weight,
                                         options.max_iterations, progress);
    for (size_t t = 0; t < shell.triangle_count(); ++t)
        if (domain[t]) decomposition.part_of_triangle[t] = region_part[regions.region_of_triangle[t]];
    tbb::parallel_for(size_t(0), region_part.size(), [&](size_t r) {
        decomposition.parts[region_part[r]] = parting_line(shell, terms, decomposition.part_of_triangle,
                                                           region_part[r], regions.direction[r], options.weights);
    });
    return parts;
}

std::vector<int> apply_cut(const Shell& shell, const MoldabilityTerms& terms, const DecompositionOptions& options,
                           const Edit& edit, const std::string& what, Decomposition& decomposition,
                           Progress& progress) {
    // Vertex adjacency (compressed rows, each vertex's neighbours in triangle
    // order), for the shortest paths between snapped points.
    const size_t vertex_count = shell.outer.vertices.size();
    std::vector<uint32_t> around_start(vertex_count + 1, 0), around(3 * shell.triangle_count());
    for (const Triangle& f : shell.outer.triangles)
        for (int k = 0; k < 3; ++k) ++around_start[f[k] + 1];
    for (size_t v = 0; v < vertex_count; ++v) around_start[v + 1] += around_start[v];
    {
        std::vector<uint32_t> next(around_start.begin(), around_start.end() - 1);
        for (const Triangle& f : shell.outer.triangles)
            for (int k = 0; k < 3; ++k) around[next[f[k]]++] = f[(k + 1) % 3];
    }
    std::vector<uint32_t> snapped;
    for (const Vec3& p : edit.points) snapped.push_back(nearest_vertex(shell, p));
    if (edit.closed) snapped.push_back(snapped.front());
    CutEdges cut_edges;
    cut_edges.on_cut.assign(vertex_count, 0);
    // Each search resets only the vertices it reached.
    std::vector<double> distance(vertex_count, 1e300);
    std::vector<uint32_t> previous(vertex_count, uint32_t(-1)), reached;
    for (size_t i = 0; i + 1 < snapped.size(); ++i) {
        for (uint32_t v : reached) {
            distance[v] = 1e300;
            previous[v] = uint32_t(-1);
        }
        reached.assign(1, snapped[i]);
        using Entry = std::pair<double, uint32_t>;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
        distance[snapped[i]] = 0;
        queue.emplace(0.0, snapped[i]);
        while (!queue.empty()) {
            const auto [d, v] = queue.top();
            queue.pop();
            if (v == snapped[i + 1]) break;
            if (d > distance[v]) continue;
            for (uint32_t k = around_start[v]; k < around_start[v + 1]; ++k) {
                const uint32_t w = around[k];
                const double nd = d + norm(shell.outer.vertices[w] - shell.outer.vertices[v]);
                if (nd < distance[w]) {
                    if (distance[w] == 1e300) reached.push_back(w);
                    distance[w] = nd;
                    previous[w] = v;
                    queue.emplace(nd, w);
                }
            }
        }
        for (uint32_t v = snapped[i + 1]; v != snapped[i] && previous[v] != uint32_t(-1); v = previous[v]) {
            cut_edges.edges.insert(std::minmax(v, previous[v]));
            cut_edges.on_cut[v] = cut_edges.on_cut[previous[v]] = 1;
        }
    }
    std::set<int> crossed;
    for (size_t t = 0; t < shell.triangle_count(); ++t) {
        const Triangle& f = shell.outer.triangles[t];
        for (int k = 0; k < 3; ++k)
            if (cut_edges.contains(f[k], f[(k + 1) % 3])) crossed.insert(decomposition.part_of_triangle[t]);
    }
    std::vector<int> touched, former_direction;  // each piece and the direction of the part it came from
    for (int p : crossed) {
        const auto pieces = pieces_of(shell, triangles_of_part(decomposition, p), &cut_edges);
        if (pieces.size() < 2) continue;
        touched.push_back(p);
        former_direction.push_back(decomposition.parts[p].direction);
        for (size_t i = 1; i < pieces.size(); ++i) {
            const int id = int(decomposition.parts.size());
            decomposition.parts.emplace_back();
            for (uint32_t t : pieces[i]) decomposition.part_of_triangle[t] = id;
            touched.push_back(id);
            former_direction.push_back(decomposition.parts[p].direction);
        }
    }
    if (touched.empty()) throw Error(FABVDB_ERR_BAD_INPUT, what + ": the cut does not separate any part");
    // The pieces side by side: a small one (the patch inside a closed cut)
    // then takes the other core while the large one starts.
    tbb::parallel_for(size_t(0), touched.size(), [&](size_t i) {
        decomposition.parts[touched[i]] = best_parting_line(shell, terms, decomposition.part_of_triangle, touched[i],
                                                            options.weights, {former_direction[i]}, progress);
    });
    return touched;
}

std::vector<int> apply_merge(const Shell& shell, const MoldabilityTerms& terms, const DecompositionOptions& options,
                             const Edit& edit, const std::string& what, Decomposition& decomposition,
                             Progress& progress) {
    const int a = decomposition.part_of_triangle[nearest_triangle(shell, edit.points[0])];
    const int b = decomposition.part_of_triangle[nearest_triangle(shell, edit.points[1])];
    if (a == b) throw Error(FABVDB_ERR_BAD_INPUT, what + ": both points are on the same part");
    bool neighbours = false;
    for (size_t t = 0; t < shell.triangle_count() && !neighbours; ++t)
        if (decomposition.part_of_triangle[t] == a)
            for (int k = 0; k < 3; ++k) neighbours |= decomposition.part_of_triangle[shell.neighbor[t][k]] == b;
    if (!neighbours) throw Error(FABVDB_ERR_BAD_INPUT, what + ": the two parts do not touch");
    const int kept = std::min(a, b), gone = std::max(a, b);
    for (int& p : decomposition.part_of_triangle)
        if (p == gone) p = kept;
    decomposition.parts[kept] =
        best_parting_line(shell, terms, decomposition.part_of_triangle, kept, options.weights,
                          {decomposition.parts[a].direction, decomposition.parts[b].direction}, progress);
    return {kept, gone};
}

std::vector<int> apply_smooth(Shell& shell, MoldabilityTerms& terms, const DecompositionOptions& options,
                              const Edit& edit, const std::string& what, Decomposition& decomposition,
                              Progress& progress) {
    std::vector<char> selected(shell.outer.vertices.size(), 0);
    const double r2 = edit.radius * edit.radius;
    for (size_t v = 0; v < selected.size(); ++v)
        for (const Vec3& p : edit.points)
            if (squared(shell.outer.vertices[v] - p) <= r2) selected[v] = 1;
    std::vector<char> on_boundary(selected.size(), 0);
    for (size_t t = 0; t < shell.triangle_count(); ++t)
        for (int k = 0; k < 3; ++k)
            if (decomposition.part_of_triangle[shell.neighbor[t][k]] != decomposition.part_of_triangle[t])
                on_boundary[shell.outer.triangles[t][k]] = 1;
    bool reaches = false;
    for (size_t v = 0; v < selected.size(); ++v) reaches |= selected[v] && on_boundary[v];
    if (!reaches) throw Error(FABVDB_ERR_BAD_INPUT, what + ": the smoothing stroke does not reach a part boundary");
    // A smooth edit smooths even when the automatic smoothing is off.
    DecompositionOptions smoothing = options;
    if (smoothing.smoothing_iterations <= 0) smoothing.smoothing_iterations = DecompositionOptions{}.smoothing_iterations;
    const nlohmann::json record = smooth_boundaries(shell, terms, decomposition, smoothing, &selected, progress);
    return record["parts_touched"].get<std::vector<int>>();
}

Vec3 read_point(const nlohmann::json& value, const std::string& what) {
    if (!value.is_array() || value.size() != 3 || !value[0].is_number() || !value[1].is_number() ||
        !value[2].is_number())
        throw Error(FABVDB_ERR_BAD_INPUT, what + ": a point is not [x, y, z]");
    return {value[0].get<double>(), value[1].get<double>(), value[2].get<double>()};
}

}  // namespace

Edit parse_edit(const nlohmann::json& item, const std::string& what) {
    if (!item.is_object() || !item.contains("type") || !item["type"].is_string())
        throw Error(FABVDB_ERR_BAD_INPUT, what + ": no \"type\"");
    Edit edit;
    const std::string type = item["type"];
    if (type == "no_cut")
        edit.type = Edit::no_cut;
    else if (type == "cut")
        edit.type = Edit::cut;
    else if (type == "merge")
        edit.type = Edit::merge;
    else if (type == "smooth")
        edit.type = Edit::smooth;
    else
        throw Error(FABVDB_ERR_BAD_INPUT, what + ": unknown type \"" + type + "\" (no_cut, cut, merge, smooth)");
    if (!item.contains("points") || !item["points"].is_array() || item["points"].empty())
        throw Error(FABVDB_ERR_BAD_INPUT, what + ": no \"points\"");
    for (const auto& p : item["points"]) edit.points.push_back(read_point(p, what));
    if (item.contains("radius")) {
        if (!item["radius"].is_number()) throw Error(FABVDB_ERR_BAD_INPUT, what + ": \"radius\" is not a number");
        edit.radius = item["radius"];
    }
    if (item.contains("closed")) {
        if (!item["closed"].is_boolean()) throw Error(FABVDB_ERR_BAD_INPUT, what + ": \"closed\" is not a boolean");
        edit.closed = item["closed"];
    }
    check_edit(edit, what);
    return edit;
}

std::vector<Edit> read_edits(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error(FABVDB_ERR_IO, path + ": cannot open the edits file");
    nlohmann::json document;
    try {
        in >> document;
    } catch (const nlohmann::json::exception& e) {
        throw Error(FABVDB_ERR_BAD_INPUT, path + ": not valid JSON (" + e.what() + ")");
    }
    if (!document.is_object() || !document.contains("edits") || !document["edits"].is_array())
        throw Error(FABVDB_ERR_BAD_INPUT, path + ": expected an object with an \"edits\" array");
    std::vector<Edit> edits;
    for (size_t i = 0; i < document["edits"].size(); ++i)
        edits.push_back(parse_edit(document["edits"][i], path + ": edit " + std::to_string(i + 1)));
    return edits;
}

void check_edit(const Edit& edit, const std::string& what) {
    const char* type = edit_type_name(edit.type);
    if (edit.points.empty()) throw Error(FABVDB_ERR_BAD_INPUT, what + ": no \"points\"");
    for (const Vec3& p : edit.points)
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            throw Error(FABVDB_ERR_BAD_INPUT, what + ": a point is not finite");
    if ((edit.type == Edit::no_cut || edit.type == Edit::smooth) && !(edit.radius > 0 && std::isfinite(edit.radius)))
        throw Error(FABVDB_ERR_BAD_INPUT, what + ": a " + type + " stroke needs \"radius\" > 0");
    if (edit.type == Edit::cut && edit.points.size() < 2)
        throw Error(FABVDB_ERR_BAD_INPUT, what + ": a cut needs at least two points");
    if (edit.type == Edit::merge && edit.points.size() != 2)
        throw Error(FABVDB_ERR_BAD_INPUT, what + ": a merge needs exactly two points");
}

const char* edit_type_name(Edit::Type type) {
    switch (type) {
        case Edit::no_cut: return "no_cut";
        case Edit::cut: return "cut";
        case Edit::merge: return "merge";
        case Edit::smooth: return "smooth";
    }
    return "unknown";
}

nlohmann::json edits_document(const std::vector<Edit>& edits) {
    nlohmann::json list = nlohmann::json::array();
    for (const Edit& edit : edits) {
        nlohmann::json item = {{"type", edit_type_name(edit.type)}, {"points", edit.points}};
        if (edit.type == Edit::no_cut || edit.type == Edit::smooth) item["radius"] = edit.radius;
        if (edit.type == Edit::cut) item["closed"] = edit.closed;
        list.push_back(std::move(item));
    }
    return {{"edits", std::move(list)}};
}

nlohmann::json apply_edit(Shell& shell, MoldabilityTerms& terms, const DecompositionOptions& options,
                          const Edit& edit, size_t index, Decomposition& decomposition, Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    const std::string what = "edit " + std::to_string(index + 1);
    std::vector<int> touched;
    const char* type = "";
    switch (edit.type) {
        case Edit::no_cut:
            type = "no_cut";
            touched = apply_no_cut(shell, terms, options, edit, what, decomposition, progress);
            break;
        case Edit::cut:
            type = "cut";
            touched = apply_cut(shell, terms, options, edit, what, decomposition, progress);
            break;
        case Edit::merge:
            type = "merge";
            touched = apply_merge(shell, terms, options, edit, what, decomposition, progress);
            break;
        case Edit::smooth:
            type = "smooth";
            touched = apply_smooth(shell, terms, options, edit, what, decomposition, progress);
            break;
    }
    drop_empty_parts(decomposition);
    const double seconds = seconds_since(start);
    return {{"type", type},
            {"parts_touched", touched},
            {"parts_after", decomposition.parts.size()},
            {"timings", {{"total", seconds}}},
            {"total_moldability_energy", decomposition.total_energy()}};
}

}  // namespace fabvdb::surface
