// pipeline/spot.cpp — see spot.hpp.
#include "pipeline/spot.hpp"

#include <algorithm>
#include <cmath>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace gsdot3::pipeline {

namespace {
constexpr double full_radius = 0.65, edge_radius = 0.9;
}

double spot_intensity(double s, double t) {
  const double r = std::hypot(2.0 * s - 1.0, 2.0 * t - 1.0);
  return std::clamp((edge_radius - r) / (edge_radius - full_radius), 0.0, 1.0);
}

std::vector<spot_vertex> spot_coordinates(const scene_light& l, const glm::mat4& to_object, const mesh& m) {
  const glm::vec3 at = glm::vec3(to_object * glm::vec4(l.position, 1.0f));
  const glm::vec3 axis = glm::normalize(glm::vec3(to_object * glm::vec4(l.direction, 0.0f)));
  const glm::vec3 up = std::fabs(axis.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  // The frustum's half-angle puts the cone's edge at radius edge_radius of the projection.
  const float half = std::atan(std::tan(glm::radians(l.cone_degrees)) / static_cast<float>(edge_radius));
  const glm::mat4 light = glm::perspective(2.0f * half, 1.0f, 0.05f, 100.0f) * glm::lookAt(at, at + axis, up);
  std::vector<spot_vertex> out(m.vertices.size());
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    const glm::vec4 c = light * glm::vec4(m.vertices[i].position, 1.0f);
    if (!(c.w > 1e-3f)) continue;
    const float q = 1.0f / c.w;
    out[i] = {(0.5f * c.x * q + 0.5f) * q, (0.5f - 0.5f * c.y * q) * q, q, true};
  }
  return out;
}

}  // namespace gsdot3::pipeline
