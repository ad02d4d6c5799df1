// pipeline/mikktspace.cpp — MikkTSpace tangents (see mikktspace.hpp for the algorithm's steps).
#include "pipeline/mikktspace.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include <glm/geometric.hpp>

namespace gsdot3::pipeline {

namespace {

using vertex_key = std::array<std::uint32_t, 8>;

struct key_hash {
  std::size_t operator()(const vertex_key& k) const {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the eight words
    for (std::uint32_t w : k) h = (h ^ w) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

vertex_key key_of(const tangent_corner& c) {
  return {std::bit_cast<std::uint32_t>(c.position.x), std::bit_cast<std::uint32_t>(c.position.y),
          std::bit_cast<std::uint32_t>(c.position.z), std::bit_cast<std::uint32_t>(c.normal.x),
          std::bit_cast<std::uint32_t>(c.normal.y),   std::bit_cast<std::uint32_t>(c.normal.z),
          std::bit_cast<std::uint32_t>(c.uv.x),       std::bit_cast<std::uint32_t>(c.uv.y)};
}

glm::vec3 in_plane(glm::vec3 v, glm::vec3 n) { return v - n * glm::dot(n, v); }

glm::vec3 safe_normalize(glm::vec3 v) {
  const float l = glm::length(v);
  return l > 0.0f && std::isfinite(l) ? v / l : glm::vec3(0.0f);
}

glm::vec3 fallback_tangent(glm::vec3 n) {
  const glm::vec3 axis = std::fabs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(in_plane(axis, n));
}

// A vertex's two orientation groups: [0] positive UV area, [1] negative.
struct groups {
  std::array<glm::vec3, 2> sum{glm::vec3(0.0f), glm::vec3(0.0f)};
  std::array<float, 2> weight{0.0f, 0.0f};
};

}  // namespace

mikktspace_result mikktspace_tangents(const std::vector<tangent_corner>& corners) {
  const std::size_t triangles = corners.size() / 3;
  mikktspace_result r;
  r.corners.resize(corners.size());

  // 1. Weld identical corners into vertices.
  std::unordered_map<vertex_key, std::uint32_t, key_hash> ids;
  std::vector<std::uint32_t> vertex_of(corners.size());
  for (std::size_t c = 0; c < corners.size(); ++c)
    vertex_of[c] = ids.try_emplace(key_of(corners[c]), static_cast<std::uint32_t>(ids.size())).first->second;
  std::vector<groups> g(ids.size());

  // 2.–3. Per triangle: dP/du and orientation; accumulated angle-weighted per vertex and orientation.
  std::vector<int> orientation(triangles, -1);  // 0 positive, 1 negative, -1 zero UV area
  for (std::size_t t = 0; t < triangles; ++t) {
    const tangent_corner* k = &corners[3 * t];
    const glm::vec3 e1 = k[1].position - k[0].position, e2 = k[2].position - k[0].position;
    const glm::vec2 d1 = k[1].uv - k[0].uv, d2 = k[2].uv - k[0].uv;
    const float area = d1.x * d2.y - d2.x * d1.y;  // twice the signed UV area
    // dP/du · area: solving e = du·Pu + dv·Pv for the two edges.
    const glm::vec3 pu_area = e1 * d2.y - e2 * d1.y;
    if (!(std::fabs(area) > 0.0f) || !(glm::length(pu_area) > 0.0f)) {
      ++r.zero_uv_area_triangles;
      continue;
    }
    orientation[t] = area > 0.0f ? 0 : 1;
    const glm::vec3 pu = safe_normalize(area > 0.0f ? pu_area : -pu_area);
    for (int i = 0; i < 3; ++i) {
      const glm::vec3 n = k[i].normal;
      const glm::vec3 a = safe_normalize(in_plane(k[(i + 1) % 3].position - k[i].position, n));
      const glm::vec3 b = safe_normalize(in_plane(k[(i + 2) % 3].position - k[i].position, n));
      const float angle = std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f));
      groups& gv = g[vertex_of[3 * t + static_cast<std::size_t>(i)]];
      gv.sum[static_cast<std::size_t>(orientation[t])] += angle * safe_normalize(in_plane(pu, n));
      gv.weight[static_cast<std::size_t>(orientation[t])] += angle;
    }
  }

  // 3.–4. Each corner takes its vertex's group tangent.
  for (std::size_t c = 0; c < corners.size(); ++c) {
    const groups& gv = g[vertex_of[c]];
    int o = orientation[c / 3];
    if (o < 0) o = gv.weight[1] > gv.weight[0] ? 1 : 0;
    const glm::vec3 n = corners[c].normal;
    const glm::vec3 t = safe_normalize(in_plane(gv.sum[static_cast<std::size_t>(o)], n));
    if (glm::length(t) > 0.0f) {
      r.corners[c] = {t, o == 0 ? 1.0f : -1.0f};
    } else {
      r.corners[c] = {fallback_tangent(n), 1.0f};
      ++r.fallback_corners;
    }
  }
  return r;
}

}  // namespace gsdot3::pipeline
