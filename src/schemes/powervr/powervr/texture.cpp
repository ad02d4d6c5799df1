// powervr/texture.cpp — normal ↔ bump texel (see texture.hpp).
#include "powervr/texture.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace gsdot3::schemes::powervr {

bump_texel encode_normal(const glm::dvec3& n, texel_rounding r, azimuth_scale a) noexcept {
  const double len = glm::length(n);
  if (!(len > 0.0)) return {255, 0};
  if (r == texel_rounding::kallistios) {
    const glm::vec3 f = glm::vec3(n / len);
    float azimuth = static_cast<float>(std::atan2(f.y, f.x));
    if (azimuth < 0) azimuth += static_cast<float>(2 * M_PI);
    const float altitude = std::clamp(std::acos(f.z), 0.0f, static_cast<float>(M_PI_2));
    const auto R = static_cast<std::uint8_t>(azimuth / (2 * M_PI) * 255 + 0.5);
    const auto S = static_cast<std::uint8_t>(static_cast<std::uint8_t>(altitude / M_PI_2 * 255 + 0.5) ^ 0xFF);
    return {S, R};
  }
  const glm::dvec3 u = n / len;
  const double e = std::asin(std::clamp(u.z, 0.0, 1.0));
  double az = std::atan2(u.y, u.x);
  if (az < 0) az += 2.0 * std::numbers::pi;
  const int steps = azimuth_steps(a);
  return {static_cast<std::uint8_t>(std::lround(e * 510.0 / std::numbers::pi)),
          static_cast<std::uint8_t>(std::lround(az * steps / (2.0 * std::numbers::pi)) % steps)};
}

glm::dvec3 decode_normal(bump_texel t, azimuth_scale a) noexcept {
  const double e = elevation_of(t.S), r = azimuth_of(t.R, a);
  return {std::cos(e) * std::cos(r), std::cos(e) * std::sin(r), std::sin(e)};
}

}  // namespace gsdot3::schemes::powervr
