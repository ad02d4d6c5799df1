// pipeline/tangents.cpp — per-vertex tangent frames from UV derivatives (Lengyel's method).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "pipeline/scene.hpp"

namespace gsdot3::pipeline {

namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Any unit vector orthogonal to n (for vertices whose UVs give no direction).
glm::vec3 any_orthogonal(glm::vec3 n) {
  const glm::vec3 axis = std::fabs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(axis - n * glm::dot(axis, n));
}

}  // namespace

void validate(const mesh& m) {
  if (m.triangles.empty()) throw std::runtime_error("mesh has no triangles");
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    const vertex& v = m.vertices[i];
    if (!finite(v.position) || !finite(v.normal) || !std::isfinite(v.uv.x) || !std::isfinite(v.uv.y))
      throw std::runtime_error("vertex " + std::to_string(i) + " has a non-finite value (NaN or infinity)");
    if (glm::length(v.normal) < 1e-6f) throw std::runtime_error("vertex " + std::to_string(i) + " has a zero normal");
  }
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (std::uint32_t i : m.triangles[t])
      if (i >= m.vertices.size())
        throw std::runtime_error("triangle " + std::to_string(t) + " refers to missing vertex " + std::to_string(i));
  if (!m.layer.empty() && m.layer.size() != m.triangles.size())
    throw std::runtime_error("the mesh has " + std::to_string(m.layer.size()) + " layer numbers for " +
                             std::to_string(m.triangles.size()) + " triangles");
}

void compute_tangents(mesh& m) {
  validate(m);
  std::vector<glm::vec3> tan(m.vertices.size(), glm::vec3(0)), bit(m.vertices.size(), glm::vec3(0));
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto [i0, i1, i2] = m.triangles[t];
    const vertex &a = m.vertices[i0], &b = m.vertices[i1], &c = m.vertices[i2];
    const glm::vec3 e1 = b.position - a.position, e2 = c.position - a.position;
    const float area2 = glm::length(glm::cross(e1, e2));
    const float scale = std::max({glm::length(e1), glm::length(e2), 1e-30f});
    if (!(area2 > 1e-7f * scale * scale))
      throw std::runtime_error("triangle " + std::to_string(t) + " is degenerate (zero area)");
    const glm::vec2 d1 = b.uv - a.uv, d2 = c.uv - a.uv;
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (std::fabs(det) < 1e-12f) continue;  // no UV direction: contributes nothing
    const glm::vec3 sdir = (e1 * d2.y - e2 * d1.y) / det;
    const glm::vec3 tdir = (e2 * d1.x - e1 * d2.x) / det;
    for (std::uint32_t i : m.triangles[t]) {
      tan[i] += sdir;
      bit[i] += tdir;
    }
  }
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    vertex& v = m.vertices[i];
    v.normal = glm::normalize(v.normal);
    glm::vec3 t = tan[i] - v.normal * glm::dot(v.normal, tan[i]);
    t = glm::length(t) > 1e-12f ? glm::normalize(t) : any_orthogonal(v.normal);
    const float handedness = glm::dot(glm::cross(v.normal, t), bit[i]) < 0.0f ? -1.0f : 1.0f;
    v.tangent = t;
    v.bitangent = glm::cross(v.normal, t) * handedness;
  }
}

}  // namespace gsdot3::pipeline
