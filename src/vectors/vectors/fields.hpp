// vectors/fields.hpp — internal to the unit table (units.cpp): a vector line's hex fields read as the
// model's values (a value outside a field's range is a domain_error), and the register values, colour
// words and boundary patterns the units' case generators build their cases from.
#pragma once

#include <cstdint>
#include <iterator>
#include <string_view>

#include "gs_arith/pixel_pipeline.hpp"
#include "gs_arith/registers.hpp"
#include "vectors/units.hpp"

namespace gsdot3::vectors::fields {

// ---- reading fields -------------------------------------------------------------------------------
void check_max(std::uint64_t v, std::uint64_t max, std::string_view name);
// An 11-bit two's-complement field (the blender's s11 values).
gs::s11 s11_field(std::uint64_t v, std::string_view name);
std::uint64_t s11_bits(gs::s11 v);
gs::rgb_wide wide_fields(const values& in, std::size_t first);  // R, G, B from in[first..]
values wide_values(const gs::rgb_wide& w);
gs::frame_psm psm_field(std::uint64_t v);
// A frame-buffer word of format psm (16-bit formats hold the low half only).
std::uint32_t frame_word(std::uint64_t v, gs::frame_psm psm, std::string_view name);
std::uint64_t fit_frame_word(std::uint32_t w, std::uint64_t psm);
gs::rgba8 colour_field(std::uint64_t v, std::string_view name);
gs::gouraud_channel cf_field(std::uint64_t v);                             // 8.7
gs::fragment_colour fragment_fields(const values& in, std::size_t first);  // Cf R, G, B, A from in[first..]

// Register decoders report a bad value as gs::register_error; here it is a domain error.
template <typename Decode>
auto decode(Decode&& d, std::uint64_t v) {
  try {
    return d(v);
  } catch (const gs::register_error& e) { throw domain_error(e.what()); }
}

// ---- building cases -------------------------------------------------------------------------------
inline constexpr std::uint64_t frame_formats[] = {0x00, 0x01, 0x02, 0x0a, 0x30, 0x31, 0x32, 0x3a};
inline constexpr std::uint64_t level1_formats[] = {0x00, 0x01, 0x02};  // one of each pixel size
// s11 values at the edges of the blend output range (−509..763), of 8 bits and of 11 bits.
inline constexpr int wide_boundary[] = {-1024, -509, -256, -255,  -1,    0,     1,   0x7F,
                                        0x80,  0xFE, 0xFF, 0x100, 0x101, 0x1FF, 763, 1023};
// A DIMX matrix with every 3-bit value, the pattern PCSX2's default DIMX resembles.
inline constexpr std::uint64_t dimx_mixed = 0x7340'2615'0736'5142u;  // every nibble <= 7

std::uint64_t word(int r, int g, int b, int a);  // a colour word 0xAABBGGRR
std::uint64_t cf_random(random& rng);
std::uint64_t wide_bits(int v);
std::uint64_t wide_random(random& rng);
std::uint64_t alpha_value(int a, int b, int c, int d, int fix);
std::uint64_t alpha_random(random& rng);
std::uint64_t test_value(bool ate, int atst, int aref, int afail);
std::uint64_t test_random(random& rng);
std::uint64_t dimx_random(random& rng);
std::uint64_t dimx_filled(int dm);
std::uint64_t prim_value(bool tme, bool abe);  // a SPRITE
std::uint64_t tex0_value(int tfx, int tcc);
std::uint64_t frame_value(std::uint64_t psm, std::uint32_t fbmsk);

}  // namespace gsdot3::vectors::fields
