// Reading a decomposition's parts back for mold generation: a part whose
// surface is closed but touches itself along one edge (two tetrahedra
// sharing an edge, four triangles on it: a part boundary passing twice
// through a vertex gives this on the prism's side) is read with its volume;
// a part with a triangle missing is refused as not closed, naming the part.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "support/shapes.h"
#include "surface/decomposition_parts.h"

namespace {

using fabvdb::Mesh;
using nlohmann::json;

// Two tetrahedra, outward, sharing the edge from (0,0,0) to (0,0,10).
Mesh wedges() {
    Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {0, 0, 10}, {10, 0, 0}, {0, 10, 0}, {-10, 0, 0}, {0, -10, 0}};
    const auto tetrahedron = [&](uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
        mesh.triangles.insert(mesh.triangles.end(), {{a, c, b}, {a, b, d}, {a, d, c}, {b, c, d}});
    };
    tetrahedron(0, 1, 2, 3);
    tetrahedron(0, 1, 4, 5);
    return mesh;
}

json document_of(const Mesh& surface) {
    json triangles = json::array();
    for (const auto& t : surface.triangles) triangles.push_back({t[0], t[1], t[2]});
    json vertices = json::array();
    for (const auto& v : surface.vertices) vertices.push_back({v[0], v[1], v[2]});
    json doc;
    doc["format"] = "fabvdb decomposition";
    doc["version"] = 1;
    doc["shell_thickness"] = 1.0;
    doc["low_res_surface"] = {{"vertices", vertices}, {"inner_vertices", vertices}, {"triangles", triangles}};
    doc["part_of_triangle"] = std::vector<int>(surface.triangles.size(), 0);
    doc["parts"] = json::array({{{"id", 0}, {"parting_direction", {0, 0, 1}}, {"surface", {{"triangles", triangles}}}}});
    return doc;
}

TEST(DecompositionParts, PartTouchingItselfAlongAnEdgeIsRead) {
    const Mesh input = wedges();
    ASSERT_GT(fabvdb::test::mesh_volume(input), 0.0);
    const auto model = fabvdb::surface::decomposed_parts(document_of(input), "d.json", input);
    ASSERT_EQ(model.parts.size(), 1u);
    EXPECT_NEAR(fabvdb::test::mesh_volume(model.parts[0].solid), fabvdb::test::mesh_volume(input), 1e-9);
}

TEST(DecompositionParts, OpenPartIsRefused) {
    const Mesh input = wedges();
    json doc = document_of(input);
    doc["parts"][0]["surface"]["triangles"].erase(0);
    try {
        fabvdb::surface::decomposed_parts(doc, "d.json", input);
        FAIL() << "an open part was accepted";
    } catch (const fabvdb::Error& e) {
        EXPECT_NE(std::string(e.what()).find("d.json"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("part 0 is not closed"), std::string::npos) << e.what();
    }
}

}  // namespace
