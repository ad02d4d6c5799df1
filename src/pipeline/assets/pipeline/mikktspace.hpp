// pipeline/mikktspace.hpp — per-corner tangent frames in the MikkTSpace convention (M. Mikkelsen,
// "Simulation of Wrinkled Surfaces Revisited", 2008), the convention glTF 2.0 prescribes and
// normal-map bakers (Blender, Substance, xNormal) bake against. The behaviour follows the reference
// implementation, mikktspace.c (github mmikk/MikkTSpace), read for its rules; no code of it is used.
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
  std::vector<corner_tangent> corners;     // one per input corner
  std::size_t zero_uv_area_triangles = 0;  // triangles whose UVs span no area (no direction of their own)
  std::size_t fallback_corners = 0;        // corners no triangle gave a direction: a fixed frame from the normal
};

// The algorithm, as mikktspace.c's genTangSpace (default angular threshold 180°, from
// genTangSpaceDefault) does it for triangles:
// 1. Corners with equal position, normal and UV are one vertex (GenerateSharedVerticesIndexList).
// 2. Each triangle with non-zero UV area has its unit directions of increasing u and v (dP/du,
//    dP/dv, negated on a triangle with negative UV area) and its orientation, the sign of its UV area
//    (InitTriInfo); one with zero UV area has none and groups with any neighbour ("group with any").
// 3. Two triangles are neighbours across an edge whose two vertices they share, traversed in
//    opposite directions; an edge of more than two triangles pairs them in triangle order
//    (BuildNeighborsFast).
// 4. At each vertex, a group is the triangles reached from a triangle through neighbours across the
//    edges at that vertex, all of one orientation; a zero-UV-area triangle takes the orientation of
//    the first group that reaches it (Build4RuleGroups, AssignRecur). So a vertex's triangles that
//    share no edge there (a bow-tie vertex, or faces of a cube whose UVs meet only at a corner) are
//    separate groups, as are the two sides of a mirrored UV seam.
// 5. A corner's tangent is the sum over the triangles of its group whose projected dP/du and dP/dv
//    are not both opposite to its own triangle's (cosine > cos 180°; GenerateTSpaces) of dP/du
//    projected into the vertex normal's plane and normalised, each weighted by the triangle's angle
//    at the vertex measured in that plane, then normalised (EvalTspace). The sign is +1 for a group
//    of positive UV area, −1 for negative.
// 6. A triangle with two equal positions takes, at each corner, the frame of the first other
//    triangle's corner at the same vertex (DegenEpilogue).
// Where the reference leaves a corner without a direction (a zero-UV-area triangle no group reached,
// or a group whose sum is zero) it returns (1, 0, 0) unprojected; here the corner gets the unit
// vector orthogonal to the normal nearest to x (or y when the normal is near ±x), the renderer
// needing an orthogonal frame, with the reference's sign (−1 unreached, else the group's).
// Faces are triangles here (the importer triangulates): the reference's quad rules do not arise.
mikktspace_result mikktspace_tangents(const std::vector<tangent_corner>& corners);

}  // namespace gsdot3::pipeline
