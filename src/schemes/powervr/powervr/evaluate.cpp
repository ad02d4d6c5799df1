// powervr/evaluate.cpp — the bump unit under each precision option (see evaluate.hpp).
#include "powervr/evaluate.hpp"

#include <cmath>
#include <numbers>

namespace gsdot3::schemes::powervr {

const char* name(precision p) noexcept {
  switch (p) {
    case precision::float32: return "float";
    case precision::fixed8: return "fixed8";
    case precision::fixed10: return "fixed10";
    case precision::fixed12: return "fixed12";
  }
  return "?";
}

double intensity_exact(bump_texel t, offset_colour k, azimuth_scale a) noexcept {
  const double s = elevation_of(t.S), d = azimuth_of(t.R, a) - azimuth_of(k.Q, a);
  return k.K1 + k.K2 * std::sin(s) + k.K3 * std::cos(s) * std::cos(d);
}

namespace {
// flycast core/rend/gles/gles.cpp, PixelPipelineShader main() under pp_BumpMap: the texel channels
// and the offset colour arrive as x/255 floats; PI is the shader's 3.1415926. Under kos_256 the
// azimuths are x/256 instead.
constexpr float pi = 3.1415926f;
float angle_s(int S) noexcept { return pi / 2.0f * static_cast<float>(S) / 255.0f; }
float angle_r(int R, azimuth_scale a) noexcept {
  return 2.0f * pi * static_cast<float>(R) / static_cast<float>(azimuth_steps(a));
}
float angle_q(int Q, azimuth_scale a) noexcept {
  return 2.0f * pi * (static_cast<float>(Q) / static_cast<float>(azimuth_steps(a)));
}
}  // namespace

flycast_tables::flycast_tables(azimuth_scale a) {
  for (int i = 0; i < 256; ++i) {
    sin_s[static_cast<std::size_t>(i)] = std::sin(angle_s(i));
    cos_s[static_cast<std::size_t>(i)] = std::cos(angle_s(i));
  }
  for (int r = 0; r < 256; ++r)
    for (int q = 0; q < 256; ++q)
      cos_rq[static_cast<std::size_t>(r << 8 | q)] = std::cos(angle_r(r, a) - angle_q(q, a));
}

float intensity_flycast(bump_texel t, float k1, float k2, float k3, float q01, azimuth_scale a) noexcept {
  const float s = angle_s(t.S), r = angle_r(t.R, a),
              q = 2.0f * pi * (q01 * (255.0f / static_cast<float>(azimuth_steps(a))));
  const float v = k1 + k2 * std::sin(s) + k3 * std::cos(s) * std::cos(r - q);
  return v < 0.0f ? 0.0f : v > 1.0f ? 1.0f : v;
}

float intensity_flycast(bump_texel t, offset_colour k, azimuth_scale a) noexcept {
  const float s = angle_s(t.S), r = angle_r(t.R, a), q = angle_q(k.Q, a);
  const float k1 = static_cast<float>(k.K1) / 255.0f, k2 = static_cast<float>(k.K2) / 255.0f,
              k3 = static_cast<float>(k.K3) / 255.0f;
  const float v = k1 + k2 * std::sin(s) + k3 * std::cos(s) * std::cos(r - q);
  return v < 0.0f ? 0.0f : v > 1.0f ? 1.0f : v;
}

std::uint8_t intensity(bump_texel t, offset_colour k, azimuth_scale a, precision p) noexcept {
  if (p == precision::float32) return static_cast<std::uint8_t>(std::lround(intensity_flycast(t, k, a) * 255.0f));
  return intensity_fixed(tables(table_bits(p), a), t, k);
}

namespace {
fixed_tables make_tables(int bits, azimuth_scale a) {
  fixed_tables tb;
  tb.bits = bits;
  tb.steps = azimuth_steps(a);
  const double one = std::ldexp(1.0, bits);
  for (int i = 0; i < 256; ++i) {
    tb.sin_s[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(std::lround(one * std::sin(elevation_of(i))));
    tb.cos_s[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(std::lround(one * std::cos(elevation_of(i))));
    tb.cos_d[static_cast<std::size_t>(i)] =
        i < tb.steps ? static_cast<std::int32_t>(std::lround(one * std::cos(azimuth_of(i, a)))) : 0;
  }
  return tb;
}
}  // namespace

const fixed_tables& tables(int bits, azimuth_scale a) {
  static const std::array<fixed_tables, 6> all{
      make_tables(8, azimuth_scale::flycast_255),  make_tables(10, azimuth_scale::flycast_255),
      make_tables(12, azimuth_scale::flycast_255), make_tables(8, azimuth_scale::kos_256),
      make_tables(10, azimuth_scale::kos_256),     make_tables(12, azimuth_scale::kos_256)};
  const std::size_t row = bits == 8 ? 0 : bits == 10 ? 1 : 2;
  return all[row + (a == azimuth_scale::kos_256 ? 3 : 0)];
}

}  // namespace gsdot3::schemes::powervr
