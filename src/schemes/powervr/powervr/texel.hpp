// powervr/texel.hpp — the PowerVR Series 2 bump texel and offset colour (seed 004, "Bump Mapping
// Tricks for Series 2", Imagination Technologies 1999), as 8-bit fields.
//
// Texel, 16 bits: high byte S = elevation of the normal above the surface (0..255 ↦ 0..π/2, 255 =
// straight out), low byte R = azimuth (0..255 ↦ 0..2π). How the hardware scales the azimuth is not
// public; two conventions are in use and are a named option:
//   flycast_255  R·2π/255 (flycast, core/rend/gles/gles.cpp, PixelPipelineShader main(): s = PI/2·S/255,
//                r = 2·PI·R/255, Q read as 2·PI·offset.b with offset.b = Q/255),
//   kos_256      R·2π/256 (KallistiOS utils/pvrtex/pixel.h pxlSphericaltoABGR8888, which decodes the
//                elevation with /255 but the azimuth with /256; the PowerVR SDK's KMBump.c
//                FXYZLightDirToSKK also writes Q as "0-360 degrees represented by 0 to 256").
// Offset colour (per vertex/polygon): K1 in A, K2 in R, K3 in G, Q in B (seed; flycast reads the
// same channels), each 0..255 ↦ 0..1 (Q: an azimuth in the texel's convention).
#pragma once

#include <cstdint>
#include <numbers>

namespace gsdot3::schemes::powervr {

enum class azimuth_scale { flycast_255, kos_256 };
constexpr int azimuth_steps(azimuth_scale a) noexcept { return a == azimuth_scale::flycast_255 ? 255 : 256; }
constexpr const char* name(azimuth_scale a) noexcept { return a == azimuth_scale::flycast_255 ? "az255" : "az256"; }

struct bump_texel {
  std::uint8_t S = 255;  // elevation
  std::uint8_t R = 0;    // azimuth
  constexpr std::uint16_t packed() const noexcept { return static_cast<std::uint16_t>(S << 8 | R); }
  static constexpr bump_texel unpack(std::uint16_t v) noexcept {
    return {static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v & 0xFF)};
  }
  friend constexpr bool operator==(bump_texel, bump_texel) = default;
};

struct offset_colour {
  std::uint8_t K1 = 0, K2 = 0, K3 = 0, Q = 0;
  // The 32-bit offset colour word as KallistiOS' pvr_pack_bump returns it: K1<<24 | K2<<16 | K3<<8 | Q.
  constexpr std::uint32_t packed() const noexcept {
    return static_cast<std::uint32_t>(K1) << 24 | static_cast<std::uint32_t>(K2) << 16 |
           static_cast<std::uint32_t>(K3) << 8 | Q;
  }
  friend constexpr bool operator==(offset_colour, offset_colour) = default;
};

// Radians of an elevation byte (S·(π/2)/255, both conventions) and of an azimuth byte.
constexpr double elevation_of(int S) noexcept { return S * (std::numbers::pi / 2.0) / 255.0; }
constexpr double azimuth_of(int R, azimuth_scale a) noexcept { return R * (2.0 * std::numbers::pi) / azimuth_steps(a); }

static_assert(bump_texel::unpack(0xFF00) == bump_texel{255, 0});
static_assert(offset_colour{1, 2, 3, 4}.packed() == 0x01020304u);

}  // namespace gsdot3::schemes::powervr
