// pipeline/default_scene.cpp — the embedded procedural scene (no files needed).
#include "pipeline/default_scene.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "pipeline/normal_map.hpp"

namespace gsdot3::pipeline {

namespace {

constexpr float pi = std::numbers::pi_v<float>;

// The head surface: polar angle th (0 top .. pi bottom), azimuth ph (0 = facing +z, the viewer).
glm::vec3 head_point(float th, float ph) {
  const float s = std::sin(th), c = std::cos(th);
  float r = 1.0f;
  const float front = std::max(0.0f, std::cos(ph));                                      // 1 on the face
  r += 0.18f * std::exp(-std::pow((th - 1.55f) / 0.22f, 2.0f)) * std::pow(front, 8.0f);  // nose
  r += 0.07f * std::exp(-std::pow((th - 1.05f) / 0.15f, 2.0f)) * std::pow(front, 2.0f);  // brow
  r -= 0.06f * std::exp(-std::pow((th - 1.30f) / 0.12f, 2.0f)) * std::pow(std::fabs(std::sin(ph)), 6.0f) * front;
  r += 0.05f * std::exp(-std::pow((th - 2.15f) / 0.25f, 2.0f)) * front;  // chin
  // Narrower at the sides, longer vertically, a jaw that tapers.
  const float jaw = 1.0f - 0.25f * std::max(0.0f, c < 0.0f ? -c : 0.0f);
  return {0.78f * r * s * std::sin(ph) * jaw, 1.05f * r * c, 0.90f * r * s * std::cos(ph) * jaw};
}

glm::vec3 head_normal(float th, float ph) {
  const float e = 1e-3f;
  const float t0 = std::clamp(th, 2 * e, pi - 2 * e);
  const glm::vec3 dth = head_point(t0 + e, ph) - head_point(t0 - e, ph);
  const glm::vec3 dph = head_point(t0, ph + e) - head_point(t0, ph - e);
  glm::vec3 n = glm::normalize(glm::cross(dph, dth));
  if (glm::dot(n, head_point(t0, ph)) < 0.0f) n = -n;
  if (th <= 2 * e) return {0, 1, 0};
  if (th >= pi - 2 * e) return {0, -1, 0};
  return n;
}

}  // namespace

mesh head_mesh(int rings, int segments) {
  mesh m;
  // Vertex grid: rows 0..rings (row 0 and row `rings` are the poles, one vertex per segment so each
  // pole triangle has its own UV), columns 0..segments (the seam column is duplicated for UVs).
  auto id = [&](int row, int col) { return static_cast<std::uint32_t>(row * (segments + 1) + col); };
  for (int row = 0; row <= rings; ++row)
    for (int col = 0; col <= segments; ++col) {
      const float v = static_cast<float>(row) / rings;
      float u = static_cast<float>(col) / segments;
      if (row == 0 || row == rings) u += 0.5f / segments;  // pole vertex sits mid-segment
      const float th = v * pi, ph = (u - 0.5f) * 2.0f * pi;
      vertex vx;
      vx.position = head_point(th, ph);
      vx.normal = head_normal(th, ph);
      vx.uv = {u * 3.0f, v * 2.0f};  // the normal map repeats 3× around and 2× down (UV < 1024 texels)
      m.vertices.push_back(vx);
    }
  for (int row = 0; row < rings; ++row)
    for (int col = 0; col < segments; ++col) {
      const std::uint32_t a = id(row, col), b = id(row, col + 1), c = id(row + 1, col), d = id(row + 1, col + 1);
      // Counter-clockwise seen from outside (u grows to the viewer's right on the face, v down).
      // The quad diagonals mirror about the face's centre line, so the mesh is mirror-symmetric
      // in x; the top pole triangle uses the pole vertex over its own quad.
      if (row == 0) {
        m.triangles.push_back({a, c, d});
      } else if (row == rings - 1) {
        m.triangles.push_back({a, c, b});
      } else if (2 * col < segments) {
        m.triangles.push_back({a, c, b});
        m.triangles.push_back({b, c, d});
      } else {
        m.triangles.push_back({a, c, d});
        m.triangles.push_back({a, d, b});
      }
    }
  compute_tangents(m);
  return m;
}

normal_map procedural_normal_map(int size) {
  std::vector<float> h(static_cast<std::size_t>(size) * size);
  const float k = 2.0f * pi / size;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float fx = x * k, fy = y * k;
      // Panels: grooves every quarter of the map; rivets at panel corners; a dented wave field.
      const float gx = std::fabs(std::sin(fx * 2.0f)), gy = std::fabs(std::sin(fy * 2.0f));
      float v = -6.0f * std::exp(-gx * gx * 60.0f) - 6.0f * std::exp(-gy * gy * 60.0f);
      const float rx = std::sin(fx * 2.0f + pi / 2), ry = std::sin(fy * 2.0f + pi / 2);
      v += 5.0f * std::exp(-((1 - rx * rx) + (1 - ry * ry)) * 40.0f);
      v += 1.5f * std::sin(fx * 6.0f + 2.0f * std::sin(fy * 3.0f)) * std::cos(fy * 5.0f);
      h[static_cast<std::size_t>(y) * size + x] = v * (size / 256.0f);
    }
  return quantise(normals_from_height(h, size, size, 0.6f), size, size, 256);
}

texture32 procedural_diffuse(int width, int height) {
  texture32 t;
  t.width = width;
  t.height = height;
  t.texels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const bool line = (x % std::max(width / 4, 1)) < 2 || (y % std::max(height / 4, 1)) < 2;
      const std::uint32_t r = line ? 0x58 : 0x98, g = line ? 0x50 : 0x90, b = line ? 0x48 : 0x88;
      t.texels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] =
          r | g << 8 | b << 16 | 0x80u << 24;
    }
  return t;
}

scene default_scene(int normal_map_size) {
  scene s;
  s.model = head_mesh();
  s.normals = procedural_normal_map(normal_map_size);
  s.diffuse = procedural_diffuse(normal_map_size, normal_map_size);
  s.lights = {{{-2.2f, 1.4f, 2.2f}, {0x10, 0x98, 0x20}},   // green, front left above
              {{2.6f, -0.2f, 0.4f}, {0x10, 0x38, 0xB0}}};  // blue, right, level with the face
  s.view.eye = {0.0f, 0.15f, 3.6f};
  s.view.target = {0.0f, 0.0f, 0.0f};
  return s;
}

}  // namespace gsdot3::pipeline
