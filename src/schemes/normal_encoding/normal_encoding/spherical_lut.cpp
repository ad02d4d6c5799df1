// The seed's two LUTs for Method #3a (see spherical_lut.hpp). Unity's Color holds floats, so each value
// is computed and rounded to float before the byte conversion.
#include "normal_encoding/spherical_lut.hpp"

#include <cmath>
#include <numbers>

namespace gsdot3::normal_encoding::spherical_lut {

namespace {
std::uint8_t byte_of(float v) {
  const float c = v < 0 ? 0.0f : v > 1 ? 1.0f : v;
  return static_cast<std::uint8_t>(c * 255.0f);  // truncation (see the header)
}

tables build() {
  tables t{};
  const float pi = std::numbers::pi_v<float>;
  const float sizeF = static_cast<float>(size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const float xval = x / sizeF * 2.0f - 1.0f, yval = y / sizeF * 2.0f - 1.0f;
      // Math.Atan2 is double in .NET; the sum is stored in a float Color.
      const double atan_res = (std::atan2(static_cast<double>(yval), static_cast<double>(xval)) + pi) / (pi * 2.0);
      t.atan2_lookup[static_cast<std::size_t>(y * size + x)] = byte_of(static_cast<float>(atan_res + 0.5 / 255.0));
    }
  for (int y = 0; y < size; ++y) {
    const float angY = y / sizeF * 2.0f - 1.0f;
    const float scphi = std::sqrt(1.0f - angY * angY);
    for (int x = 0; x < size; ++x) {
      const float ang = (x / sizeF * 2.0f - 1.0f) * pi;
      const float vs = std::sin(ang), vc = std::cos(ang);
      const float h = 0.5f / 255.0f;
      t.sincos[static_cast<std::size_t>(y * size + x)] = {byte_of(vc * scphi * 0.5f + 0.5f + h),
                                                          byte_of(vs * scphi * 0.5f + 0.5f + h),
                                                          byte_of(angY * 0.5f + 0.5f + h)};
    }
  }
  return t;
}
}  // namespace

const tables& lut() {
  static const tables t = build();
  return t;
}

}  // namespace gsdot3::normal_encoding::spherical_lut
