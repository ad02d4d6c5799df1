// gs_arith/perspective.cpp — S, T, Q at a pixel and their conversion to texels (see perspective.hpp).
// Built with -ffp-contract=off: a fused multiply-add would change the last bits of the planes.
#include "gs_arith/perspective.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gs {

namespace {

std::int64_t cross(xy124 a, xy124 b, xy124 c) {
  return static_cast<std::int64_t>(b.x - a.x) * (c.y - a.y) - static_cast<std::int64_t>(b.y - a.y) * (c.x - a.x);
}

// x86's float-to-integer conversion (cvttps2dq): toward zero, and 0x80000000 (the "integer
// indefinite") for a value outside int32 or a NaN.
std::int32_t x86_truncate(double v) {
  constexpr double limit = 2147483648.0;  // 2^31
  if (!(v > -limit - 1.0 && v < limit)) return std::numeric_limits<std::int32_t>::min();
  return static_cast<std::int32_t>(v);
}

}  // namespace

stq stq_at(const stq_triangle& t, int x, int y) {
  const xy124 p{x * 16, y * 16};
  // Barycentric weights E_i / area2, E_i the doubled area opposite vertex i (exact integers, |E_i| < 2^36).
  const std::array<double, 3> e{static_cast<double>(cross(t.v[1], t.v[2], p)),
                                static_cast<double>(cross(t.v[2], t.v[0], p)),
                                static_cast<double>(cross(t.v[0], t.v[1], p))};
  const double area = static_cast<double>(t.area2);
  auto at = [&](float stq::*m) {
    const double sum = e[0] * static_cast<double>(t.a[0].*m) + e[1] * static_cast<double>(t.a[1].*m) +
                       e[2] * static_cast<double>(t.a[2].*m);
    return static_cast<float>(sum / area);
  };
  return {at(&stq::S), at(&stq::T), at(&stq::Q)};
}

std::int32_t stq_texel(float s, float q, unsigned size_log2, const model_options& o) {
  double r = static_cast<double>(s / q);  // the float32 division
  if (o.stq_range == stq_range_mode::saturate_2047) r = std::isnan(r) ? r : std::clamp(r, -2047.0, 2047.0);
  const double texels = std::ldexp(r, static_cast<int>(size_log2));  // exact: a power of two
  switch (o.stq_convert) {
    case stq_convert_mode::truncate: return x86_truncate(texels * 16.0);
    case stq_convert_mode::floor_1_64: return x86_truncate(std::floor(texels * 16.0 + 1.0 / 64.0));
    case stq_convert_mode::trunc_16_16: return x86_truncate(texels * 65536.0) >> 12;
  }
  return 0;
}

std::array<std::int32_t, 2> stq_vertex_texel(const stq& v, unsigned TW, unsigned TH, const model_options& o) {
  return {std::clamp(stq_texel(v.S, v.Q, TW, o), -(1 << 20), 1 << 20),
          std::clamp(stq_texel(v.T, v.Q, TH, o), -(1 << 20), 1 << 20)};
}

stq_sampler make_stq_sampler(const stq_triangle& t, unsigned TW, unsigned TH, const model_options& o) {
  stq_sampler s{t, TW, TH, t.a[1].Q != t.a[0].Q || t.a[2].Q != t.a[0].Q, {}, {}};
  if (s.per_pixel) return s;
  std::array<std::int32_t, 3> u{}, v{};
  for (std::size_t k = 0; k < 3; ++k) {
    const auto uv = stq_vertex_texel(t.a[k], TW, TH, o);
    u[k] = uv[0], v[k] = uv[1];
  }
  s.u = make_uv_plane(t.v, u, uv_rule_of(o));
  s.v = make_uv_plane(t.v, v, uv_rule_of(o));
  return s;
}

}  // namespace gs
