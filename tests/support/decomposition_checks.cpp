//! decomposition_checks: map-based edge adjacency, depth-first pieces, the
//! overhang term written out from the thesis' formula on the written corners.
#include "support/decomposition_checks.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <set>

#include "support/check_vec3.h"

namespace fabvdb::test {

namespace {

using Point = std::array<double, 3>;
using Face = std::array<uint32_t, 3>;

//! Number of connected pieces of `faces` joined across shared edges; the
//! piece of each face in `piece_of` if given.
size_t pieces(const std::vector<Face>& faces, std::vector<size_t>* piece_of = nullptr) {
    std::map<std::pair<uint32_t, uint32_t>, std::vector<size_t>> by_edge;
    for (size_t i = 0; i < faces.size(); ++i)
        for (int k = 0; k < 3; ++k) by_edge[std::minmax(faces[i][k], faces[i][(k + 1) % 3])].push_back(i);
    std::vector<char> seen(faces.size(), 0);
    if (piece_of) piece_of->assign(faces.size(), 0);
    size_t count = 0;
    for (size_t s = 0; s < faces.size(); ++s) {
        if (seen[s]) continue;
        ++count;
        std::vector<size_t> stack{s};
        seen[s] = 1;
        while (!stack.empty()) {
            const size_t i = stack.back();
            stack.pop_back();
            if (piece_of) (*piece_of)[i] = count - 1;
            for (int k = 0; k < 3; ++k)
                for (size_t j : by_edge[std::minmax(faces[i][k], faces[i][(k + 1) % 3])])
                    if (!seen[j]) {
                        seen[j] = 1;
                        stack.push_back(j);
                    }
        }
    }
    return count;
}

std::vector<Point> corners_of(const nlohmann::json& doc) {
    std::vector<Point> corners;
    for (const auto& v : doc["low_res_surface"]["vertices"]) corners.push_back(v.get<Point>());
    for (const auto& v : doc["low_res_surface"]["inner_vertices"]) corners.push_back(v.get<Point>());
    return corners;
}

//! Per S_low triangle, the id of the part whose prisms list it (−1: none).
std::vector<int> owners(const nlohmann::json& doc) {
    std::vector<int> owner(doc["low_res_surface"]["triangles"].size(), -1);
    for (const auto& part : doc["parts"])
        for (uint32_t t : part["prisms"].get<std::vector<uint32_t>>()) owner[t] = part["id"];
    return owner;
}

}  // namespace

nlohmann::json read_decomposition(const std::string& path) {
    std::ifstream in(path);
    nlohmann::json doc;
    in >> doc;
    return doc;
}

std::vector<double> check_decomposition(const nlohmann::json& doc) {
    const std::vector<Point> corners = corners_of(doc);
    const auto all = doc["low_res_surface"]["triangles"].get<std::vector<Face>>();
    std::vector<int> owner(all.size(), -1);
    std::vector<double> areas;
    const double s = doc["unit_scale"];
    const double draft = double(doc["draft_degrees"]) * M_PI / 180.0;
    for (const auto& part : doc["parts"]) {
        const int id = part["id"];
        std::vector<Face> prisms;
        double area = 0;
        for (uint32_t t : part["prisms"].get<std::vector<uint32_t>>()) {
            EXPECT_EQ(owner[t], -1) << "triangle " << t << " in two parts";
            owner[t] = id;
            prisms.push_back(all[t]);
            const Point c = cross(sub(corners[all[t][1]], corners[all[t][0]]), sub(corners[all[t][2]], corners[all[t][0]]));
            area += 0.5 * norm(c);
        }
        areas.push_back(area);
        EXPECT_EQ(pieces(prisms), 1u) << "part " << id << " is not connected";
        const auto surface = part["surface"]["triangles"].get<std::vector<Face>>();
        const auto upper = part["surface"]["upper"].get<std::vector<int>>();
        const auto kind = part["surface"]["kind"].get<std::vector<int>>();
        // A part that is a whole closed shell of a hollow decomposition has
        // its inner surface apart from its outer one: each piece of the
        // part's surface is split once, into at most one M+ and one M- piece.
        std::vector<size_t> surface_piece;
        pieces(surface, &surface_piece);
        std::vector<Face> top, bottom;
        std::set<size_t> top_in, bottom_in;
        const Point d = part["parting_direction"].get<Point>();
        double overhang = 0;
        for (size_t i = 0; i < surface.size(); ++i) {
            (upper[i] ? top : bottom).push_back(surface[i]);
            (upper[i] ? top_in : bottom_in).insert(surface_piece[i]);
            if (kind[i] == 1) continue;  // inner triangles are invisible
            const Face& f = surface[i];
            const Point c = cross(sub(corners[f[1]], corners[f[0]]), sub(corners[f[2]], corners[f[0]]));
            const double twice = norm(c);
            if (twice == 0) continue;
            const double facing = dot(c, d) / twice * (upper[i] ? 1 : -1);
            const double theta = std::acos(std::max(-1.0, std::min(1.0, facing)));
            if (theta > M_PI / 2 - draft)
                overhang += -std::cos(std::min(theta + draft, M_PI)) * 0.5 * twice * s * s * std::abs(facing);
        }
        EXPECT_EQ(pieces(top), top_in.size()) << "M+ of part " << id;
        EXPECT_EQ(pieces(bottom), bottom_in.size()) << "M- of part " << id;
        EXPECT_NEAR(overhang, double(part["overhang_energy"]), 1e-9 + 1e-6 * overhang) << "part " << id;
    }
    for (size_t t = 0; t < owner.size(); ++t) EXPECT_GE(owner[t], 0) << "triangle " << t << " in no part";
    return areas;
}

BoundaryMeasure measure_boundaries(const nlohmann::json& doc) {
    const std::vector<Point> corners = corners_of(doc);
    const auto all = doc["low_res_surface"]["triangles"].get<std::vector<Face>>();
    const std::vector<int> owner = owners(doc);
    std::map<std::pair<uint32_t, uint32_t>, std::vector<int>> sides;
    for (size_t t = 0; t < all.size(); ++t)
        for (int k = 0; k < 3; ++k) sides[std::minmax(all[t][k], all[t][(k + 1) % 3])].push_back(owner[t]);
    BoundaryMeasure m;
    std::map<uint32_t, std::vector<uint32_t>> ends;
    for (const auto& [edge, parts] : sides) {
        if (parts.size() != 2 || parts[0] == parts[1]) continue;
        const Point e = sub(corners[edge.second], corners[edge.first]);
        m.length += norm(e);
        ends[edge.first].push_back(edge.second);
        ends[edge.second].push_back(edge.first);
    }
    for (const auto& [v, others] : ends) {
        if (others.size() != 2) continue;
        const Point a = sub(corners[others[0]], corners[v]);
        const Point b = sub(corners[others[1]], corners[v]);
        const double c = dot(a, b) / std::sqrt(dot(a, a) * dot(b, b));
        m.turning += M_PI - std::acos(std::max(-1.0, std::min(1.0, c)));
        ++m.vertices;
    }
    return m;
}

}  // namespace fabvdb::test
