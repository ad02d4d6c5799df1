// tests/schemes/powervr/mesh_test.cpp — the seed's flipped-UV check on the shared mesh: KMBump.c
// CalculateTangentSpaceMethodUpRight mirrors the binormal when (uA − uC)(vB − vC) > (uB − uC)(vA − vC),
// i.e. when the triangle's UVs run clockwise. On every triangle of the embedded scene that check must
// agree with the handedness of gsdot3's tangent frame (dot(n × t, b) < 0 = mirrored) at its three
// vertices, and a mirrored frame must leave the PowerVR intensity what the mirrored texel means.
#include <gtest/gtest.h>

#include <cstdio>

#include <glm/geometric.hpp>

#include "pipeline/default_scene.hpp"
#include "powervr/encode.hpp"
#include "powervr/evaluate.hpp"
#include "powervr/texture.hpp"

namespace gsdot3::schemes::powervr {
namespace {

// Per triangle: the SDK's clockwise-UV test, and whether each vertex frame is mirrored relative to
// `unmirrored` (the sign of dot(n × t, b) on an unmirrored triangle: gsdot3's v runs down the image).
struct check {
  int triangles = 0, clockwise = 0, disagree = 0;
};
check run_check(const pipeline::mesh& m, float unmirrored) {
  check c;
  for (const auto& tri : m.triangles) {
    const auto &A = m.vertices[tri[0]], &B = m.vertices[tri[1]], &C = m.vertices[tri[2]];
    const bool sdk_flip = (A.uv.x - C.uv.x) * (B.uv.y - C.uv.y) > (B.uv.x - C.uv.x) * (A.uv.y - C.uv.y);
    ++c.triangles;
    c.clockwise += sdk_flip;
    for (const auto* v : {&A, &B, &C})
      if ((glm::dot(glm::cross(v->normal, v->tangent), v->bitangent) * unmirrored < 0) != sdk_flip) ++c.disagree;
  }
  return c;
}

TEST(PowervrMesh, ClockwiseUvCheckAgreesWithTheTangentFrameOnEveryTriangle) {
  auto s = pipeline::default_scene();
  const auto& v0 = s.model.vertices[s.model.triangles[0][0]];
  const float unmirrored = glm::dot(glm::cross(v0.normal, v0.tangent), v0.bitangent) < 0 ? -1.0f : 1.0f;
  const check plain = run_check(s.model, unmirrored);
  std::printf("shared mesh: %d triangles, %d with clockwise UVs, %d vertex frames disagreeing\n", plain.triangles,
              plain.clockwise, plain.disagree);
  EXPECT_EQ(plain.clockwise, 0);  // the embedded head has no mirrored UVs
  EXPECT_EQ(plain.disagree, 0);
  // The same mesh with u mirrored (u → −u) and its frames recomputed: every triangle is now clockwise,
  // and the check flags exactly the frames gsdot3 mirrors.
  for (auto& v : s.model.vertices) v.uv.x = -v.uv.x;
  pipeline::compute_tangents(s.model);
  const check mirrored = run_check(s.model, unmirrored);
  std::printf("mirrored u: %d triangles, %d with clockwise UVs, %d vertex frames disagreeing\n", mirrored.triangles,
              mirrored.clockwise, mirrored.disagree);
  EXPECT_EQ(mirrored.clockwise, mirrored.triangles);
  EXPECT_EQ(mirrored.disagree, 0);
}

TEST(PowervrMesh, MirroringTheFrameGivesTheMirroredTexelsShading) {
  // On a mirrored triangle a texel's normal is (−x, y, z) in the unmirrored frame. The fix expresses
  // the light in the mirrored frame (x negated) before computing Q: the exact intensity of the
  // texel's K/Q is then the intensity of the mirrored normal, to the Q quantisation (≤ K3·π/255).
  const glm::dvec3 L = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
  for (int i = 0; i < 65536; i += 11) {
    const auto t = bump_texel::unpack(static_cast<std::uint16_t>(i));
    glm::dvec3 N = decode_normal(t, azimuth_scale::flycast_255);
    N.x = -N.x;
    const offset_colour k = offset_nearest(seed_atan2({-L.x, L.y, L.z}, 1.0), azimuth_scale::flycast_255);
    ASSERT_NEAR(intensity_exact(t, k, azimuth_scale::flycast_255), 255.0 * glm::dot(N, L),
                0.5 + 0.5 + k.K3 * 3.1415927 / 255.0)
        << i;
  }
}

}  // namespace
}  // namespace gsdot3::schemes::powervr
