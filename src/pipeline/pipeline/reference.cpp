// pipeline/reference.cpp — see reference.hpp. Compiled with -ffp-contract=off (CMakeLists).
#include "pipeline/reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "gs_arith/bilinear.hpp"
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

template <class Texel>
glm::dvec3 filtered(Texel&& texel, std::int32_t u16, std::int32_t v16, bool bilinear) {
  const gs::texel_footprint f = gs::footprint(u16, v16, bilinear ? gs::bilinear_mode::lerp16_4 : gs::bilinear_mode::nearest);
  if (!bilinear) return texel(f.u0, f.v0);
  const double wu = f.wu.value() / 16.0, wv = f.wv.value() / 16.0;
  const glm::dvec3 top = texel(f.u0, f.v0) * (1 - wu) + texel(f.u0 + 1, f.v0) * wu;
  const glm::dvec3 bottom = texel(f.u0, f.v0 + 1) * (1 - wu) + texel(f.u0 + 1, f.v0 + 1) * wu;
  return top * (1 - wv) + bottom * wv;
}

}  // namespace

reference_frame render_reference(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& visible,
                                 bool bilinear, double power) {
  reference_frame r;
  r.width = ps.width;
  r.height = ps.height;
  const std::size_t n = static_cast<std::size_t>(ps.width) * static_cast<std::size_t>(ps.height);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  r.renormalised.assign(s.lights.size(), std::vector<float>(n, nan));
  r.unnormalised = r.renormalised;
  r.colour.assign(n, 0xFF000000u);

  const normal_map& nm = s.normals;
  auto normal_texel = [&](std::int32_t u, std::int32_t v) {
    const std::size_t at = static_cast<std::size_t>(v & (nm.height - 1)) * static_cast<std::size_t>(nm.width) +
                           static_cast<std::size_t>(u & (nm.width - 1));
    return glm::dvec3(nm.palette[nm.index[at]]);
  };
  const texture32& dt = s.diffuse;
  auto diffuse_texel = [&](std::int32_t u, std::int32_t v) {
    const std::uint32_t w = dt.texels[static_cast<std::size_t>(v & (dt.height - 1)) * static_cast<std::size_t>(dt.width) +
                                      static_cast<std::size_t>(u & (dt.width - 1))];
    return glm::dvec3(w & 0xFF, (w >> 8) & 0xFF, (w >> 16) & 0xFF);
  };

  std::vector<std::array<plane, 2>> uv(ps.triangles.size());
  for (std::size_t t = 0; t < ps.triangles.size(); ++t) {
    const prepared_triangle& tri = ps.triangles[t];
    for (int c = 0; c < 2; ++c)
      uv[t][static_cast<std::size_t>(c)] = make_plane(tri.setup.v, {tri.uv16[0][static_cast<std::size_t>(c)], tri.uv16[1][static_cast<std::size_t>(c)], tri.uv16[2][static_cast<std::size_t>(c)]}, -(1 << 20), 1 << 20);
  }

  for (int y = 0; y < ps.height; ++y)
    for (int x = 0; x < ps.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(ps.width) + static_cast<std::size_t>(x);
      if (visible[i] < 0) continue;
      const auto t = static_cast<std::size_t>(visible[i]);
      const prepared_triangle& tri = ps.triangles[t];
      const glm::dvec3 lambda = barycentric(tri.setup, x, y);
      const std::int32_t u16 = uv[t][0].at(x, y), v16 = uv[t][1].at(x, y);
      const glm::dvec3 N = glm::normalize(filtered(normal_texel, u16, v16, bilinear));
      glm::dvec3 lab(s.ambient[0], s.ambient[1], s.ambient[2]);
      for (std::size_t l = 0; l < s.lights.size(); ++l) {
        glm::dvec3 T(0.0), faded(0.0);
        double fade = 0.0;
        for (int k = 0; k < 3; ++k) {
          const light_vertex& lv = ps.lights[l][tri.vertex[static_cast<std::size_t>(k)]];
          T += glm::dvec3(lv.T) * lambda[k];
          faded += glm::dvec3(lv.T) * static_cast<double>(lv.fade) * lambda[k];
          fade += static_cast<double>(lv.fade) * lambda[k];
        }
        const double renorm = glm::length(T) > 0.0 ? 128.0 * fade * glm::dot(N, glm::normalize(T)) : 0.0;
        r.renormalised[l][i] = static_cast<float>(renorm);
        r.unnormalised[l][i] = static_cast<float>(128.0 * glm::dot(N, faded));
        const auto& lc = s.lights[l].colour;
        lab += glm::dvec3(lc[0], lc[1], lc[2]) * std::pow(std::max(renorm, 0.0) / 128.0, power);
      }
      const glm::dvec3 out = glm::min(filtered(diffuse_texel, u16, v16, bilinear) * glm::min(lab, 255.0) / 128.0, 255.0);
      r.colour[i] = static_cast<std::uint32_t>(std::lround(out.x)) | static_cast<std::uint32_t>(std::lround(out.y)) << 8 |
                    static_cast<std::uint32_t>(std::lround(out.z)) << 16 | 0xFF000000u;
    }
  return r;
}

}  // namespace gsdot3::pipeline
