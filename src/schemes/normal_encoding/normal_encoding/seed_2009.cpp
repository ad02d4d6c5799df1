// The seed's 2009 measurement on a faceted sphere (seed_2009.hpp).
#include "normal_encoding/seed_2009.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gsdot3::normal_encoding {

namespace {
// Vertex (ring i, meridian j) of the UV sphere, the pole axis along y (the view looks down −z):
// i = 0 and i = rings are the poles.
vec3 uv_vertex(int i, int j, int rings, int segments) {
  const double theta = std::numbers::pi * i / rings, phi = 2 * std::numbers::pi * j / segments;
  return {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
}

std::vector<std::array<vec3, 3>> uv_triangles(int rings, int segments) {
  std::vector<std::array<vec3, 3>> t;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const vec3 a = uv_vertex(i, j, rings, segments), b = uv_vertex(i, j + 1, rings, segments);
      const vec3 c = uv_vertex(i + 1, j, rings, segments), d = uv_vertex(i + 1, j + 1, rings, segments);
      if (i > 0) t.push_back({a, b, d});          // none at the top pole's fan (a = b there)
      if (i < rings - 1) t.push_back({a, d, c});  // none at the bottom pole's (c = d there)
    }
  return t;
}

double edge(vec3 a, vec3 b, double x, double y) { return (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x); }
}  // namespace

std::vector<vec3> faceted_sphere_normals(int rings, int segments, int size) {
  if (rings < 2 || segments < 3 || size < 1) throw std::invalid_argument("faceted_sphere_normals: too coarse");
  const auto n = static_cast<std::size_t>(size);
  std::vector<vec3> pixel(n * n);
  std::vector<bool> covered(n * n, false);
  auto centre = [size](int k) { return -1 + (2.0 * k + 1) / size; };
  auto index = [size](double c) { return std::clamp(static_cast<int>(std::floor((c + 1) * size / 2)), 0, size - 1); };
  for (const auto& [a, b, c] : uv_triangles(rings, segments)) {
    vec3 face = cross(b - a, c - a);
    if (dot(face, a + b + c) < 0) face = -1.0 * face;  // outward
    const double area = edge(a, b, c.x, c.y);
    if (face.z <= 0 || area == 0) continue;  // back-facing or edge-on: no pixel of this view
    const int x0 = index(std::min({a.x, b.x, c.x})), x1 = index(std::max({a.x, b.x, c.x}));
    const int y0 = index(std::min({a.y, b.y, c.y})), y1 = index(std::max({a.y, b.y, c.y}));
    for (int py = y0; py <= y1; ++py)
      for (int px = x0; px <= x1; ++px) {
        const double x = centre(px), y = centre(py);
        const double l0 = edge(b, c, x, y) / area, l1 = edge(c, a, x, y) / area, l2 = edge(a, b, x, y) / area;
        const std::size_t at = static_cast<std::size_t>(py) * n + static_cast<std::size_t>(px);
        if (l0 < 0 || l1 < 0 || l2 < 0 || covered[at]) continue;  // a shared edge: the first face keeps it
        covered[at] = true;
        pixel[at] = interpolate(a, b, c, l0, l1, l2);  // the vertex normals are the positions
      }
  }
  std::vector<vec3> out;
  for (std::size_t k = 0; k < pixel.size(); ++k)
    if (covered[k]) out.push_back(pixel[k]);
  return out;
}

seed_2009_error measure_2009(const method& m, int bits, const std::vector<vec3>& pixels) {
  seed_2009_sum sum;
  for (const vec3& v : pixels) sum.add(m, v, bits);
  return sum.done();
}

}  // namespace gsdot3::normal_encoding
