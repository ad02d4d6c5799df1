// pipeline/floor.cpp — see floor.hpp.
#include "pipeline/floor.hpp"

#include <algorithm>
#include <stdexcept>

#include <glm/common.hpp>

namespace gsdot3::pipeline {

mesh floor_under(const mesh& model, int cells, float repeats) {
  if (model.vertices.empty()) throw std::invalid_argument("floor: the model has no vertices");
  if (cells < 1 || cells > 256) throw std::invalid_argument("floor: cells must be 1..256");
  glm::vec3 lo = model.vertices.front().position, hi = lo;
  for (const vertex& v : model.vertices) lo = glm::min(lo, v.position), hi = glm::max(hi, v.position);
  const glm::vec3 centre = (lo + hi) * 0.5f;
  const float half = 2.0f * std::max({(hi.x - lo.x) * 0.5f, (hi.z - lo.z) * 0.5f, 1e-3f});
  mesh m;
  const auto n = static_cast<std::uint32_t>(cells) + 1;
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i) {
      const float a = static_cast<float>(i) / static_cast<float>(cells),
                  b = static_cast<float>(j) / static_cast<float>(cells);
      vertex v;
      v.position = {centre.x - half + 2.0f * half * a, lo.y, centre.z - half + 2.0f * half * b};
      v.normal = {0.0f, 1.0f, 0.0f};
      v.uv = {a * repeats, b * repeats};
      m.vertices.push_back(v);
    }
  // Vertex (i, j) at x index i, z index j: (i, j), (i, j + 1), (i + 1, j) turns counter-clockwise about +y.
  auto at = [n](std::uint32_t i, std::uint32_t j) { return j * n + i; };
  for (std::uint32_t j = 0; j + 1 < n; ++j)
    for (std::uint32_t i = 0; i + 1 < n; ++i) {
      m.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j)});
      m.triangles.push_back({at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)});
    }
  return m;
}

}  // namespace gsdot3::pipeline
