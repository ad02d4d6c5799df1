// tests/pipeline/test_scenes.hpp — small hand-built scenes for closed-form checks.
#pragma once

#include <cstddef>

#include <glm/geometric.hpp>

#include "pipeline/default_scene.hpp"
#include "pipeline/prepare.hpp"
#include "pipeline/render.hpp"

namespace gsdot3::pipeline::test {

// A W×H frame with one screen-aligned quad [x0, x1) × [y0, y1) (pixel-centre corners) made of two
// front-facing triangles; a constant normal map (every texel = palette entry 0 = n); one light whose
// tangent-space tolight vector is T at every vertex (a directional light) with fade_att = 1.
struct flat_quad {
  scene s;
  prepared_scene ps;
};

inline flat_quad make_flat_quad(glm::vec3 n, glm::vec3 T, int w = 64, int h = 48, int x0 = 8, int y0 = 8, int x1 = 56,
                                int y1 = 40) {
  flat_quad q;
  q.s.width = w;
  q.s.height = h;
  q.s.normals.width = q.s.normals.height = 8;
  q.s.normals.index.assign(64, 0);
  q.s.normals.palette = {glm::normalize(n)};
  q.s.diffuse = procedural_diffuse(8, 8);
  q.s.lights = {{{0, 0, 1}, {0x80, 0x80, 0x80}}};
  q.ps.width = w;
  q.ps.height = h;
  q.ps.lights = {std::vector<light_vertex>(4, light_vertex{glm::normalize(T), 1.0f})};
  const xy124 a{x0 * 16, y0 * 16}, b{x1 * 16, y0 * 16}, c{x0 * 16, y1 * 16}, d{x1 * 16, y1 * 16};
  auto tri = [&](std::array<std::uint32_t, 3> idx, std::array<xy124, 3> p) {
    prepared_triangle t;
    t.vertex = idx;
    t.setup = setup_triangle(p);
    t.z = make_plane(p, {1000, 1000, 1000}, 0, 0xFFFFFF);
    t.uv16 = {{{40, 40}, {40, 40}, {40, 40}}};  // texel (2, 2)
    return t;
  };
  q.ps.triangles = {tri({0, 2, 1}, {a, c, b}), tri({1, 2, 3}, {b, c, d})};
  return q;
}

// A second map unlike m: its rows upside down and its normals turned 90° about z (palette and
// unquantised alike).
inline normal_map turned(const normal_map& m) {
  normal_map t = m;
  auto turn = [](glm::vec3 n) { return glm::vec3(-n.y, n.x, n.z); };
  for (glm::vec3& n : t.palette) n = turn(n);
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) {
      const auto to = static_cast<std::size_t>(y * m.width + x);
      const auto from = static_cast<std::size_t>((m.height - 1 - y) * m.width + x);
      t.index[to] = m.index[from];
      if (!m.unquantised.empty()) t.unquantised[to] = turn(m.unquantised[from]);
    }
  return t;
}

// s with a two-layer map, s's own and turned(s's): the model's first half samples layer 0, the rest
// layer 1 (contiguous: the draw order stays the mesh's).
inline scene two_layers(scene s) {
  s.normals = stacked({s.normals, turned(s.normals)});
  const std::size_t n = s.model.triangles.size();
  s.model.layer.assign(n, 0);
  for (std::size_t t = n / 2; t < n; ++t) s.model.layer[t] = 1;
  return s;
}

}  // namespace gsdot3::pipeline::test
