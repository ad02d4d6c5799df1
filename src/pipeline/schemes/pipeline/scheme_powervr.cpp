// pipeline/scheme_powervr.cpp — seed 004 on the shared scene. The normal map is converted texel by
// texel as `gsdot3 pvr-bump` does (KallistiOS rounding, azimuths /255); the bump unit is evaluated
// under flycast's float (or fixed8) precision with azimuths /255, sampled nearest (no filtering of
// the S/R bytes), and the 8-bit output b gives the report's value 128·fade·b/255 (fade interpolated
// as for the GS methods). Light: S_l = 1 (K1 = 0, K2 = 255 sin T, K3 = 255 cos T, rounded), Q =
// atan2 of the tangent-space tolight vector. Where the offset colour comes from:
//   flat     one K/Q per triangle, from the normalised mean of its three vertex tolight vectors
//            (the seed: "the bump map effect is flat shaded");
//   gouraud  K/Q per vertex, interpolated as x/255 floats across the triangle as flycast does under
//            Gouraud shading (its vertex shader passes in_offs through, the Q byte included);
//   pixel    K/Q per pixel from the interpolated tolight vector (no hardware does this: it isolates
//            the flat-shading error from the texel and K/Q quantisation);
//   cheap    the seed's "cheap bump" (SDK KMBump.c KMCheapBumpShade, standard method): K1 = 0,
//            K2 = K3 = 255 and one Q per object and light: the angle, on screen, between the light's
//            direction from the mesh centroid and the object's upright axis, plus 90° (the SDK's +64/256),
//            taken exactly with atan2 (the SDK approximates the angles as (y + 1)·64).
#include "pipeline/scheme_powervr.hpp"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "pipeline/pixel_walk.hpp"
#include "powervr/encode.hpp"
#include "powervr/evaluate.hpp"
#include "powervr/texture.hpp"

namespace gsdot3::pipeline::powervr_methods {

namespace {
namespace pvr = schemes::powervr;
constexpr auto scale = pvr::azimuth_scale::flycast_255;

enum class source { flat, gouraud, pixel, cheap };

pvr::offset_colour light_offset(const glm::dvec3& T) {
  const double len = glm::length(T);
  return pvr::offset_nearest(pvr::seed_atan2(len > 0 ? T / len : glm::dvec3(0, 0, 1), 1.0), scale);
}

// The cheap method's Q per light: screen-space angle of (light − centroid) against the object's up.
std::vector<pvr::offset_colour> cheap_offsets(const scene& s) {
  glm::dvec3 centre{};
  for (const auto& v : s.model.vertices) centre += glm::dvec3(v.position);
  if (!s.model.vertices.empty()) centre /= static_cast<double>(s.model.vertices.size());
  const glm::dvec3 forward = glm::normalize(glm::dvec3(s.view.target - s.view.eye));
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 1, 0))), up = glm::cross(right, forward);
  std::vector<pvr::offset_colour> out;
  for (const auto& l : s.lights) {
    const glm::dvec3 d = glm::dvec3(l.position) - (l.kind == light_kind::directional ? glm::dvec3(0.0) : centre);
    const double light_angle = std::atan2(glm::dot(d, up), glm::dot(d, right));
    const double up_angle = std::atan2(glm::dot(glm::dvec3(0, 1, 0), up), glm::dot(glm::dvec3(0, 1, 0), right));
    double q = std::numbers::pi / 2 + (light_angle - up_angle);
    q = std::fmod(q + 4 * std::numbers::pi, 2 * std::numbers::pi);
    pvr::offset_colour k = pvr::offset_nearest({1.0, 0.0, q}, scale);
    k.K1 = 0, k.K2 = 255, k.K3 = 255;
    out.push_back(k);
  }
  return out;
}

scheme_frame render_with(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& visible, source src,
                         pvr::precision prec) {
  std::vector<pvr::bump_texel> palette;
  for (const auto& n : s.normals.palette)
    palette.push_back(pvr::encode_normal(glm::dvec3(n), pvr::texel_rounding::kallistios, scale));
  // Per light and triangle (flat) or mesh vertex (gouraud): the offset colour.
  std::vector<std::vector<pvr::offset_colour>> per_triangle(s.lights.size()), per_vertex(s.lights.size());
  for (std::size_t l = 0; l < s.lights.size(); ++l) {
    for (const auto& lv : ps.lights[l]) per_vertex[l].push_back(light_offset(glm::dvec3(lv.T)));
    for (const auto& tri : ps.triangles) {
      glm::dvec3 sum{};
      for (auto v : tri.vertex) sum += glm::dvec3(ps.lights[l][v].T);
      per_triangle[l].push_back(light_offset(sum));
    }
  }
  const auto cheap = cheap_offsets(s);
  scheme_frame f;
  const std::size_t n = static_cast<std::size_t>(ps.width) * static_cast<std::size_t>(ps.height);
  f.dot.assign(s.lights.size(), std::vector<float>(n, NAN));
  for_each_covered_pixel(ps, visible, [&](const pixel_sample& p) {
    const auto texel = palette[palette_entry(s.normals, ps.triangles[p.triangle].layer,
                                             wrapped_texel(s.normals.width, s.normals.height, p.u16 >> 4, p.v16 >> 4))];
    for (std::size_t l = 0; l < s.lights.size(); ++l) {
      const pixel_light pl = interpolate_light(ps, l, p);
      double b = 0;
      if (src == source::gouraud) {
        const auto& tri = ps.triangles[p.triangle];
        float k[4] = {0, 0, 0, 0};
        for (int c = 0; c < 3; ++c) {
          const auto& o = per_vertex[l][tri.vertex[static_cast<std::size_t>(c)]];
          const auto w = static_cast<float>(p.lambda[c]);
          k[0] += w * o.K1 / 255.0f, k[1] += w * o.K2 / 255.0f, k[2] += w * o.K3 / 255.0f, k[3] += w * o.Q / 255.0f;
        }
        b = std::lround(pvr::intensity_flycast(texel, k[0], k[1], k[2], k[3], scale) * 255.0f);
      } else {
        const pvr::offset_colour k = src == source::flat    ? per_triangle[l][p.triangle]
                                     : src == source::pixel ? light_offset(pl.T)
                                                            : cheap[l];
        b = pvr::intensity(texel, k, scale, prec);
      }
      f.dot[l][p.index] = static_cast<float>(128.0 * pl.fade * b / 255.0);
    }
  });
  f.colour = compose_lit(s, ps, visible, f.dot, false, 1.0);
  return f;
}
}  // namespace

scheme_frame flat_float(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& v,
                        const render_options&) {
  return render_with(s, ps, v, source::flat, pvr::precision::float32);
}
scheme_frame flat_fixed8(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& v,
                         const render_options&) {
  return render_with(s, ps, v, source::flat, pvr::precision::fixed8);
}
scheme_frame gouraud_float(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& v,
                           const render_options&) {
  return render_with(s, ps, v, source::gouraud, pvr::precision::float32);
}
scheme_frame pixel_float(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& v,
                         const render_options&) {
  return render_with(s, ps, v, source::pixel, pvr::precision::float32);
}
scheme_frame cheap_float(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& v,
                         const render_options&) {
  return render_with(s, ps, v, source::cheap, pvr::precision::float32);
}

}  // namespace gsdot3::pipeline::powervr_methods
