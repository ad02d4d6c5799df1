// Seed 002's encodings in the report (scheme_normal_encoding.hpp). Compiled with -ffp-contract=off.
#include "pipeline/scheme_normal_encoding.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "normal_encoding/methods.hpp"
#include "pipeline/pixel_walk.hpp"

namespace gsdot3::pipeline {

namespace ne = normal_encoding;

namespace {
ne::vec3 to_ne(glm::dvec3 v) { return {v.x, v.y, v.z}; }
glm::dvec3 from_ne(ne::vec3 v) { return {v.x, v.y, v.z}; }

scheme_frame render_stored(ne::method_id id, const scene& s, const prepared_scene& ps,
                           const std::vector<std::int32_t>& visible) {
  // The 8-bit palette makes this cheap: each palette normal is encoded and decoded once. The decoded
  // vector is used as is (not renormalised), as a shader using the decoded G-buffer normal would.
  const auto& m = ne::method_of(id);
  std::vector<glm::dvec3> decoded;
  for (const auto& n : s.normals.palette)
    decoded.push_back(from_ne(m.decode(ne::encode_2010(m, to_ne(glm::dvec3(n)), 8), 8)));
  scheme_frame f;
  const std::size_t count = static_cast<std::size_t>(ps.width) * static_cast<std::size_t>(ps.height);
  f.dot.assign(s.lights.size(), std::vector<float>(count, NAN));
  for_each_covered_pixel(ps, visible, [&](const pixel_sample& p) {
    const glm::dvec3 N =
        decoded[palette_entry(s.normals, ps.triangles[p.triangle].layer,
                              wrapped_texel(s.normals.width, s.normals.height, p.u16 >> 4, p.v16 >> 4))];
    for (std::size_t l = 0; l < s.lights.size(); ++l) {
      const pixel_light pl = interpolate_light(ps, l, p);
      f.dot[l][p.index] = static_cast<float>(128.0 * pl.fade * glm::dot(N, glm::normalize(pl.T)));
    }
  });
  f.colour = compose_lit(s, ps, visible, f.dot, false, 1.0);
  return f;
}
}  // namespace

scheme_frame render_enc_xyz(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& v,
                            const render_options&) {
  return render_stored(ne::method_id::xyz, s, ps, v);
}
scheme_frame render_enc_xy(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& v,
                           const render_options&) {
  return render_stored(ne::method_id::xy, s, ps, v);
}
scheme_frame render_enc_spheremap(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& v,
                                  const render_options&) {
  return render_stored(ne::method_id::spheremap, s, ps, v);
}
scheme_frame render_enc_stereographic(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& v,
                                      const render_options&) {
  return render_stored(ne::method_id::stereographic, s, ps, v);
}
scheme_frame render_enc_octahedral(const scene& s, const prepared_scene& ps, const std::vector<std::int32_t>& v,
                                   const render_options&) {
  return render_stored(ne::method_id::octahedral, s, ps, v);
}

std::vector<psnr_row> normal_encoding_psnr(const scene& s, const prepared_scene& ps,
                                           const std::vector<std::int32_t>& visible, int bits) {
  // The view rotation of prepare() (yaw 0): glm::lookAt's upper 3×3.
  const glm::dmat3 view(glm::lookAt(glm::dvec3(s.view.eye), glm::dvec3(s.view.target), glm::dvec3(0, 1, 0)));
  struct px {
    glm::dvec3 raw, unit, geometric;
  };
  std::vector<px> pixels;
  for_each_covered_pixel(ps, visible, [&](const pixel_sample& p) {
    const auto& tri = ps.triangles[p.triangle];
    glm::dvec3 t(0), b(0), n(0);
    for (int k = 0; k < 3; ++k) {
      const vertex& v = s.model.vertices[tri.vertex[static_cast<std::size_t>(k)]];
      t += p.lambda[k] * glm::dvec3(v.tangent);
      b += p.lambda[k] * glm::dvec3(v.bitangent);
      n += p.lambda[k] * glm::dvec3(v.normal);
    }
    const glm::dvec3 tn(s.normals.palette[palette_entry(
        s.normals, tri.layer, wrapped_texel(s.normals.width, s.normals.height, p.u16 >> 4, p.v16 >> 4))]);
    const glm::dvec3 raw = view * (tn.x * t + tn.y * b + tn.z * n);
    pixels.push_back({raw, glm::normalize(raw), view * n});
  });
  std::size_t facing_away = 0;
  double length_sum = 0;
  for (const auto& p : pixels) {
    facing_away += p.unit.z < 0 ? 1 : 0;
    length_sum += glm::length(p.raw);
  }
  std::vector<psnr_row> rows;
  for (const auto& m : ne::methods()) {
    if (m.only_8_bits && bits != 8) continue;
    // #8 takes the per-pixel view vector; the scene's is not kept per pixel, so it runs with the view
    // straight down −z (its table frame), i.e. as #1.
    ne::seed_error_sum given, given8(8), raw_self, bug;
    ne::seed_2009_sum as_2009;
    for (const auto& p : pixels) {
      as_2009.add(m, to_ne(p.geometric), bits);
      const ne::vec3 v = to_ne(p.raw), n = to_ne(p.unit);
      const ne::vec3 dn = m.decode(m.encode(n, bits), bits), dv = m.decode(m.encode(v, bits), bits);
      given.add(n, dn);
      given8.add(n, dn);
      raw_self.add(v, dv);
      bug.add(n, dv);
    }
    rows.push_back({std::string(m.name), pixels.size(), facing_away, given.done(), given8.done(), raw_self.done(),
                    bug.done(), length_sum / static_cast<double>(std::max<std::size_t>(1, pixels.size())),
                    as_2009.done()});
  }
  return rows;
}

}  // namespace gsdot3::pipeline
