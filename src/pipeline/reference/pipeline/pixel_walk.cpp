// pipeline/pixel_walk.cpp — see pixel_walk.hpp. Compiled with -ffp-contract=off (CMakeLists).
#include "pipeline/pixel_walk.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/common.hpp>

#include "gs_arith/bilinear.hpp"
#include "gs_arith/uv_plane.hpp"
#include "pipeline/raster.hpp"

namespace gsdot3::pipeline {

namespace {

// Barycentric weights of pixel centre (x, y) in a 12.4 triangle.
glm::dvec3 barycentric(const triangle_setup& t, int x, int y) {
  const double px = x * 16.0, py = y * 16.0;
  auto cross = [](double ax, double ay, double bx, double by, double cx, double cy) {
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  };
  const auto& v = t.v;
  const double area = cross(v[0].x, v[0].y, v[1].x, v[1].y, v[2].x, v[2].y);
  return {cross(px, py, v[1].x, v[1].y, v[2].x, v[2].y) / area, cross(v[0].x, v[0].y, px, py, v[2].x, v[2].y) / area,
          cross(v[0].x, v[0].y, v[1].x, v[1].y, px, py) / area};
}

// f for every pixel whose visible[index] ≥ 0, a triangle of `triangles`.
void walk(const prepared_scene& ps, const std::vector<prepared_triangle>& triangles,
          const std::vector<std::int32_t>& visible, const std::function<void(const pixel_sample&)>& f) {
  if (visible.empty()) return;
  std::vector<std::array<plane, 2>> uv(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const prepared_triangle& tri = triangles[t];
    for (std::size_t c = 0; c < 2; ++c)
      uv[t][c] = gs::make_uv_plane(tri.setup.v, {tri.uv16[0][c], tri.uv16[1][c], tri.uv16[2][c]},
                                   gs::uv_rule_of(gs::model_options{}));
  }
  pixel_sample p;
  for (p.y = 0; p.y < ps.height; ++p.y)
    for (p.x = 0; p.x < ps.width; ++p.x) {
      p.index = static_cast<std::size_t>(p.y) * static_cast<std::size_t>(ps.width) + static_cast<std::size_t>(p.x);
      if (visible[p.index] < 0) continue;
      p.triangle = static_cast<std::size_t>(visible[p.index]);
      p.lambda = barycentric(triangles[p.triangle].setup, p.x, p.y);
      p.u16 = uv[p.triangle][0].at(p.x, p.y);
      p.v16 = uv[p.triangle][1].at(p.x, p.y);
      f(p);
    }
}

// A texture32 texel (u, v), wrapped, as (r, g, b).
glm::dvec3 rgb_texel(const texture32& t, std::int32_t u, std::int32_t v) {
  const std::uint32_t w = t.texels[wrapped_texel(t.width, t.height, u, v)];
  return {w & 0xFF, (w >> 8) & 0xFF, (w >> 16) & 0xFF};
}

std::uint32_t to_word(const glm::dvec3& c) {
  return static_cast<std::uint32_t>(std::lround(c.x)) | static_cast<std::uint32_t>(std::lround(c.y)) << 8 |
         static_cast<std::uint32_t>(std::lround(c.z)) << 16 | 0xFF000000u;
}

}  // namespace

void for_each_covered_pixel(const prepared_scene& ps, const std::vector<std::int32_t>& visible,
                            const std::function<void(const pixel_sample&)>& f) {
  walk(ps, ps.triangles, visible, f);
}

void for_each_plain_pixel(const prepared_scene& ps, const std::vector<std::int32_t>& plain,
                          const std::function<void(const pixel_sample&)>& f) {
  walk(ps, ps.plain, plain, f);
}

void compose_plain(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& plain, bool bilinear,
                   std::vector<std::uint32_t>& colour) {
  auto diffuse_texel = [&](std::int32_t u, std::int32_t v) { return rgb_texel(s.diffuse, u, v); };
  for_each_plain_pixel(ps, plain, [&](const pixel_sample& p) {
    glm::dvec3 light(0.0);
    for (std::size_t k = 0; k < 3; ++k)
      light +=
          glm::min(glm::dvec3(ps.plain_light[ps.plain[p.triangle].vertex[k]]), 255.0) * p.lambda[static_cast<int>(k)];
    colour[p.index] = to_word(glm::min(filtered(diffuse_texel, p.u16, p.v16, bilinear) * light / 128.0, 255.0));
  });
}

pixel_light interpolate_light(const prepared_scene& ps, std::size_t l, const pixel_sample& p) {
  pixel_light r;
  const prepared_triangle& tri = ps.triangles[p.triangle];
  for (std::size_t k = 0; k < 3; ++k) {
    const light_vertex& lv = ps.lights[l][tri.vertex[k]];
    r.T += glm::dvec3(lv.T) * p.lambda[static_cast<int>(k)];
    r.fade += static_cast<double>(lv.fade) * p.lambda[static_cast<int>(k)];
  }
  return r;
}

double interpolate_spot(const prepared_scene& ps, std::size_t l, const pixel_sample& p) {
  if (!ps.spot(l)) return 1.0;
  const prepared_triangle& tri = ps.triangles[p.triangle];
  double S = 0.0, T = 0.0, Q = 0.0;
  for (std::size_t k = 0; k < 3; ++k) {
    const spot_vertex& v = ps.spots[l][tri.vertex[k]];
    if (!v.front) return 0.0;
    const double w = p.lambda[static_cast<int>(k)];
    S += static_cast<double>(v.S) * w, T += static_cast<double>(v.T) * w, Q += static_cast<double>(v.Q) * w;
  }
  return spot_intensity(S / Q, T / Q);
}

glm::dvec3 filtered(const std::function<glm::dvec3(std::int32_t, std::int32_t)>& texel, std::int32_t u16,
                    std::int32_t v16, bool bilinear) {
  const gs::texel_footprint f =
      gs::footprint(u16, v16, bilinear ? gs::bilinear_mode::lerp16_4 : gs::bilinear_mode::nearest);
  if (!bilinear) return texel(f.u0, f.v0);
  const double wu = f.wu.value() / 16.0, wv = f.wv.value() / 16.0;
  const glm::dvec3 top = texel(f.u0, f.v0) * (1 - wu) + texel(f.u0 + 1, f.v0) * wu;
  const glm::dvec3 bottom = texel(f.u0, f.v0 + 1) * (1 - wu) + texel(f.u0 + 1, f.v0 + 1) * wu;
  return top * (1 - wv) + bottom * wv;
}

std::vector<std::uint32_t> compose_lit(const scene& s, const prepared_scene& ps,
                                       const std::vector<std::int32_t>& visible,
                                       const std::vector<std::vector<float>>& dot, bool bilinear, double power) {
  std::vector<std::uint32_t> colour(static_cast<std::size_t>(ps.width) * static_cast<std::size_t>(ps.height),
                                    0xFF000000u);
  auto diffuse_texel = [&](std::int32_t u, std::int32_t v) { return rgb_texel(s.diffuse, u, v); };
  for_each_covered_pixel(ps, visible, [&](const pixel_sample& p) {
    glm::dvec3 lab(s.ambient[0], s.ambient[1], s.ambient[2]);
    for (std::size_t l = 0; l < s.lights.size(); ++l) {
      const double d = static_cast<double>(dot[l][p.index]);
      if (std::isnan(d)) continue;
      const auto& lc = s.lights[l].colour;
      lab += glm::dvec3(lc[0], lc[1], lc[2]) * std::pow(std::max(d, 0.0) / 128.0, power);
    }
    const glm::dvec3 out =
        glm::min(filtered(diffuse_texel, p.u16, p.v16, bilinear) * glm::min(lab, 255.0) / 128.0, 255.0);
    colour[p.index] = to_word(out);
  });
  return colour;
}

}  // namespace gsdot3::pipeline
