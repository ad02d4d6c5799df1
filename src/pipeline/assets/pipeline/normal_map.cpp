// pipeline/normal_map.cpp — height field to normals; spherical k-means to a 256-entry palette.
#include "pipeline/normal_map.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <tuple>

#include <glm/geometric.hpp>

namespace gsdot3::pipeline {

std::vector<glm::vec3> normals_from_height(const std::vector<float>& h, int w, int hgt, float strength) {
  std::vector<glm::vec3> out(static_cast<std::size_t>(w) * hgt);
  auto at = [&](int x, int y) { return h[static_cast<std::size_t>((y + hgt) % hgt) * w + (x + w) % w]; };
  for (int y = 0; y < hgt; ++y)
    for (int x = 0; x < w; ++x) {
      const float dx = (at(x + 1, y) - at(x - 1, y)) * 0.5f * strength;
      const float dy = (at(x, y + 1) - at(x, y - 1)) * 0.5f * strength;
      out[static_cast<std::size_t>(y) * w + x] = glm::normalize(glm::vec3(-dx, -dy, 1.0f));
    }
  return out;
}

namespace {

// The distinct normals with their multiplicities (procedural maps repeat a few values a lot).
struct weighted {
  glm::vec3 n;
  double weight;
};

std::vector<weighted> distinct(const std::vector<glm::vec3>& normals) {
  std::map<std::tuple<float, float, float>, double> count;
  for (const glm::vec3& n : normals) count[{n.x, n.y, n.z}] += 1.0;
  std::vector<weighted> out;
  out.reserve(count.size());
  for (const auto& [k, c] : count) out.push_back({{std::get<0>(k), std::get<1>(k), std::get<2>(k)}, c});
  return out;
}

std::size_t nearest(const std::vector<glm::vec3>& centres, glm::vec3 n) {
  std::size_t best = 0;
  float best_dot = -2.0f;
  for (std::size_t c = 0; c < centres.size(); ++c) {
    const float d = glm::dot(centres[c], n);
    if (d > best_dot) best_dot = d, best = c;
  }
  return best;
}

}  // namespace

normal_map quantise(const std::vector<glm::vec3>& normals, int width, int height, int entries) {
  if (normals.size() != static_cast<std::size_t>(width) * height || normals.empty())
    throw std::runtime_error("normal map size does not match its data");
  const std::vector<weighted> pts = distinct(normals);
  const std::size_t k = std::min<std::size_t>(static_cast<std::size_t>(entries), pts.size());

  // Farthest-point seeding: each new centre is the point least similar to every centre so far.
  std::vector<glm::vec3> centres{pts.front().n};
  std::vector<float> best(pts.size(), -2.0f);
  while (centres.size() < k) {
    std::size_t pick = 0;
    float lowest = 2.0f;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      best[i] = std::max(best[i], glm::dot(pts[i].n, centres.back()));
      if (best[i] < lowest) lowest = best[i], pick = i;
    }
    centres.push_back(pts[pick].n);
  }

  std::vector<std::size_t> assign(pts.size(), k);
  for (int iter = 0; iter < 30; ++iter) {
    bool changed = false;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const std::size_t c = nearest(centres, pts[i].n);
      changed |= c != assign[i];
      assign[i] = c;
    }
    if (!changed) break;
    std::vector<glm::dvec3> sum(k, glm::dvec3(0.0));
    for (std::size_t i = 0; i < pts.size(); ++i) sum[assign[i]] += glm::dvec3(pts[i].n) * pts[i].weight;
    for (std::size_t c = 0; c < k; ++c)
      if (glm::length(sum[c]) > 0.0) centres[c] = glm::vec3(glm::normalize(sum[c]));
  }

  normal_map m;
  m.width = width;
  m.height = height;
  m.palette = centres;
  m.index.resize(normals.size());
  for (std::size_t i = 0; i < normals.size(); ++i) m.index[i] = static_cast<std::uint8_t>(nearest(centres, normals[i]));
  return m;
}

}  // namespace gsdot3::pipeline
