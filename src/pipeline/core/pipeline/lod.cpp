#include "pipeline/lod.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/common.hpp>

namespace gsdot3::pipeline {

std::vector<scene_light> split_for_lod(const std::vector<scene_light>& lights, double share) {
  if (!(share >= 0.0 && share <= 1.0))
    throw std::invalid_argument("level-of-detail share must be in [0, 1], got " + std::to_string(share));
  std::vector<scene_light> out;
  for (const scene_light& l : lights) {
    scene_light dot3 = l, gouraud = l;
    gouraud.gouraud = true;
    for (std::size_t c = 0; c < 3; ++c) {
      dot3.colour[c] = static_cast<std::uint8_t>(std::lround(share * l.colour[c]));
      gouraud.colour[c] = static_cast<std::uint8_t>(l.colour[c] - dot3.colour[c]);
    }
    for (const scene_light& half : {dot3, gouraud})
      if (half.colour != std::array<std::uint8_t, 3>{}) out.push_back(half);
  }
  return out;
}

double lod_share_at(double distance, double near, double far) {
  if (!(near >= 0.0 && near < far && std::isfinite(far)))
    throw std::invalid_argument("level-of-detail distances must satisfy 0 <= near < far, got " + std::to_string(near) +
                                ", " + std::to_string(far));
  return std::clamp((far - distance) / (far - near), 0.0, 1.0);
}

double camera_distance(const scene& s) {
  if (s.model.vertices.empty()) throw std::invalid_argument("camera distance: the model has no vertices");
  glm::vec3 lo = s.model.vertices.front().position, hi = lo;
  for (const vertex& v : s.model.vertices) lo = glm::min(lo, v.position), hi = glm::max(hi, v.position);
  const glm::dvec3 d = glm::dvec3(s.view.eye) - (glm::dvec3(lo) + glm::dvec3(hi)) * 0.5;
  return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}

}  // namespace gsdot3::pipeline
