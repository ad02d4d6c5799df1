// Crease-angle normals (generated_normals.hpp) on meshes whose expected normals follow from how they
// are built: a cube's face normals are the axes its faces were laid out on, a hinge's shared normal
// is the bisector of its two wings, a fine sphere's normals stay one per position.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "pipeline/generated_normals.hpp"

namespace gsdot3::pipeline {
namespace {

struct soup {
  std::vector<glm::vec3> positions;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<glm::vec3> expected_face;  // per triangle, stated by construction
};

// The unit cube [-1, 1]³ as an OBJ importer gives it: every face corner its own vertex (24 vertices,
// the faces' corners at shared positions). Each face is listed with its outward axis and its corners
// counter-clockwise seen from outside.
soup cube() {
  soup s;
  const std::array<std::tuple<glm::vec3, glm::vec3, glm::vec3>, 6> faces = {{
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},   // outward axis, then u and v with u × v = axis
      {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},  //
      {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},   //
      {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},  //
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},   //
      {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},  //
  }};
  for (const auto& [n, u, v] : faces) {
    const auto base = static_cast<std::uint32_t>(s.positions.size());
    for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
      s.positions.push_back(n + c.x * u + c.y * v);
    s.triangles.push_back({base, base + 1, base + 2});
    s.triangles.push_back({base, base + 2, base + 3});
    s.expected_face.insert(s.expected_face.end(), {n, n});
  }
  return s;
}

// Two wings on the edge (0,0,0)–(1,0,0): A in the xy plane (normal +z), B folded up so its normal
// is (0, sin 45°, cos 45°). Both have the corner angle atan(2) at each end of the shared edge.
soup hinge() {
  const float c = std::sqrt(0.5f);
  return {{{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, {1, 0, 0}, {0, 0, 0}, {0.5f, -c, c}},
          {{0, 1, 2}, {3, 4, 5}},
          {{0, 0, 1}, {0, c, c}}};
}

void expect_near(glm::vec3 a, glm::vec3 b, float tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

std::vector<glm::vec3> normals(const soup& s, float crease) {
  return crease_normals(s.positions, s.triangles, std::vector<char>(s.triangles.size(), 1), crease);
}

TEST(CreaseNormals, CubeAtTheDefaultAngleGetsItsFaceNormals) {
  const soup s = cube();
  for (float crease : {60.0f, 89.0f}) {  // the faces meet at 90°
    const std::vector<glm::vec3> n = normals(s, crease);
    for (std::size_t c = 0; c < n.size(); ++c) expect_near(n[c], s.expected_face[c / 3], 1e-6f);
  }
}

TEST(CreaseNormals, CubeAboveNinetyDegreesIsSmoothAtEveryCorner) {
  // Three faces meet at each corner, each with a total angle of π/2 there (one 90° corner or two of
  // 45°): the normal is the corner's diagonal, the old fully smooth result.
  const soup s = cube();
  for (float crease : {91.0f, 180.0f}) {
    const std::vector<glm::vec3> n = normals(s, crease);
    for (std::size_t t = 0; t < s.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) expect_near(n[3 * t + k], glm::normalize(s.positions[s.triangles[t][k]]), 1e-6f);
  }
}

TEST(CreaseNormals, HingeSplitsAboveTheAngleAndSharesTheBisectorBelowIt) {
  const soup s = hinge();
  const std::vector<glm::vec3> split = normals(s, 44.0f);  // the wings differ by 45°
  for (std::size_t c = 0; c < 6; ++c) expect_near(split[c], s.expected_face[c / 3], 1e-6f);
  const std::vector<glm::vec3> smooth = normals(s, 46.0f);
  // Equal corner angles at both ends of the edge: the normal halfway, 22.5° from +z towards +y.
  const glm::vec3 bisector(0.0f, std::sin(0.3926991f), std::cos(0.3926991f));
  for (std::size_t c : {0u, 1u, 3u, 4u}) expect_near(smooth[c], bisector, 1e-6f);
  expect_near(smooth[2], s.expected_face[0], 1e-6f);  // the wings' far corners keep their own
  expect_near(smooth[5], s.expected_face[1], 1e-6f);
}

TEST(CreaseNormals, FineSphereStaysSmooth) {
  // A UV sphere of 24 segments and 12 rings: neighbouring faces differ by at most 30°.
  soup s;
  constexpr int seg = 24, rings = 12;
  constexpr float pi = 3.14159265f;
  auto at = [](int i, int j) {
    if (j == 0 || j == rings) return glm::vec3(0.0f, j == 0 ? 1.0f : -1.0f, 0.0f);  // one pole position
    const float th = pi * static_cast<float>(j) / rings, ph = 2 * pi * static_cast<float>(i % seg) / seg;
    return glm::vec3(std::sin(th) * std::cos(ph), std::cos(th), -std::sin(th) * std::sin(ph));
  };
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < seg; ++i) {  // each quad's corners as their own vertices, as OBJ importers give them
      const auto base = static_cast<std::uint32_t>(s.positions.size());
      s.positions.insert(s.positions.end(), {at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)});
      if (j > 0) s.triangles.push_back({base, base + 1, base + 3});
      if (j + 1 < rings) s.triangles.push_back({base + 1, base + 2, base + 3});
    }
  const std::vector<glm::vec3> n = normals(s, 60.0f);
  std::map<std::tuple<float, float, float>, glm::vec3> first;  // every corner at a position: one normal
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 p = s.positions[s.triangles[t][k]];
      const auto [it, fresh] = first.try_emplace({p.x, p.y, p.z}, n[3 * t + k]);
      if (!fresh) { EXPECT_EQ(glm::length(it->second - n[3 * t + k]), 0.0f) << p.x << "," << p.y << "," << p.z; }
      EXPECT_GT(glm::dot(n[3 * t + k], glm::normalize(p)), std::cos(0.05f));  // within 3° of the radius
    }
}

TEST(CreaseNormals, DroppedTrianglesNeitherGetNorContributeANormal) {
  const soup s = hinge();
  const std::vector<glm::vec3> n = crease_normals(s.positions, s.triangles, {1, 0}, 180.0f);
  for (std::size_t c = 0; c < 3; ++c) expect_near(n[c], s.expected_face[0], 1e-6f);
  for (std::size_t c = 3; c < 6; ++c) EXPECT_EQ(glm::length(n[c]), 0.0f);
}

}  // namespace
}  // namespace gsdot3::pipeline
