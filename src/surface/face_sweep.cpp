//! Swept volumes of a part's mold faces (see face_sweep.h).
#include "surface/face_sweep.h"

#include <map>
#include <utility>

#include "core/error.h"

namespace fabvdb::surface {

Mesh sweep_faces_to_plane(const Mesh& part, bool upward, double plane_z) {
    Mesh swept;
    std::vector<uint32_t> base(part.vertices.size(), UINT32_MAX), cap(part.vertices.size(), UINT32_MAX);
    auto base_vertex = [&](uint32_t v) {
        if (base[v] == UINT32_MAX) {
            base[v] = uint32_t(swept.vertices.size());
            swept.vertices.push_back(part.vertices[v]);
        }
        return base[v];
    };
    auto cap_vertex = [&](uint32_t v) {
        if (cap[v] == UINT32_MAX) {
            cap[v] = uint32_t(swept.vertices.size());
            swept.vertices.push_back({part.vertices[v][0], part.vertices[v][1], plane_z});
        }
        return cap[v];
    };
    // Directed edges of the chosen faces; an edge whose reverse is not among
    // them is on the border of the face set and gets a wall.
    std::map<std::pair<uint32_t, uint32_t>, bool> edges;
    std::vector<Triangle> faces;
    for (const Triangle& t : part.triangles) {
        const Vec3 &a = part.vertices[t[0]], &b = part.vertices[t[1]], &c = part.vertices[t[2]];
        const double normal_z = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        if (normal_z == 0.0)
            throw Error(FABVDB_ERR_BAD_INPUT, "the part has a face parallel to the parting direction");
        if ((normal_z < 0) != upward) continue;
        faces.push_back(t);
        for (int k = 0; k < 3; ++k) edges[{t[k], t[(k + 1) % 3]}] = true;
    }
    for (const Triangle& t : part.triangles)
        for (uint32_t v : t) {
            const double z = part.vertices[v][2];
            if (upward ? z >= plane_z : z <= plane_z)
                throw Error(FABVDB_ERR_BAD_INPUT, "the sweep plane does not clear the part");
        }
    if (faces.empty()) throw Error(FABVDB_ERR_BAD_INPUT, "the part has no face to sweep");
    for (const Triangle& t : faces) {
        swept.triangles.push_back({base_vertex(t[0]), base_vertex(t[1]), base_vertex(t[2])});
        swept.triangles.push_back({cap_vertex(t[0]), cap_vertex(t[2]), cap_vertex(t[1])});
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = t[k], b = t[(k + 1) % 3];
            if (edges.count({b, a})) continue;
            swept.triangles.push_back({base_vertex(b), base_vertex(a), cap_vertex(a)});
            swept.triangles.push_back({base_vertex(b), cap_vertex(a), cap_vertex(b)});
        }
    }
    return swept;
}

}  // namespace fabvdb::surface
