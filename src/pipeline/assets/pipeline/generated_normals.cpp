// pipeline/generated_normals.cpp — crease-angle normals (see generated_normals.hpp).
#include "pipeline/generated_normals.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <unordered_map>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "pipeline/word_hash.hpp"

namespace gsdot3::pipeline {

namespace {

float corner_angle(glm::vec3 p, glm::vec3 a, glm::vec3 b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a - p), glm::normalize(b - p)), -1.0f, 1.0f));
}

// Union-find over the corners, with path halving.
struct groups {
  std::vector<std::size_t> parent;
  explicit groups(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t{0}); }
  std::size_t find(std::size_t c) {
    while (parent[c] != c) c = parent[c] = parent[parent[c]];
    return c;
  }
  void join(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

}  // namespace

std::vector<glm::vec3> crease_normals(const std::vector<glm::vec3>& positions,
                                      const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                      const std::vector<char>& keep, float crease_degrees) {
  // Each vertex's position as a small id (vertices at bit-identical positions share it).
  std::unordered_map<std::array<std::uint32_t, 3>, std::uint32_t, word_hash> ids;
  std::vector<std::uint32_t> at(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const glm::vec3 p = positions[i];
    const std::array<std::uint32_t, 3> key = {std::bit_cast<std::uint32_t>(p.x), std::bit_cast<std::uint32_t>(p.y),
                                              std::bit_cast<std::uint32_t>(p.z)};
    at[i] = ids.try_emplace(key, static_cast<std::uint32_t>(ids.size())).first->second;
  }

  std::vector<glm::vec3> face(triangles.size(), glm::vec3(0.0f));
  // The triangles on each edge (its two position ids, the smaller first), in triangle order.
  std::unordered_map<std::array<std::uint32_t, 2>, std::vector<std::size_t>, word_hash> edges;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (!keep[t]) continue;
    const auto& tri = triangles[t];
    face[t] = glm::normalize(glm::cross(positions[tri[1]] - positions[tri[0]], positions[tri[2]] - positions[tri[0]]));
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = at[tri[k]], b = at[tri[(k + 1) % 3]];
      edges[{std::min(a, b), std::max(a, b)}].push_back(t);
    }
  }

  // Faces within the crease angle join their corners at both ends of the shared edge.
  const float limit = std::cos(glm::radians(crease_degrees));
  auto corner_at = [&](std::size_t t, std::uint32_t id) {
    const auto& tri = triangles[t];
    return 3 * t + (at[tri[0]] == id ? 0 : at[tri[1]] == id ? 1 : 2);
  };
  groups g(3 * triangles.size());
  for (const auto& [edge, list] : edges)
    for (std::size_t i = 1; i < list.size(); ++i) {
      const std::size_t s = list[i - 1], t = list[i];
      if (!(std::clamp(glm::dot(face[s], face[t]), -1.0f, 1.0f) >= limit)) continue;
      for (const std::uint32_t id : edge) g.join(corner_at(s, id), corner_at(t, id));
    }

  // Each group's angle-weighted sum, then normalised per corner.
  std::vector<glm::vec3> sum(3 * triangles.size(), glm::vec3(0.0f)), out(3 * triangles.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (!keep[t]) continue;
    const auto& tri = triangles[t];
    for (int k = 0; k < 3; ++k)
      sum[g.find(3 * t + k)] +=
          corner_angle(positions[tri[k]], positions[tri[(k + 1) % 3]], positions[tri[(k + 2) % 3]]) * face[t];
  }
  for (std::size_t c = 0; c < out.size(); ++c) {
    const glm::vec3 s = sum[g.find(c)];
    if (keep[c / 3] && glm::length(s) > 1e-12f) out[c] = glm::normalize(s);
  }
  return out;
}

}  // namespace gsdot3::pipeline
