// Fully automatic mold decomposition of a shared model from the thesis'
// Table 3.2 (kitten, genus 1, at the thesis' S_low size): two parts, each
// under gamma, checked on the written decomposition.json with the
// independent checks of support/decomposition_checks.h (disjoint, covering,
// connected parts; connected M+ and M-; overhang energy recomputed). The
// other models of the table (bunny, fertility, airplane) run in
// bench/decompose.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "io/mesh_io.h"
#include "support/decomposition_checks.h"
#include "surface/decompose.h"
#include "surface/decomposition_io.h"

namespace {

TEST(DecomposeSharedMeshes, KittenIsTwoMoldablePartsLikeTheThesis) {
    fabvdb::Progress progress;
    const fabvdb::Mesh input = fabvdb::io::read_mesh(FABVDB_SHARED_DATA "/meshes/kitten.obj", progress);
    fabvdb::surface::DecomposeSettings settings;
    settings.shell.target_triangles = 2310;
    const fabvdb::BoundingBox box = fabvdb::bounding_box(input);
    settings.shell.thickness =
        0.03 * std::max({box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]});
    const auto result = fabvdb::surface::decompose_mesh(input, settings, {}, progress);
    const std::string folder = std::filesystem::temp_directory_path() / "fabvdb_decompose_kitten";
    fabvdb::surface::write_decomposition(folder, input, result.shell, result.terms, result.decomposition,
                                         settings.decomposition);
    const nlohmann::json doc = fabvdb::test::read_decomposition(folder + "/decomposition.json");
    EXPECT_EQ(doc["parts"].size(), 2u);
    fabvdb::test::check_decomposition(doc);
    const double gamma = doc["gamma"];
    for (const auto& part : doc["parts"]) EXPECT_LT(double(part["moldability_energy"]), gamma);
    EXPECT_LT(double(doc["total_moldability_energy"]), gamma);
    std::filesystem::remove_all(folder);
}

}  // namespace
