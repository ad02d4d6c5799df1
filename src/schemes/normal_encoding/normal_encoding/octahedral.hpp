// normal_encoding/octahedral.hpp — octahedral encoding (not in the seeds; e.g. meshoptimizer
// `meshopt_encodeFilterOct`, Cigolle et al. JCGT 2014). p = n.xy/(|x| + |y| + |z|); for z < 0 fold:
// p = ((1 − |p.y|)·sign p.x, (1 − |p.x|)·sign p.y), sign(0) = +1. Decode: z = 1 − |x| − |y|; if z < 0
// unfold the same way; normalise.
// Stored as unorm (enc = p·0.5 + 0.5, round to nearest), as snorm (round half away, scale 2^(b−1) − 1),
// or unorm "precise" (Cigolle et al.): floor each coordinate, try the 4 floor/ceil neighbours, keep the
// code whose decoded vector has the largest cosine to n (the first of equals in the order ff, cf, fc, cc).
#pragma once

#include <cmath>
#include <cstdint>

#include "normal_encoding/quantise.hpp"
#include "normal_encoding/vec.hpp"

namespace gsdot3::normal_encoding::octahedral {

constexpr double sign_not_zero(double v) noexcept { return v < 0 ? -1.0 : 1.0; }

inline void enc(vec3 n, double& u, double& v) noexcept {
  const double s = std::fabs(n.x) + std::fabs(n.y) + std::fabs(n.z);
  u = n.x / s;
  v = n.y / s;
  if (n.z < 0) {
    const double fu = (1 - std::fabs(v)) * sign_not_zero(u), fv = (1 - std::fabs(u)) * sign_not_zero(v);
    u = fu;
    v = fv;
  }
}
inline vec3 dec(double u, double v) noexcept {
  const double z = 1 - std::fabs(u) - std::fabs(v);
  if (z < 0) {
    const double fu = (1 - std::fabs(v)) * sign_not_zero(u), fv = (1 - std::fabs(u)) * sign_not_zero(v);
    u = fu;
    v = fv;
  }
  return normalize(vec3{u, v, z});
}

inline code encode(vec3 n, int bits) {
  check_bits(bits);
  double u, v;
  enc(n, u, v);
  return {{unorm_encode(u * 0.5 + 0.5, bits), unorm_encode(v * 0.5 + 0.5, bits), 0}};
}
inline vec3 decode(code q, int bits) {
  check_bits(bits);
  return dec(unorm_decode(q.c[0], bits) * 2 - 1, unorm_decode(q.c[1], bits) * 2 - 1);
}

inline code encode_snorm(vec3 n, int bits) {
  check_bits(bits);
  double u, v;
  enc(n, u, v);
  const auto bias = static_cast<std::int32_t>(std::uint32_t{1} << (bits - 1));
  return {{static_cast<std::uint32_t>(snorm_encode(u, bits) + bias),
           static_cast<std::uint32_t>(snorm_encode(v, bits) + bias), 0}};
}
inline vec3 decode_snorm(code q, int bits) {
  check_bits(bits);
  const auto bias = static_cast<std::int32_t>(std::uint32_t{1} << (bits - 1));
  return dec(snorm_decode(static_cast<std::int32_t>(q.c[0]) - bias, bits),
             snorm_decode(static_cast<std::int32_t>(q.c[1]) - bias, bits));
}

inline code encode_precise(vec3 n, int bits) {
  check_bits(bits);
  double u, v;
  enc(n, u, v);
  const double m = unorm_max(bits);
  const auto clampq = [&](double t) { return static_cast<std::uint32_t>(t < 0 ? 0 : t > m ? m : t); };
  const std::uint32_t fu = clampq(std::floor((u * 0.5 + 0.5) * m)), fv = clampq(std::floor((v * 0.5 + 0.5) * m));
  const vec3 nn = normalize(n);
  code best{{fu, fv, 0}};
  double best_cos = -2;
  for (std::uint32_t dv = 0; dv < 2; ++dv)
    for (std::uint32_t du = 0; du < 2; ++du) {
      const code c{{clampq(fu + du), clampq(fv + dv), 0}};
      const double cs = dot(decode(c, bits), nn);
      if (cs > best_cos) {
        best_cos = cs;
        best = c;
      }
    }
  return best;
}

}  // namespace gsdot3::normal_encoding::octahedral
