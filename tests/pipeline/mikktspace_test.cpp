// MikkTSpace's grouping (pipeline/mikktspace.hpp) on meshes whose every corner frame follows by hand
// from the geometry and the reference's rules: a corner's tangent is the angle-weighted sum of the
// projected dP/du of the triangles edge-connected to it around its vertex with the same UV
// orientation. Each test states which triangles group at each corner and why; the expected vectors
// are computed here from the construction (face axes, projections), never from the code under test.
// Cross-check, by hand once (not in ctest: it needs node): the same seven meshes through the npm
// package mikktspace 1.1.1 (a WASM build of the reference mikktspace.c, genTangSpaceDefault) give
// the same tangent on all 147 corners within 0.02° (float rounding) and the same sign on every one.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "pipeline/mikktspace.hpp"

namespace gsdot3::pipeline {
namespace {

constexpr float pi = std::numbers::pi_v<float>;

glm::vec3 projected(glm::vec3 v, glm::vec3 n) { return glm::normalize(v - n * glm::dot(n, v)); }

void expect_frame(const corner_tangent& got, glm::vec3 tangent, float sign, const char* what, std::size_t corner) {
  EXPECT_NEAR(got.tangent.x, tangent.x, 1e-5f) << what << " corner " << corner;
  EXPECT_NEAR(got.tangent.y, tangent.y, 1e-5f) << what << " corner " << corner;
  EXPECT_NEAR(got.tangent.z, tangent.z, 1e-5f) << what << " corner " << corner;
  EXPECT_EQ(got.sign, sign) << what << " corner " << corner;
}

// A cube [−1, 1]³ with smooth normals (the corner's diagonal, so corners of different faces can weld):
// face f spans N + a·U + b·V, a, b ∈ {−1, 1}, counter-clockwise from outside (U × V = N), two
// triangles (0, 1, 2), (0, 2, 3) over the corners (a, b) = (−1, −1), (1, −1), (1, 1), (−1, 1).
struct cube_face {
  glm::vec3 N, U, V;
};
// The first four form a band around y, U continuing from one face to the next; then +y, −y.
const std::array<cube_face, 6> faces{{{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},
                                      {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},
                                      {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
                                      {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                                      {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},
                                      {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}}};
constexpr std::array<std::array<float, 2>, 4> square{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
constexpr std::array<int, 6> triangle_corners{0, 1, 2, 0, 2, 3};

// uv_of(face, a, b) gives each corner's UV. Returns the corners, 36 of them, face by face.
template <class UvOf>
std::vector<tangent_corner> cube(UvOf uv_of) {
  std::vector<tangent_corner> out;
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int k : triangle_corners) {
      const auto [a, b] = square[static_cast<std::size_t>(k)];
      const glm::vec3 p = faces[f].N + a * faces[f].U + b * faces[f].V;
      out.push_back({p, glm::normalize(p), uv_of(f, a, b)});
    }
  return out;
}

// Split UVs: every face its own island. No corner welds across faces, so each corner's group is its
// face's triangles there, all with dP/du = U: t = U projected into the corner normal's plane.
TEST(MikkTSpaceByHand, CubeWithSplitUvsTakesEachFacesOwnAxis) {
  const auto corners = cube([](std::size_t f, float a, float b) {
    return glm::vec2(2.0f * static_cast<float>(f) + (a + 1) / 2, (b + 1) / 2);
  });
  const auto r = mikktspace_tangents(corners);
  for (std::size_t c = 0; c < corners.size(); ++c)
    expect_frame(r.corners[c], projected(faces[c / 6].U, corners[c].normal), 1.0f, "split cube", c);
}

// Shared UVs: every face maps onto the whole unit square. Corners of different faces then weld where
// their UVs agree — at (1, 1, −1), +x and +y both have uv (1, 1) — but on no cube edge do two faces
// agree at both ends (asserted below), so no two faces are edge-connected and, as with split UVs,
// each corner takes its own face's U. Grouping by vertex and orientation alone would mix the welded
// faces' axes.
TEST(MikkTSpaceByHand, CubeWithSharedUvsGroupsByEdgesNotByWeldedCorners) {
  const auto corners = cube([](std::size_t, float a, float b) { return glm::vec2((a + 1) / 2, (b + 1) / 2); });
  std::size_t welded_across = 0, edges_agreeing = 0;
  for (std::size_t c = 0; c < corners.size(); ++c)
    for (std::size_t d = 0; d < corners.size(); ++d) {
      if (c / 6 == d / 6 || corners[c].position != corners[d].position) continue;
      if (corners[c].uv != corners[d].uv) continue;
      ++welded_across;
      // An edge from this corner's triangle that d's triangle also has, with the same UVs at the far end.
      for (std::size_t e = 3 * (c / 3); e < 3 * (c / 3) + 3; ++e)
        for (std::size_t g = 3 * (d / 3); g < 3 * (d / 3) + 3; ++g)
          edges_agreeing +=
              e != c && g != d && corners[e].position == corners[g].position && corners[e].uv == corners[g].uv;
    }
  ASSERT_GT(welded_across, 0u);   // the case is exercised
  ASSERT_EQ(edges_agreeing, 0u);  // and is the one described
  const auto r = mikktspace_tangents(corners);
  for (std::size_t c = 0; c < corners.size(); ++c)
    expect_frame(r.corners[c], projected(faces[c / 6].U, corners[c].normal), 1.0f, "shared cube", c);
}

// A band: the first four faces share their vertical edges in UV (u runs 0..4 around y, continuous
// except for the seam between the fourth face and the first); the caps are islands. At a band corner
// away from the seam, the two band faces are edge-connected: one group. Each face spans 120° of the
// corner seen along the diagonal normal (the cube's three-fold symmetry), so the weights are equal and
// t = normalize(proj U_A + proj U_B). Seam and cap corners take their own face's U.
TEST(MikkTSpaceByHand, CubeWithAUvBandSumsTheConnectedFaces) {
  const auto corners = cube([](std::size_t f, float a, float b) {
    return glm::vec2(static_cast<float>(f < 4 ? f : 2 * f) + (a + 1) / 2, (b + 1) / 2);
  });
  const auto r = mikktspace_tangents(corners);
  for (std::size_t c = 0; c < corners.size(); ++c) {
    const std::size_t f = c / 6;
    const float a = square[static_cast<std::size_t>(triangle_corners[c % 6])][0];
    const glm::vec3 n = corners[c].normal;
    glm::vec3 t = projected(faces[f].U, n);
    if (f < 3 && a > 0) t = glm::normalize(t + projected(faces[f + 1].U, n));
    if (f >= 1 && f < 4 && a < 0) t = glm::normalize(t + projected(faces[f - 1].U, n));
    expect_frame(r.corners[c], t, 1.0f, "band cube", c);
  }
}

// A mirrored UV seam on a roof: two panels meet at a ridge along y (ridge normal +z, elsewhere the
// panel normals); u = 1 + x on the left, u = 1 − x on the right (mirrored), v = y. The ridge corners
// weld and the panels share the ridge edge, but their UV orientations differ: two groups. Left:
// dP/du = (1, 0, 1)/√2, sign +1; right: (−1, 0, 1)/√2, sign −1; at the ridge projected onto z's plane.
TEST(MikkTSpaceByHand, MirroredSeamSplitsTheGroupAtTheRidge) {
  const glm::vec3 nl = glm::normalize(glm::vec3(-1, 0, 1)), nr = glm::normalize(glm::vec3(1, 0, 1)), up{0, 0, 1};
  auto corner = [&](glm::vec3 p, bool right) {
    return tangent_corner{p, p.x == 0.0f ? up : (right ? nr : nl), {right ? 1 - p.x : 1 + p.x, p.y}};
  };
  const std::array<glm::vec3, 4> left{{{-1, 0, 0}, {0, 0, 1}, {0, 1, 1}, {-1, 1, 0}}};
  const std::array<glm::vec3, 4> right{{{0, 0, 1}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1}}};
  std::vector<tangent_corner> corners;
  for (int k : triangle_corners) corners.push_back(corner(left[static_cast<std::size_t>(k)], false));
  for (int k : triangle_corners) corners.push_back(corner(right[static_cast<std::size_t>(k)], true));
  const auto r = mikktspace_tangents(corners);
  for (std::size_t c = 0; c < corners.size(); ++c) {
    const bool is_right = c >= 6;
    const glm::vec3 pu = is_right ? glm::vec3(-1, 0, 1) : glm::vec3(1, 0, 1);
    expect_frame(r.corners[c], projected(pu, corners[c].normal), is_right ? -1.0f : 1.0f, "roof", c);
  }
}

// Mirrored seams crossing at a vertex: a fan of four triangles around c = 0 in the z = 0 plane, rim
// (1,0,0), (0,1,0), (−1,0,0), (0,−1,0), UVs per vertex c (0,0), rim (1,0), (0,1), (1,0), (0,1) — the
// map folded on both axes. The orientations alternate +, −, +, −, so although every corner at c welds
// and every spoke is a shared edge, each triangle is its own group everywhere. dP/du, by solving
// the UVs: +x, −x, −x, +x. (Grouping by orientation alone sums +x and −x at c: no direction.)
TEST(MikkTSpaceByHand, AlternatingMirrorsAroundAVertexKeepEveryTriangleApart) {
  const glm::vec3 n{0, 0, 1}, c{0, 0, 0};
  const std::array<glm::vec3, 4> rim{{{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}}};
  const std::array<glm::vec2, 4> rim_uv{{{1, 0}, {0, 1}, {1, 0}, {0, 1}}};
  std::vector<tangent_corner> corners;
  for (std::size_t t = 0; t < 4; ++t) {
    corners.push_back({c, n, {0, 0}});
    corners.push_back({rim[t], n, rim_uv[t]});
    corners.push_back({rim[(t + 1) % 4], n, rim_uv[(t + 1) % 4]});
  }
  const std::array<glm::vec3, 4> pu{{{1, 0, 0}, {-1, 0, 0}, {-1, 0, 0}, {1, 0, 0}}};
  const std::array<float, 4> sign{1, -1, 1, -1};
  const auto r = mikktspace_tangents(corners);
  for (std::size_t k = 0; k < corners.size(); ++k) expect_frame(r.corners[k], pu[k / 3], sign[k / 3], "folded fan", k);
  EXPECT_EQ(r.fallback_corners, 0u);
}

// A bow-tie vertex: at c = 0 a fan of two triangles, T1 (c, x, y) with UVs (0,0), (1,0), (0,1)
// (dP/du = x, angle 90° at c) and T2 (c, y, (−1,1,0)) with (0,0), (0,1), (−1,2) (dP/du = (1,1,0)/√2,
// angle 45° at c), touches a third triangle Tb (c, −y, (1,−1,0)), UVs (0,0), (1,0), (1,1)
// (dP/du = −y), only at c: same position, normal and UV there, same orientation, no shared edge.
// At c: T1 and T2 group, t = normalize(π/2·x + π/4·(1,1,0)/√2); Tb alone, t = −y. At y, shared by T1
// (45°) and T2 (90°): t = normalize(π/4·x + π/2·(1,1,0)/√2). Every other corner: its own dP/du.
TEST(MikkTSpaceByHand, BowTieVertexKeepsItsTwoFansApart) {
  const glm::vec3 n{0, 0, 1}, c{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0};
  const std::vector<tangent_corner> corners{{c, n, {0, 0}}, {x, n, {1, 0}},  {y, n, {0, 1}},
                                            {c, n, {0, 0}}, {y, n, {0, 1}},  {{-1, 1, 0}, n, {-1, 2}},
                                            {c, n, {0, 0}}, {-y, n, {1, 0}}, {{1, -1, 0}, n, {1, 1}}};
  const glm::vec3 d2 = glm::normalize(glm::vec3(1, 1, 0));
  const glm::vec3 at_c = glm::normalize(pi / 2 * x + pi / 4 * d2), at_y = glm::normalize(pi / 4 * x + pi / 2 * d2);
  const std::array<glm::vec3, 9> expected{at_c, x, at_y, at_c, at_y, d2, -y, -y, -y};
  const auto r = mikktspace_tangents(corners);
  for (std::size_t k = 0; k < corners.size(); ++k) expect_frame(r.corners[k], expected[k], 1.0f, "bow-tie", k);
}

// A triangle with zero UV area joins the group of an edge-connected neighbour (taking its
// orientation) and adds nothing to it: a quad whose second triangle has all three UVs equal.
TEST(MikkTSpaceByHand, ZeroUvAreaTriangleJoinsItsNeighboursGroup) {
  const glm::vec3 n{0, 0, 1};
  // T0 (0,0), (1,0), (1,1) with mirrored UVs (u = −x): dP/du = −x, sign −1; T1 (0,0), (1,1), (0,1) flat UVs.
  const std::vector<tangent_corner> corners{{{0, 0, 0}, n, {0, 0}}, {{1, 0, 0}, n, {-1, 0}}, {{1, 1, 0}, n, {-1, 1}},
                                            {{0, 0, 0}, n, {0, 0}}, {{1, 1, 0}, n, {-1, 1}}, {{0, 1, 0}, n, {-1, 1}}};
  const auto r = mikktspace_tangents(corners);
  EXPECT_EQ(r.zero_uv_area_triangles, 1u);
  // T1's corners at (0,0) and (1,1) weld with T0's and share the diagonal: −x, −1. Its corner at
  // (0,1) (UV (−1, 1), welded with nothing) has no group: the fallback x and the reference's sign −1.
  const std::array<glm::vec3, 6> expected{{{-1, 0, 0}, {-1, 0, 0}, {-1, 0, 0}, {-1, 0, 0}, {-1, 0, 0}, {1, 0, 0}}};
  for (std::size_t k = 0; k < corners.size(); ++k) expect_frame(r.corners[k], expected[k], -1.0f, "quad", k);
  EXPECT_EQ(r.fallback_corners, 1u);
}

}  // namespace
}  // namespace gsdot3::pipeline
