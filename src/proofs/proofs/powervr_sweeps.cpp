// proofs/powervr_sweeps.cpp — see powervr_sweeps.hpp.
#include "proofs/powervr_sweeps.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "powervr/encode.hpp"
#include "powervr/texture.hpp"

namespace gsdot3::proofs::powervr_sweeps {

identity_case identity_case_at(const identity_grid& g, pvr::azimuth_scale a, std::uint64_t i) {
  const std::uint64_t nl = g.intensities.size(), nt = g.elevations.size(), nq = g.q_bytes.size();
  const double S_l = g.intensities[i % nl];
  const double T = g.elevations[(i / nl) % nt];
  const int Q = g.q_bytes[(i / nl / nt) % nq];
  const auto texel = pvr::bump_texel::unpack(static_cast<std::uint16_t>(i / nl / nt / nq));
  const double q = pvr::azimuth_of(Q, a);
  pvr::offset_colour k = pvr::offset_nearest({S_l, T, q}, a);
  k.Q = static_cast<std::uint8_t>(Q);
  const glm::dvec3 N = pvr::decode_normal(texel, a),
                   L{std::cos(T) * std::cos(q), std::cos(T) * std::sin(q), std::sin(T)};
  const double v = (1.0 - S_l) + S_l * (N.x * L.x + N.y * L.y + N.z * L.z);
  return {texel, k, S_l, T, 255.0 * std::clamp(v, 0.0, 1.0)};
}

error_stats identity_8bit_error(const identity_grid& g, pvr::azimuth_scale a, pvr::precision p,
                                const sweep_config& cfg) {
  const auto fly = p == pvr::precision::float32 ? std::make_unique<pvr::flycast_tables>(a) : nullptr;
  const pvr::fixed_tables* tb = p == pvr::precision::float32 ? nullptr : &pvr::tables(pvr::table_bits(p), a);
  // The grid's lights, in index order within one texel (identity_case_at computes the same per case).
  struct light {
    pvr::offset_colour k;
    double S_l;
    glm::dvec3 L;
  };
  std::vector<light> lights;
  for (std::uint64_t j = 0; j < g.size() / 65536; ++j) {
    const identity_case c = identity_case_at(g, a, j);
    const double q = pvr::azimuth_of(c.k.Q, a);
    lights.push_back({c.k, c.S_l, {std::cos(c.T) * std::cos(q), std::cos(c.T) * std::sin(q), std::sin(c.T)}});
  }
  return sweep<error_stats>(65536, cfg, [&](error_stats& acc, std::uint64_t b, std::uint64_t e) {
    for (std::uint64_t texel = b; texel < e; ++texel) {
      const auto t = pvr::bump_texel::unpack(static_cast<std::uint16_t>(texel));
      const glm::dvec3 N = pvr::decode_normal(t, a);
      for (std::size_t j = 0; j < lights.size(); ++j) {
        const light& l = lights[j];
        const double expected =
            255.0 * std::clamp((1.0 - l.S_l) + l.S_l * (N.x * l.L.x + N.y * l.L.y + N.z * l.L.z), 0.0, 1.0);
        const int out =
            fly ? static_cast<int>(std::lround(fly->value(t, l.k) * 255.0f)) : pvr::intensity_fixed(*tb, t, l.k);
        acc.add(out - expected, texel * lights.size() + j);
      }
    }
  });
}

}  // namespace gsdot3::proofs::powervr_sweeps
