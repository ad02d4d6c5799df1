// powervr/texture.hpp — normals to bump texels and back.
//
// KallistiOS utils/pvrtex/pixel.h pxlFloattoSpherical (read with the search tool): normalise; azimuth
// = atan2(y, x), + 2π if negative; altitude = clamp(acos(z), 0, π/2) (the angle from the normal);
// R = (u8)(azimuth/(2π)·255 + 0.5), S = (u8)(altitude/(π/2)·255 + 0.5) ^ 0xFF — rounding by +0.5 and
// truncation, and the elevation inverted so that 255 = straight out. In float, as it is written.
// Round to nearest: S = round(asin(z)·510/π), R = round(azimuth·steps/2π) mod steps, in double.
#pragma once

#include <glm/vec3.hpp>

#include "powervr/texel.hpp"

namespace gsdot3::schemes::powervr {

enum class texel_rounding { kallistios, nearest };
constexpr const char* name(texel_rounding r) noexcept {
  return r == texel_rounding::kallistios ? "kallistios" : "nearest";
}

// `n` need not be unit length (it is normalised; a zero vector gives the flat texel S = 255, R = 0);
// normals below the surface (z < 0) get elevation 0. `a` is used by `nearest` only (KallistiOS
// always writes /255).
bump_texel encode_normal(const glm::dvec3& n, texel_rounding r, azimuth_scale a) noexcept;

// The unit normal a texel stands for: (cos e cos r, cos e sin r, sin e), e = S·(π/2)/255, r = R·2π/steps.
glm::dvec3 decode_normal(bump_texel t, azimuth_scale a) noexcept;

}  // namespace gsdot3::schemes::powervr
