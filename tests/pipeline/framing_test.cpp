// Framing: for random models (random sizes, offsets, aspect ratios, views), every vertex projects
// inside the frame. Checked twice: with GLM's own glm::project (a projection written independently
// of prepare's), and through prepare itself (nothing dropped outside the guard band, every drawn
// vertex inside the window).
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_projection.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "pipeline/default_scene.hpp"
#include "pipeline/framing.hpp"
#include "pipeline/prepare.hpp"

namespace gsdot3::pipeline {
namespace {

// A random triangle soup in a random anisotropic box far from the origin, each triangle in both
// windings (so one of the two is front-facing from any view).
mesh random_model(std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f), expo(-3.0f, 4.0f);
  const glm::vec3 scale{std::pow(10.0f, expo(rng)), std::pow(10.0f, expo(rng)), std::pow(10.0f, expo(rng))};
  const glm::vec3 offset = glm::vec3(unit(rng), unit(rng), unit(rng)) * 1e4f;
  mesh m;
  const int triangles = std::uniform_int_distribution<int>(1, 60)(rng);
  for (int t = 0; t < triangles; ++t) {
    const auto base = static_cast<std::uint32_t>(m.vertices.size());
    for (int k = 0; k < 3; ++k) {
      vertex v;
      v.position = offset + glm::vec3(unit(rng), unit(rng), unit(rng)) * scale;
      v.normal = {0, 0, 1};
      v.tangent = {1, 0, 0};
      v.bitangent = {0, 1, 0};
      m.vertices.push_back(v);
    }
    m.triangles.push_back({base, base + 1, base + 2});
    m.triangles.push_back({base, base + 2, base + 1});
  }
  return m;
}

TEST(Framing, EveryVertexOfRandomModelsProjectsInsideTheFrame) {
  std::mt19937 rng(9);
  std::uniform_int_distribution<int> side(16, 2048);
  std::uniform_real_distribution<float> az(-180.0f, 180.0f), el(-89.0f, 89.0f);
  for (int trial = 0; trial < 300; ++trial) {
    scene s;
    s.model = random_model(rng);
    normalise(s.model, bounds_of(s.model));
    s.width = side(rng);
    s.height = side(rng);
    s.normals = procedural_normal_map(8);
    const float a = az(rng), e = el(rng);
    s.view = frame_unit_sphere(a, e, s.width, s.height);
    SCOPED_TRACE("trial " + std::to_string(trial) + ", " + std::to_string(s.width) + "x" + std::to_string(s.height));

    const glm::mat4 view = glm::lookAt(s.view.eye, s.view.target, glm::vec3(0, 1, 0));
    const glm::mat4 proj = glm::perspective(glm::radians(s.view.fov_y_degrees),
                                            static_cast<float>(s.width) / static_cast<float>(s.height), 0.1f, 100.0f);
    const glm::vec4 viewport(0, 0, s.width, s.height);
    for (const vertex& v : s.model.vertices) {
      EXPECT_LE(glm::length(v.position), 1.0f + 1e-5f);
      const glm::vec3 w = glm::project(v.position, view, proj, viewport);
      EXPECT_GE(w.x, 0.0f);
      EXPECT_LE(w.x, static_cast<float>(s.width));
      EXPECT_GE(w.y, 0.0f);
      EXPECT_LE(w.y, static_cast<float>(s.height));
      EXPECT_GT(w.z, 0.0f);  // between the near and far planes
      EXPECT_LT(w.z, 1.0f);
    }
    // The frame is filled: a point of the unit sphere beside the centre, across the tighter axis,
    // lands at least 80 % of the way to the frame's edge (cos 20° / 1.1 ≈ 0.854 by construction).
    const glm::vec3 forward = glm::normalize(s.view.target - s.view.eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0))), up = glm::cross(right, forward);
    const bool tall = s.height > s.width;  // the horizontal field is the tighter one
    const glm::vec3 edge = glm::project(tall ? right : up, view, proj, viewport);
    const float reach =
        tall ? (edge.x - s.width / 2.0f) / (s.width / 2.0f) : (edge.y - s.height / 2.0f) / (s.height / 2.0f);
    EXPECT_GT(reach, 0.8f);
    EXPECT_LT(reach, 1.0f);

    const prepared_scene ps = prepare(s);
    EXPECT_EQ(ps.dropped_outside, 0);
    for (const prepared_triangle& t : ps.triangles)
      for (const xy124& p : t.setup.v) {
        EXPECT_GE(p.x, 0);
        EXPECT_LE(p.x, 16 * s.width);
        EXPECT_GE(p.y, 0);
        EXPECT_LE(p.y, 16 * s.height);
      }
  }
}

// Outside the GS's 12.4 coordinate space (the guard band), a triangle is dropped and counted,
// never drawn with wrapped coordinates: a camera inside a model, and one looking past it.
TEST(Framing, OutsideTheGuardBandIsDroppedNotWrapped) {
  scene s = default_scene(8);
  s.width = 64;
  s.height = 56;
  s.view.eye = {0.0f, 0.0f, 0.3f};  // inside the head: triangles behind the eye and far off-screen
  const prepared_scene ps = prepare(s);
  EXPECT_GT(ps.dropped_outside, 0);
  for (const prepared_triangle& t : ps.triangles)
    for (const xy124& p : t.setup.v) {
      EXPECT_LT(std::abs(p.x), 16 * xy_offset_pixels);
      EXPECT_LT(std::abs(p.y), 16 * xy_offset_pixels);
    }
}

// One triangle in the unit sphere, its corners in the order given.
mesh one_triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  mesh m;
  for (const glm::vec3 p : {a, b, c}) m.vertices.push_back({p, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0}});
  m.triangles.push_back({0, 1, 2});
  return m;
}

// The view that sees the front of the faces: expected views by the triangles' construction, and
// prepare's back-face culling (the renderer's own test, on screen coordinates) agreeing that it
// draws the triangle from there.
TEST(Framing, TheDefaultViewTurnsToTheFrontOfTheFaces) {
  struct want {
    mesh m;
    float azimuth, elevation;
  };
  const std::vector<want> cases = {
      {one_triangle({-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0, 0.5f, 0}), 0.0f, 0.0f},    // counter-clockwise from +z
      {one_triangle({-0.5f, -0.5f, 0}, {0, 0.5f, 0}, {0.5f, -0.5f, 0}), 180.0f, 0.0f},  // clockwise: seen from −z
      {one_triangle({-0.5f, 0, 0.5f}, {0.5f, 0, 0.5f}, {0, 0, -0.5f}), 0.0f, 89.0f},    // faces +y, edge-on to both
      {one_triangle({-0.5f, 0, 0.5f}, {0, 0, -0.5f}, {0.5f, 0, 0.5f}), 0.0f, -89.0f}};  // faces −y
  for (const want& w : cases) {
    const std::optional<front_view> v = view_of_fronts(w.m, 64, 48, 40.0f);
    ASSERT_TRUE(v.has_value());
    EXPECT_NEAR(v->azimuth, w.azimuth, 1e-4f);
    EXPECT_NEAR(v->elevation, w.elevation, 1e-4f);
    EXPECT_EQ(v->facing, 1u);
    scene s;
    s.model = w.m;
    s.width = 64;
    s.height = 48;
    s.normals = procedural_normal_map(8);
    s.view = frame_unit_sphere(v->azimuth, v->elevation, 64, 48);
    EXPECT_EQ(prepare(s).culled_back, 0);
    s.view = frame_unit_sphere(v->azimuth + 180.0f, -v->elevation, 64, 48);  // the opposite side culls it
    EXPECT_EQ(prepare(s).culled_back, 1);
  }
  // A triangle of zero area faces no view.
  EXPECT_FALSE(view_of_fronts(one_triangle({0, 0, 0}, {1, 0, 0}, {0.5f, 0, 0}), 64, 48, 40.0f).has_value());
}

}  // namespace
}  // namespace gsdot3::pipeline
