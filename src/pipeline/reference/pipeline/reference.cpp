// pipeline/reference.cpp — see reference.hpp. Compiled with -ffp-contract=off (CMakeLists).
#include "pipeline/reference.hpp"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "pipeline/pixel_walk.hpp"

namespace gsdot3::pipeline {

reference_frame render_reference(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& visible,
                                 bool bilinear, double power, const std::vector<std::int32_t>& plain) {
  reference_frame r;
  r.width = ps.width;
  r.height = ps.height;
  const std::size_t n = static_cast<std::size_t>(ps.width) * static_cast<std::size_t>(ps.height);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  r.renormalised.assign(s.lights.size(), std::vector<float>(n, nan));
  r.unnormalised = r.renormalised;

  const normal_map& nm = s.normals;
  for_each_covered_pixel(ps, visible, [&](const pixel_sample& p) {
    const prepared_triangle& tri = ps.triangles[p.triangle];
    auto normal_texel = [&](std::int32_t u, std::int32_t v) {
      return glm::dvec3(texel_normal(nm, tri.layer, wrapped_texel(nm.width, nm.height, u, v)));
    };
    const glm::dvec3 N = glm::normalize(filtered(normal_texel, p.u16, p.v16, bilinear));
    for (std::size_t l = 0; l < s.lights.size(); ++l) {
      const pixel_light pl = interpolate_light(ps, l, p);
      const double spot = interpolate_spot(ps, l, p);
      glm::dvec3 faded(0.0);
      for (std::size_t k = 0; k < 3; ++k) {
        const light_vertex& lv = ps.lights[l][tri.vertex[k]];
        faded += glm::dvec3(lv.T) * static_cast<double>(lv.fade) * p.lambda[static_cast<int>(k)];
      }
      r.renormalised[l][p.index] = static_cast<float>(
          glm::length(pl.T) > 0.0 ? 128.0 * spot * pl.fade * glm::dot(N, glm::normalize(pl.T)) : 0.0);
      r.unnormalised[l][p.index] = static_cast<float>(128.0 * spot * glm::dot(N, faded));
    }
  });
  r.colour = compose_lit(s, ps, visible, r.renormalised, bilinear, power);
  compose_plain(s, ps, plain, bilinear, r.colour);
  return r;
}

}  // namespace gsdot3::pipeline
