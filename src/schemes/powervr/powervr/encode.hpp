// powervr/encode.hpp — the light as the offset colour K1, K2, K3, Q: the seed's formulas, KallistiOS'
// pvr_pack_bump and the PowerVR SDK's FXYZLightDirToSKK.
//
// Frames. gsdot3's tangent space is (t, b, n): x, y in the surface, z = the normal, and a texel's
// azimuth is measured from x towards y. The seed and the SDK treat y as the normal: their
// (Px, Py, Pz) is gsdot3's (x, z, y), so the seed's Q = arctan(Pz/Px) is arctan(y/x) here.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "powervr/texel.hpp"

namespace gsdot3::schemes::powervr {

// The light in polar form: intensity S_l (the seed's S), elevation T above the surface, azimuth Q
// (radians, in [0, 2π)).
struct polar_light {
  double S_l = 1.0, T = 0.0, Q = 0.0;
};

// Seed 004: T from Py (K2 = Py·S, K3 = sqrt(1 − Py²)·S) and Q = arctan(Pz/Px) exactly as printed: the
// principal arctangent (−π/2, π/2) of the ratio, taken modulo 2π. `P` is a unit tolight vector.
polar_light seed_printed(const glm::dvec3& P, double S_l) noexcept;
// The same with the quadrant-correct Q = atan2(Pz, Px) modulo 2π.
polar_light seed_atan2(const glm::dvec3& P, double S_l) noexcept;

// K1 = 1 − S_l, K2 = S_l sin T, K3 = S_l cos T (the seed), each round(255·k) (round half away from
// zero, clamped to 0..255); Q = round(Q·steps/2π) modulo the convention's steps.
offset_colour offset_nearest(const polar_light& l, azimuth_scale a) noexcept;

// KallistiOS kernel/arch/dreamcast/include/dc/fmath.h, pvr_pack_bump(h, t, q), in float: hp = (u8)(h·255),
// K1 = ~hp, K2 = (u8)(hp·sin t), K3 = (u8)(hp·cos t), Q = (u8)(q/(2π)·255) — every conversion truncates.
// Defined for h ∈ [0, 1], t ∈ [0, π/2], q ∈ [0, 2π) (its documented ranges).
offset_colour pvr_pack_bump(float h, float t, float q) noexcept;

// The PowerVR SDK's KMBump.c FXYZLightDirToSKK(fxyz, skk) in its own frame (y = the normal): skk[0]
// = the azimuth of (x, z) in 1/256 turns by the quadratic s·(43.562812 − 11.562812·s), s = min/max
// of |x|, |z|, folded per octant (its Octants table); skk[1] = sin T, skk[2] = cos T, in 1/256;
// each rounded to nearest (the 1.5·2^23 magic-number addition) and 256 clamped to 255; y < 0 is
// replaced by 0.00001 as the SDK does. Not modelled: the SDK's inverse square roots come from an
// 8-bit seed table and one Newton step; here sin T and cos T are exact in float.
struct skk {
  std::uint8_t s = 0, sinT = 0, cosT = 0;
};
skk fxyz_light_dir_to_skk(float x, float y, float z) noexcept;
// The quadratic arctangent alone: atan(s) for s ∈ [0, 1] in 1/256 turns (0..32).
constexpr double sdk_quadratic_arctan(double s) noexcept { return (-11.562812 * s + 43.562812) * s; }

// KMBump.c KMBumpShade, BUMP_METHOD_STANDARD: K1 = 0, K2 = 255 ("to avoid flat shading"), K3 = skk[2],
// Q = skk[0].
constexpr offset_colour sdk_standard(skk v) noexcept { return {0, 255, v.cosT, v.s}; }

}  // namespace gsdot3::schemes::powervr
