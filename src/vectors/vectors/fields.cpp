// vectors/fields.cpp — reading a vector line's fields and building the units' cases (fields.hpp).
#include "vectors/fields.hpp"

#include <array>
#include <string>

namespace gsdot3::vectors::fields {

using gs::u8;

void check_max(std::uint64_t v, std::uint64_t max, std::string_view name) {
  if (v > max) throw domain_error(std::string(name) + " above its maximum");
}
gs::s11 s11_field(std::uint64_t v, std::string_view name) {
  check_max(v, 0x7FF, name);
  return gs::s11::from_wrapped(v);
}
std::uint64_t s11_bits(gs::s11 v) { return static_cast<std::uint64_t>(v.value()) & 0x7FF; }
gs::rgb_wide wide_fields(const values& in, std::size_t first) {
  return {s11_field(in[first], "R"), s11_field(in[first + 1], "G"), s11_field(in[first + 2], "B")};
}
values wide_values(const gs::rgb_wide& w) { return {s11_bits(w.r), s11_bits(w.g), s11_bits(w.b)}; }

gs::frame_psm psm_field(std::uint64_t v) {
  static constexpr std::array valid = {gs::frame_psm::PSMCT32,  gs::frame_psm::PSMCT24, gs::frame_psm::PSMCT16,
                                       gs::frame_psm::PSMCT16S, gs::frame_psm::PSMZ32,  gs::frame_psm::PSMZ24,
                                       gs::frame_psm::PSMZ16,   gs::frame_psm::PSMZ16S};
  for (auto p : valid) {
    if (static_cast<std::uint64_t>(p) == v) return p;
  }
  throw domain_error("PSM is not a frame-buffer format (00 01 02 0a 30 31 32 3a)");
}
std::uint32_t frame_word(std::uint64_t v, gs::frame_psm psm, std::string_view name) {
  check_max(v, gs::bits_of(psm) == gs::pixel_bits::b16 ? 0xFFFF : 0xFFFFFFFF, name);
  return static_cast<std::uint32_t>(v);
}
std::uint64_t fit_frame_word(std::uint32_t w, std::uint64_t psm) {
  return gs::bits_of(static_cast<gs::frame_psm>(psm)) == gs::pixel_bits::b16 ? (w & 0xFFFFu) : w;
}

gs::rgba8 colour_field(std::uint64_t v, std::string_view name) {
  check_max(v, 0xFFFFFFFF, name);
  return gs::rgba8::from_u32(static_cast<std::uint32_t>(v));
}
gs::gouraud_channel cf_field(std::uint64_t v) {
  check_max(v, 0x7FFF, "Cf (8.7)");
  return gs::gouraud_channel::from_wrapped(v);
}
gs::fragment_colour fragment_fields(const values& in, std::size_t first) {
  return {cf_field(in[first]), cf_field(in[first + 1]), cf_field(in[first + 2]), cf_field(in[first + 3])};
}
std::uint64_t cf_random(random& rng) {
  return std::uint64_t{rng.colour_byte()} << 7 | (rng.coin() ? 0 : rng.below(128));
}

std::uint64_t word(int r, int g, int b, int a) {
  return static_cast<std::uint64_t>(r & 0xFF) | static_cast<std::uint64_t>(g & 0xFF) << 8 |
         static_cast<std::uint64_t>(b & 0xFF) << 16 | static_cast<std::uint64_t>(a & 0xFF) << 24;
}
std::uint64_t wide_bits(int v) { return static_cast<std::uint64_t>(v) & 0x7FF; }
std::uint64_t wide_random(random& rng) {
  if (rng.coin()) return wide_bits(wide_boundary[rng.below(std::size(wide_boundary))]);
  return rng.below(0x800);
}

std::uint64_t alpha_value(int a, int b, int c, int d, int fix) {
  return gs::encode(gs::alpha_reg{static_cast<gs::blend_colour>(a), static_cast<gs::blend_colour>(b),
                                  static_cast<gs::blend_alpha>(c), static_cast<gs::blend_colour>(d),
                                  u8::from_wrapped(fix)});
}
std::uint64_t alpha_random(random& rng) {
  auto sel = [&] { return static_cast<int>(rng.below(3)); };
  const int a = sel(), b = sel(), c = sel(), d = sel();
  return alpha_value(a, b, c, d, rng.colour_byte());
}
std::uint64_t test_value(bool ate, int atst, int aref, int afail) {
  gs::test_reg t;
  t.ATE = ate;
  t.ATST = static_cast<gs::atst>(atst);
  t.AREF = u8::from_wrapped(aref);
  t.AFAIL = static_cast<gs::afail>(afail);
  return gs::encode(t);
}
std::uint64_t test_random(random& rng) {
  const bool ate = rng.coin();
  const int atst = static_cast<int>(rng.below(8));
  const int aref = rng.colour_byte();
  return test_value(ate, atst, aref, static_cast<int>(rng.below(4)));
}
std::uint64_t dimx_random(random& rng) {
  gs::dimx_reg d;
  for (auto& row : d.DM) {
    for (auto& e : row) e = gs::u3::from_wrapped(rng.below(8));
  }
  return gs::encode(d);
}
std::uint64_t dimx_filled(int dm) {
  gs::dimx_reg d;
  for (auto& row : d.DM) row.fill(gs::u3::from_wrapped(dm));
  return gs::encode(d);
}
std::uint64_t prim_value(bool tme, bool abe) {
  gs::prim_reg p;
  p.PRIM = gs::prim_type::SPRITE;
  p.TME = tme;
  p.ABE = abe;
  return gs::encode(p);
}
std::uint64_t tex0_value(int tfx, int tcc) {
  gs::tex0_reg t;
  t.TFX = static_cast<gs::tfx>(tfx);
  t.TCC = static_cast<gs::tcc>(tcc);
  return gs::encode(t);
}
std::uint64_t frame_value(std::uint64_t psm, std::uint32_t fbmsk) {
  gs::frame_reg f;
  f.PSM = static_cast<gs::frame_psm>(psm);
  f.FBMSK = fbmsk;
  return gs::encode(f);
}

}  // namespace gsdot3::vectors::fields
