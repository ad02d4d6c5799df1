// The rule that picks a UV projection for a mesh without UVs (uv_generation.hpp), on shapes whose
// figures are worked by hand: a quad faces its axis fully, a slab of thickness t has mean |n·z|
// 2 / (2 + 4t), a cube 1/3 and 3/√11 = 0.905 (two triangles a side), an octahedron's faces look
// straight out from its centre.
#include <gtest/gtest.h>

#include <glm/common.hpp>

#include "pipeline/uv_generation.hpp"

namespace gsdot3::pipeline {
namespace {

using tris = std::vector<std::array<glm::vec3, 3>>;

uv_bounds bounds(const tris& t) {
  uv_bounds b;
  for (const auto& p : t)
    for (const glm::vec3& q : p) {
      b.lo = glm::min(b.lo, q);
      b.hi = glm::max(b.hi, q);
    }
  return b;
}

// An axis-aligned box [0, x] × [0, y] × [0, z], two triangles a side (orientation does not matter:
// the rule takes |n·a|).
tris box_of(float x, float y, float z) {
  tris t;
  auto quad = [&](glm::vec3 o, glm::vec3 u, glm::vec3 v) {
    t.push_back({o, o + u, o + u + v});
    t.push_back({o, o + u + v, o + v});
  };
  const glm::vec3 X(x, 0, 0), Y(0, y, 0), Z(0, 0, z), O(0.0f);
  quad(O, X, Y), quad(Z, X, Y), quad(O, X, Z), quad(Y, X, Z), quad(O, Y, Z), quad(X, Y, Z);
  return t;
}

projection_choice choose(const tris& t) { return choose_projection(t, bounds(t)); }

TEST(UvProjectionRule, AFlatQuadIsPlanar) {
  const tris quad = {{glm::vec3(0, 0, 0), glm::vec3(2, 0, 0), glm::vec3(2, 1, 0)},
                     {glm::vec3(0, 0, 0), glm::vec3(2, 1, 0), glm::vec3(0, 1, 0)}};
  const projection_choice c = choose(quad);
  EXPECT_EQ(c.how, uv_projection::planar);
  EXPECT_EQ(c.why, "the surface faces one axis: mean |n.axis| 1.000 >= 0.90");
}

TEST(UvProjectionRule, ASlabIsPlanarUpToTheBoundaryThickness) {
  // Mean |n·z| = 2 / (2 + 4t) for the 1 × 1 × t slab: 0.909 at t = 0.05, 0.893 at t = 0.06 (0.9 at 1/18).
  EXPECT_EQ(choose(box_of(1, 1, 0.05f)).how, uv_projection::planar);
  const projection_choice thick = choose(box_of(1, 1, 0.06f));
  EXPECT_EQ(thick.how, uv_projection::box);
  EXPECT_NE(thick.why.find("mean |n.axis| 0.893 < 0.90"), std::string::npos) << thick.why;
  EXPECT_EQ(choose(box_of(0.05f, 1, 1)).how, uv_projection::planar);  // the thin axis is x
}

TEST(UvProjectionRule, ACubeIsBoxProjected) {
  const projection_choice c = choose(box_of(2, 2, 2));
  EXPECT_EQ(c.how, uv_projection::box);
  EXPECT_EQ(c.why, "neither flat (mean |n.axis| 0.333 < 0.90) nor round (mean |n.radial| 0.905 < 0.95)");
}

TEST(UvProjectionRule, AnOctahedronIsSphereProjected) {
  tris t;
  for (float sx : {-1.0f, 1.0f})
    for (float sy : {-1.0f, 1.0f})
      for (float sz : {-1.0f, 1.0f}) t.push_back({glm::vec3(sx, 0, 0), glm::vec3(0, sy, 0), glm::vec3(0, 0, sz)});
  const projection_choice c = choose(t);
  EXPECT_EQ(c.how, uv_projection::sphere);
  EXPECT_EQ(c.why, "the surface faces away from its centre: mean |n.radial| 1.000 >= 0.95");
}

TEST(UvProjectionRule, PlanarMapsTheTwoLargestSidesOntoOneRepeat) {
  // The quad of AFlatQuadIsPlanar: u = x / 2 along the largest side, v = (1 − y) / 2 down the image.
  const tris quad = {{glm::vec3(0, 0, 0), glm::vec3(2, 0, 0), glm::vec3(2, 1, 0)}};
  const auto uv = project(uv_projection::planar, quad[0], bounds(quad));
  EXPECT_EQ(uv[0], glm::vec2(0.0f, 0.5f));
  EXPECT_EQ(uv[1], glm::vec2(1.0f, 0.5f));
  EXPECT_EQ(uv[2], glm::vec2(1.0f, 0.0f));
}

}  // namespace
}  // namespace gsdot3::pipeline
