// MikkTSpace tangents against an independent implementation: tests/data/meshes/mikk_mirrored.glb
// carries TANGENTs written by the mikktspace npm package (a WASM build of the reference C code)
// through glTF-Transform (see tests/data/README.md). gsdot3's own tangents must agree with them
// within 1e-3 per component, with the same bitangent, on every corner not touching a triangle
// with zero UV area (those get a fallback frame by rule, not by geometry).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <tuple>

#include <glm/geometric.hpp>

#include "pipeline/mesh_import.hpp"
#include "pipeline/mikktspace.hpp"

namespace gsdot3::pipeline {
namespace {

const std::filesystem::path glb = std::filesystem::path(GSDOT3_TEST_DATA) / "meshes" / "mikk_mirrored.glb";

TEST(Tangents, MikkTSpaceAgreesWithTheReferenceImplementationsTangents) {
  const imported_mesh stored = import_mesh(glb);
  ASSERT_EQ(stored.report.tangents, "file (TANGENT)");
  import_options o;
  o.tangents = tangent_mode::mikktspace;
  const imported_mesh computed = import_mesh(glb, o);
  ASSERT_EQ(computed.report.tangents, "MikkTSpace (computed)");
  EXPECT_EQ(computed.report.zero_uv_area_triangles, 1u);  // the strip's third triangle (by construction)
  ASSERT_EQ(stored.model.triangles.size(), computed.model.triangles.size());

  // Positions of the corners of zero-UV-area triangles.
  std::set<std::tuple<float, float, float>> skip;
  for (const auto& t : computed.model.triangles) {
    const glm::vec2 a = computed.model.vertices[t[0]].uv, b = computed.model.vertices[t[1]].uv,
                    c = computed.model.vertices[t[2]].uv;
    if ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y) == 0.0f)
      for (auto i : t)
        skip.insert({computed.model.vertices[i].position.x, computed.model.vertices[i].position.y,
                     computed.model.vertices[i].position.z});
  }
  std::size_t compared = 0, mirrored = 0;
  for (std::size_t t = 0; t < stored.model.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const vertex& s = stored.model.vertices[stored.model.triangles[t][k]];
      const vertex& c = computed.model.vertices[computed.model.triangles[t][k]];
      ASSERT_EQ(s.position, c.position) << "triangle " << t;
      if (skip.count({c.position.x, c.position.y, c.position.z})) continue;
      ++compared;
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(c.tangent[i], s.tangent[i], 1e-3f) << "triangle " << t << " corner " << k << " component " << i;
        EXPECT_NEAR(c.bitangent[i], s.bitangent[i], 1e-3f) << "triangle " << t << " corner " << k << " component " << i;
      }
      mirrored += glm::dot(glm::cross(c.normal, c.tangent), c.bitangent) < 0.0f;
    }
  EXPECT_GT(compared, 300u);
  EXPECT_GT(mirrored, 100u);  // the sphere's mirrored half is exercised
}

// The algorithm on a case worked by hand: a unit right triangle in the xy plane with UVs along the
// edges has dP/du = +x; with the UVs mirrored in u, dP/du = −x and the sign is −1 (the bitangent
// sign · n × t = −1 · (z × −x) = −(−y) = +y is unchanged: v still runs along +y).
TEST(Tangents, HandWorkedTriangleAndItsMirror) {
  const glm::vec3 n{0, 0, 1};
  const auto r = mikktspace_tangents({{{0, 0, 0}, n, {0, 0}}, {{1, 0, 0}, n, {1, 0}}, {{0, 1, 0}, n, {0, 1}}});
  const auto m = mikktspace_tangents({{{0, 0, 0}, n, {1, 0}}, {{1, 0, 0}, n, {0, 0}}, {{0, 1, 0}, n, {1, 1}}});
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(r.corners[static_cast<std::size_t>(k)].tangent, glm::vec3(1, 0, 0));
    EXPECT_EQ(r.corners[static_cast<std::size_t>(k)].sign, 1.0f);
    EXPECT_EQ(m.corners[static_cast<std::size_t>(k)].tangent, glm::vec3(-1, 0, 0));
    EXPECT_EQ(m.corners[static_cast<std::size_t>(k)].sign, -1.0f);
  }
  EXPECT_EQ(r.zero_uv_area_triangles + m.zero_uv_area_triangles, 0u);
}

}  // namespace
}  // namespace gsdot3::pipeline
