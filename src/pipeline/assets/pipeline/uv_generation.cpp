// pipeline/uv_generation.cpp — generated UVs and the rule that picks their projection (see uv_generation.hpp).
#include "pipeline/uv_generation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <glm/geometric.hpp>

namespace gsdot3::pipeline {

namespace {

// The axis of the box's smallest side.
int thinnest_axis(const uv_bounds& b) {
  const glm::vec3 e = b.hi - b.lo;
  return e.x <= e.y && e.x <= e.z ? 0 : (e.y <= e.z ? 1 : 2);
}

std::string figure(const char* what, double value, const char* relation, double limit) {
  char t[96];
  std::snprintf(t, sizeof t, "%s %.3f %s %.2f", what, value, relation, limit);
  return t;
}

}  // namespace

float uv_bounds::extent() const { return std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-30f}); }

std::array<glm::vec2, 3> project(uv_projection how, const std::array<glm::vec3, 3>& p, const uv_bounds& b) {
  const float L = b.extent();
  std::array<glm::vec2, 3> uv{};
  auto along = [&](glm::vec3 q, int ua, int va) { return glm::vec2((q[ua] - b.lo[ua]) / L, (b.hi[va] - q[va]) / L); };
  if (how == uv_projection::sphere) {
    const glm::vec3 c = 0.5f * (b.lo + b.hi);
    constexpr float pi = std::numbers::pi_v<float>;
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 d = p[k] - c;
      const float r = glm::length(d);
      uv[k] = {0.5f + std::atan2(d.x, d.z) / (2 * pi), r > 0 ? std::acos(std::clamp(d.y / r, -1.0f, 1.0f)) / pi : 0.5f};
    }
    // A triangle across the back meridian (u jumps from ~1 to ~0) is moved onto one side of it.
    const float umax = std::max({uv[0].x, uv[1].x, uv[2].x});
    for (auto& q : uv)
      if (umax - q.x > 0.5f) q.x += 1.0f;
  } else if (how == uv_projection::planar) {
    const int drop = thinnest_axis(b);
    const int ua = drop == 0 ? 2 : 0, va = drop == 1 ? 2 : 1;
    for (int k = 0; k < 3; ++k) uv[k] = along(p[k], ua, va);
  } else {  // box
    const glm::vec3 n = glm::abs(glm::cross(p[1] - p[0], p[2] - p[0]));
    const int axis = n.x >= n.y && n.x >= n.z ? 0 : (n.y >= n.z ? 1 : 2);
    const int ua = axis == 0 ? 2 : 0, va = axis == 1 ? 2 : 1;
    for (int k = 0; k < 3; ++k) uv[k] = along(p[k], ua, va);
  }
  return uv;
}

projection_choice choose_projection(const std::vector<std::array<glm::vec3, 3>>& triangles, const uv_bounds& b) {
  const int thin = thinnest_axis(b);
  const glm::vec3 centre = 0.5f * (b.lo + b.hi);
  double area = 0.0, facing_axis = 0.0, facing_out = 0.0;  // Σ |n|·… with n = the unnormalised cross product
  for (const auto& p : triangles) {
    const glm::vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    const double a = glm::length(n);
    if (!(a > 0.0) || !std::isfinite(a)) continue;
    area += a;
    facing_axis += std::fabs(static_cast<double>(n[thin]));
    const glm::vec3 r = (p[0] + p[1] + p[2]) / 3.0f - centre;
    if (glm::length(r) > 0.0f) facing_out += std::fabs(static_cast<double>(glm::dot(n, glm::normalize(r))));
  }
  const double flat = area > 0.0 ? facing_axis / area : 0.0, round = area > 0.0 ? facing_out / area : 0.0;
  constexpr double flat_limit = 0.9, round_limit = 0.95;
  if (flat >= flat_limit)
    return {uv_projection::planar, "the surface faces one axis: " + figure("mean |n.axis|", flat, ">=", flat_limit)};
  if (round >= round_limit)
    return {uv_projection::sphere,
            "the surface faces away from its centre: " + figure("mean |n.radial|", round, ">=", round_limit)};
  return {uv_projection::box, "neither flat (" + figure("mean |n.axis|", flat, "<", flat_limit) + ") nor round (" +
                                  figure("mean |n.radial|", round, "<", round_limit) + ")"};
}

const char* projection_name(uv_projection how) {
  switch (how) {
    case uv_projection::box: return "box projection";
    case uv_projection::sphere: return "sphere projection";
    case uv_projection::planar: return "planar projection";
    case uv_projection::automatic: break;
  }
  return "automatic projection";
}

}  // namespace gsdot3::pipeline
