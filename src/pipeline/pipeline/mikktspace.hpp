// pipeline/mikktspace.hpp — per-corner tangent frames in the MikkTSpace convention (M. Mikkelsen,
// "Simulation of Wrinkled Surfaces Revisited", 2008, and the description on mikktspace.com), the
// convention glTF 2.0 prescribes and normal-map bakers (Blender, Substance, xNormal) bake against.
// Written from the algorithm's description; no code of the reference implementation is used.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace gsdot3::pipeline {

// One triangle corner as the algorithm sees it: three corners per triangle, in order.
struct tangent_corner {
  glm::vec3 position{}, normal{};  // normal: unit
  glm::vec2 uv{};
};

struct corner_tangent {
  glm::vec3 tangent{};  // unit, orthogonal to the corner's normal
  float sign = 1.0f;    // bitangent = sign · normal × tangent points along increasing uv.y
};

struct mikktspace_result {
  std::vector<corner_tangent> corners;   // one per input corner
  std::size_t zero_uv_area_triangles = 0;  // triangles whose UVs span no area (no direction of their own)
  std::size_t fallback_corners = 0;        // corners no triangle gave a direction: a fixed frame from the normal
};

// The algorithm, as described:
// 1. Corners with bit-identical position, normal and UV are one vertex (seams stay split).
// 2. Each triangle with non-zero UV area gives its direction of increasing u (dP/du) and its UV
//    orientation (the sign of its UV area: mirrored UVs have the opposite sign).
// 3. At each vertex, the triangles of one orientation form a group; the group's tangent is the
//    sum of the triangles' dP/du projected into the vertex normal's plane and normalised, each
//    weighted by the triangle's angle at the vertex (also measured in that plane), then normalised.
//    The sign is +1 for a positive UV area, −1 for a negative one.
// 4. A triangle with zero UV area takes, at each corner, the vertex's group with the larger total
//    weight (if any other triangle there has a direction); else the corner gets the fallback frame:
//    the unit vector orthogonal to the normal nearest to x (or y when the normal is near ±x), sign +1.
// Simplification against the reference implementation: it splits a vertex's triangles into groups
// by edge connectivity as well as orientation; here a vertex's triangles of one orientation are one
// group even if they do not share edges (only non-manifold "bow-tie" vertices differ).
mikktspace_result mikktspace_tangents(const std::vector<tangent_corner>& corners);

}  // namespace gsdot3::pipeline
