// pipeline/scheme_valve.cpp — seed 001's two shader paths as report methods (scheme_method.hpp):
//  - rnm: the scene's normal map stored as RGB8 (round(127.5·n + 127.5) per palette normal),
//    Listing 1 in fp32;
//  - ssbump: the same RGB8 map converted by normal2ssbump (Source's float tool, truncating writer,
//    as `gsdot3 ssbump from-normal` does), Listing 2 in fp32.
// The point light: per vertex, its unit tangent-space tolight T is projected onto the basis,
// L_i = saturate(B_i·T) (valve::project_light, the seed's "project the lighting direction onto our
// basis directions"), L_i interpolated with the pixel's barycentric weights like the GS methods'
// lights, and the method's value is 128·fade·Σ D_i·L_i (fade interpolated the same way). Both are
// ≥ 0. Filtering (--filter bilinear) blends the 8-bit texels before the shader, as a texture unit.
#include <cmath>

#include <glm/geometric.hpp>

#include "pipeline/pixel_walk.hpp"
#include "pipeline/scheme_valve.hpp"
#include "valve/encode.hpp"
#include "valve/evaluate.hpp"

namespace gsdot3::pipeline {

namespace {

namespace v = gsdot3::valve;

enum class path { rnm, ssbump };

scheme_frame render_valve(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& visible,
                          const render_options& o, path which) {
  // The 8-bit texel of every palette entry, as the map would be stored.
  std::vector<v::texel> texels;
  for (const glm::vec3& n : s.normals.palette) {
    const v::texel rgb = v::encode_normal_rgb8({n.x, n.y, n.z});
    texels.push_back(which == path::rnm ? rgb : v::ssbump_texel(v::normal2ssbump(rgb)));
  }
  // L_i per light and vertex.
  std::vector<std::vector<v::lightmaps>> projected(ps.lights.size());
  for (std::size_t l = 0; l < ps.lights.size(); ++l)
    for (const light_vertex& lv : ps.lights[l]) {
      const double len = glm::length(glm::dvec3(lv.T));
      const v::vec3<double> T =
          len > 0 ? v::vec3<double>{lv.T.x / len, lv.T.y / len, lv.T.z / len} : v::vec3<double>{0, 0, 1};
      projected[l].push_back(v::project_light(T));
    }
  const v::shader_arith a{v::precision::fp32};
  scheme_frame f;
  const std::size_t n = static_cast<std::size_t>(ps.width) * static_cast<std::size_t>(ps.height);
  f.dot.assign(ps.lights.size(), std::vector<float>(n, NAN));
  for_each_covered_pixel(ps, visible, [&](const pixel_sample& p) {
    auto texel_at = [&](std::int32_t u, std::int32_t vv) {
      const v::texel& t = texels[palette_entry(s.normals, ps.triangles[p.triangle].layer,
                                               wrapped_texel(s.normals.width, s.normals.height, u, vv))];
      return glm::dvec3(t.r, t.g, t.b);
    };
    const glm::dvec3 c = filtered(texel_at, p.u16, p.v16, o.bilinear);
    const v::vec3<double> t{a.r(c.x / 255.0), a.r(c.y / 255.0), a.r(c.z / 255.0)};
    const auto& tri = ps.triangles[p.triangle].vertex;
    for (std::size_t l = 0; l < ps.lights.size(); ++l) {
      v::lightmaps L;
      for (int k = 0; k < 3; ++k) {
        const v::lightmaps& lk = projected[l][tri[static_cast<std::size_t>(k)]];
        L.L0 += p.lambda[k] * lk.L0, L.L1 += p.lambda[k] * lk.L1, L.L2 += p.lambda[k] * lk.L2;
      }
      L = {a.r(L.L0), a.r(L.L1), a.r(L.L2)};  // interpolated varyings arrive in the shader's format
      const double value = which == path::rnm ? v::rnm_diffuse_fetched(a, t, L) : v::ssbump_diffuse_fetched(a, t, L);
      const double fade = interpolate_light(ps, l, p).fade;
      f.dot[l][p.index] = std::isnan(value) ? 0.0f : static_cast<float>(128.0 * fade * value);  // NaN (Σd = 0) → black
    }
  });
  f.colour = compose_lit(s, ps, visible, f.dot, o.bilinear, o.specular_power);
  return f;
}

}  // namespace

scheme_frame render_valve_rnm(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& visible,
                              const render_options& o) {
  return render_valve(s, ps, visible, o, path::rnm);
}

scheme_frame render_valve_ssbump(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& visible,
                                 const render_options& o) {
  return render_valve(s, ps, visible, o, path::ssbump);
}

}  // namespace gsdot3::pipeline
