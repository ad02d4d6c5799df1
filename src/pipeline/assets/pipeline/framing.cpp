// pipeline/framing.cpp — bounding sphere, camera distance, lights (see framing.hpp).
#include "pipeline/framing.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "pipeline/default_scene.hpp"

namespace gsdot3::pipeline {

bounding_sphere bounds_of(const mesh& m) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const vertex& v : m.vertices) {
    lo = glm::min(lo, v.position);
    hi = glm::max(hi, v.position);
  }
  bounding_sphere b{0.5f * (lo + hi), 0.0f};
  for (const vertex& v : m.vertices) b.radius = std::max(b.radius, glm::length(v.position - b.centre));
  return b;
}

void normalise(mesh& m, const bounding_sphere& b) {
  const float s = b.radius > 0.0f ? 1.0f / b.radius : 1.0f;
  for (vertex& v : m.vertices) v.position = (v.position - b.centre) * s;
}

namespace {

// The direction from the origin towards the eye.
glm::vec3 view_direction(float azimuth, float elevation) {
  const float az = glm::radians(azimuth), el = glm::radians(std::clamp(elevation, -89.0f, 89.0f));
  return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}

// Turns a vector given for the front view (eye on +z) into the view (azimuth, elevation).
glm::vec3 turn(glm::vec3 p, float azimuth, float elevation) {
  const float az = glm::radians(azimuth), el = glm::radians(std::clamp(elevation, -89.0f, 89.0f));
  const glm::vec3 q{p.x, p.y * std::cos(el) + p.z * std::sin(el),
                    -p.y * std::sin(el) + p.z * std::cos(el)};                                      // about x, up by el
  return {q.x * std::cos(az) + q.z * std::sin(az), q.y, -q.x * std::sin(az) + q.z * std::cos(az)};  // about y by az
}

}  // namespace

camera frame_unit_sphere(float azimuth, float elevation, int width, int height, float fov_degrees, float margin) {
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const float half = glm::radians(fov_degrees) / 2.0f;
  // fov_degrees is the narrower field: for a frame taller than wide the vertical field widens
  // (up to 160°), so the camera never backs off beyond prepare's far plane (100).
  const float half_y = aspect >= 1.0f ? half : std::min(std::atan(std::tan(half) / aspect), glm::radians(80.0f));
  const float half_x = std::atan(std::tan(half_y) * aspect);
  // The unit sphere seen from distance d subtends the half angle asin(1/d); its outline lies inside
  // the frame when that angle is below both half fields of view.
  const float d = margin / std::sin(std::min(half_y, half_x));
  return {view_direction(azimuth, elevation) * d, glm::vec3(0.0f), glm::degrees(2.0f * half_y)};
}

std::size_t facing(const mesh& m, glm::vec3 eye) {
  std::size_t n = 0;
  for (const auto& t : m.triangles) {
    const glm::vec3 a = m.vertices[t[0]].position, b = m.vertices[t[1]].position, c = m.vertices[t[2]].position;
    // Edge-on (within 0.01°) is not facing: a plane through the eye, whose dot rounding may make
    // positive, covers no pixel and prepare culls it.
    const glm::vec3 normal = glm::cross(b - a, c - a), to_eye = eye - a;
    n += glm::dot(normal, to_eye) > 1.75e-4f * glm::length(normal) * glm::length(to_eye);
  }
  return n;
}

std::optional<front_view> view_of_fronts(const mesh& m, int width, int height, float fov_degrees) {
  glm::vec3 mean(0.0f);  // Σ (b − a) × (c − a): each unit normal weighted by twice its area
  for (const auto& t : m.triangles) {
    const glm::vec3 a = m.vertices[t[0]].position, b = m.vertices[t[1]].position, c = m.vertices[t[2]].position;
    mean += glm::cross(b - a, c - a);
  }
  std::vector<front_view> tries = {{0.0f, 0.0f, 0}, {180.0f, 0.0f, 0}};
  if (glm::length(mean) > 0.0f) {
    const glm::vec3 d = glm::normalize(mean);
    tries.push_back({glm::degrees(std::atan2(d.x, d.z)),
                     std::clamp(glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f))), -89.0f, 89.0f), 0});
  }
  for (front_view v : tries) {
    v.facing = facing(m, frame_unit_sphere(v.azimuth, v.elevation, width, height, fov_degrees).eye);
    if (v.facing > 0) return v;
  }
  return std::nullopt;
}

std::vector<scene_light> default_lights(float azimuth, float elevation) {
  std::vector<scene_light> lights = default_scene(8).lights;
  for (scene_light& l : lights) l.position = turn(l.position, azimuth, elevation);
  return lights;
}

}  // namespace gsdot3::pipeline
