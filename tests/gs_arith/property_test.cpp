// gs_arith_property — algebraic properties of the GS units over random registers and colours
// (rapidcheck). Each property is a fact stated independently of the code: an identity of the
// formulas in ../shared/spec/gs-alu-facts.md, or of register semantics.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <optional>

#include "gs_arith/alpha_blend.hpp"
#include "gs_arith/bilinear.hpp"
#include "gs_arith/colclamp.hpp"
#include "gs_arith/frame_write.hpp"
#include "gs_arith/gouraud.hpp"
#include "gs_arith/pixel_pipeline.hpp"
#include "gs_arith/registers.hpp"
#include "gs_arith/texture_function.hpp"
#include "model_calls.hpp"
#include "reference.hpp"

namespace {

using gs::rgba8;
using gs::u8;

using gs_test::u8v;

rc::Gen<int> byte_gen() { return rc::gen::inRange(0, 256); }
rc::Gen<std::uint32_t> word_gen() { return rc::gen::arbitrary<std::uint32_t>(); }

rc::Gen<gs::model_options> options_gen() {
  return rc::gen::map(rc::gen::inRange(0, 64), [](int bits) {
    gs::model_options o;
    o.tfx = (bits & 1) ? gs::tfx_rounding::truncate : gs::tfx_rounding::floor;
    o.gouraud = (bits & 2) ? gs::gouraud_fraction::truncate_to_8 : gs::gouraud_fraction::keep_fraction;
    o.shift = (bits & 4) ? gs::blend_shift::truncate : gs::blend_shift::floor;
    o.dither = (bits & 8) ? gs::dither_decode::sign_magnitude : gs::dither_decode::twos_complement;
    o.dither_on = (bits & 16) ? gs::dither_targets::all_formats : gs::dither_targets::sixteen_bit_only;
    o.bilinear = (bits & 32) ? gs::bilinear_mode::nearest : gs::bilinear_mode::lerp16_4;
    return o;
  });
}

// A random register set, every field drawn from its valid values.
gs::gs_registers random_registers() {
  const auto u64 = [] { return *rc::gen::arbitrary<std::uint64_t>(); };
  gs::gs_registers r;
  const std::uint64_t prim = (u64() & 0x7F8) | static_cast<std::uint64_t>(*rc::gen::inRange(0, 7));
  gs::set_register(r, "PRIM", prim);
  const auto sel = [] { return static_cast<std::uint64_t>(*rc::gen::inRange(0, 3)); };
  gs::set_register(r, "ALPHA_1", sel() | sel() << 2 | sel() << 4 | sel() << 6 | (u64() & 0xFF) << 32);
  gs::set_register(r, "TEST_1", u64() & 0x7FFFF);
  const std::uint64_t psm = *rc::gen::element<std::uint64_t>(0x00, 0x01, 0x02, 0x0A, 0x30, 0x31, 0x32, 0x3A);
  gs::set_register(r, "FRAME_1", (u64() & 0xFFFFFFFF003F01FFull) | psm << 24);
  const std::uint64_t tpsm = *rc::gen::element<std::uint64_t>(0x00, 0x01, 0x02, 0x0A, 0x13, 0x14, 0x1B, 0x24, 0x2C);
  const std::uint64_t cpsm = *rc::gen::element<std::uint64_t>(0x0, 0x2, 0xA);
  const auto tw = static_cast<std::uint64_t>(*rc::gen::inRange(0, 11));
  const auto th = static_cast<std::uint64_t>(*rc::gen::inRange(0, 11));
  gs::set_register(r, "TEX0_1", (u64() & 0xFF87FFFC000FFFFFull) | tpsm << 20 | tw << 26 | th << 30 | cpsm << 51);
  gs::set_register(r, "COLCLAMP", u64() & 1);
  gs::set_register(r, "PABE", u64() & 1);
  gs::set_register(r, "FBA_1", u64() & 1);
  gs::set_register(r, "DTHE", u64() & 1);
  gs::set_register(r, "DIMX", u64() & 0x7777777777777777ull);
  return r;
}

std::uint32_t frame_word_for(const gs::gs_registers& r, std::uint32_t w) {
  return gs::bits_of(r.FRAME_1.PSM) == gs::pixel_bits::b16 ? (w & 0xFFFFu) : w;
}

gs::pixel_input random_input(const gs::gs_registers& r) {
  return {gs::fragment_colour::flat(rgba8::from_u32(*word_gen())), rgba8::from_u32(*word_gen()),
          frame_word_for(r, *word_gen()), static_cast<unsigned>(*rc::gen::inRange(0, 4096)),
          static_cast<unsigned>(*rc::gen::inRange(0, 4096))};
}

// MODULATE with vertex colour 0x80 (1.0) is DECAL, for both TCC and every option.
RC_GTEST_PROP(GsArithProperty, ModulateByOneIsDecal, ()) {
  const auto o = *options_gen();
  const rgba8 texel = rgba8::from_u32(*word_gen());
  const auto one = gs::fragment_colour::flat(rgba8::from_u32(0x80808080u));
  for (auto cc : {gs::tcc::RGB, gs::tcc::RGBA})
    RC_ASSERT(gs::texture_function(gs::tfx::MODULATE, cc, texel, one, o) ==
              gs::texture_function(gs::tfx::DECAL, cc, texel, one, o));
}

// (Cs − Cd)·FIX + Cd with FIX = 0x80 gives Cs, under both blend shifts.
RC_GTEST_PROP(GsArithProperty, FixOneBlendGivesCs, ()) {
  const auto o = *options_gen();
  const rgba8 cs = rgba8::from_u32(*word_gen()), cd = rgba8::from_u32(*word_gen());
  const gs::alpha_reg reg{gs::blend_colour::Cs, gs::blend_colour::Cd, gs::blend_alpha::FIX, gs::blend_colour::Cd,
                          u8v(0x80)};
  RC_ASSERT(gs::alpha_blend(reg, cs, cd, o) == gs::blend_off(cs));
}

// A = B cancels the product: the result is D for every C.
RC_GTEST_PROP(GsArithProperty, EqualABGivesD, ()) {
  const auto o = *options_gen();
  const int a = *byte_gen(), c = *byte_gen(), d = *byte_gen();
  RC_ASSERT(gs::blend_channel(u8v(a), u8v(a), u8v(c), u8v(d), o.shift).value() == d);
}

// Wrap equals clamp whenever the pre-clamp value is in 0..255.
RC_GTEST_PROP(GsArithProperty, WrapEqualsClampInRange, ()) {
  const int v = *rc::gen::inRange(0, 256);
  const auto w = gs::s11::from_wrapped(v);
  RC_ASSERT(gs::colclamp_channel(w, false) == gs::colclamp_channel(w, true));
  RC_ASSERT(gs::colclamp_channel(w, true).value() == v);
}

// Through the whole pipeline: COLCLAMP = 0 and 1 write the same word when the wide value is in 0..255.
RC_GTEST_PROP(GsArithProperty, PipelineWrapEqualsClampInRange, ()) {
  auto regs = random_registers();
  const auto in = random_input(regs);
  const auto o = *options_gen();
  regs.COLCLAMP.CLAMP = true;
  const auto clamped = gs::pixel_pipeline(regs, in, o);
  regs.COLCLAMP.CLAMP = false;
  const auto wrapped = gs::pixel_pipeline(regs, in, o);
  auto in_range = [](gs::s11 v) { return v.value() >= 0 && v.value() <= 255; };
  const auto& w = clamped.dithered;
  if (in_range(w.r) && in_range(w.g) && in_range(w.b)) RC_ASSERT(clamped.out == wrapped.out);
}

// FBMSK = all ones leaves the frame buffer unchanged, whatever else the registers say.
RC_GTEST_PROP(GsArithProperty, FullFbmskKeepsFrameBuffer, ()) {
  auto regs = random_registers();
  regs.FRAME_1.FBMSK = 0xFFFFFFFFu;
  const auto in = random_input(regs);
  RC_ASSERT(gs::pixel_pipeline(regs, in, *options_gen()).out == in.dst);
}

// PABE with As < 0x80 passes Cs: no blend, whatever ALPHA_1 says.
RC_GTEST_PROP(GsArithProperty, PabeLowAlphaPassesCs, ()) {
  auto regs = random_registers();
  regs.PRIM.ABE = true;
  regs.PRIM.TME = false;
  regs.PABE.PABE = true;
  regs.TEST_1.ATE = false;
  regs.DTHE.DTHE = false;
  regs.FBA_1.FBA = false;
  regs.FRAME_1 = {};
  const std::uint32_t vertex = *word_gen() & 0x7FFFFFFFu;
  auto in = random_input(regs);
  in.vertex = gs::fragment_colour::flat(rgba8::from_u32(vertex));
  RC_ASSERT(gs::pixel_pipeline(regs, in, *options_gen()).out == vertex);
}

// With no texture, blend, test, dither, mask or FBA, a PSMCT32 pixel is the vertex colour.
RC_GTEST_PROP(GsArithProperty, NeutralPipelineWritesVertex, ()) {
  const gs::gs_registers regs;
  const std::uint32_t vertex = *word_gen();
  auto in = random_input(regs);
  in.vertex = gs::fragment_colour::flat(rgba8::from_u32(vertex));
  RC_ASSERT(gs::pixel_pipeline(regs, in, *options_gen()).out == vertex);
}

// ATE = 0 behaves as ATST = ALWAYS.
RC_GTEST_PROP(GsArithProperty, AlphaTestOffIsAlways, ()) {
  auto regs = random_registers();
  const auto in = random_input(regs);
  const auto o = *options_gen();
  auto off = regs, always = regs;
  off.TEST_1.ATE = false;
  always.TEST_1.ATE = true;
  always.TEST_1.ATST = gs::atst::ALWAYS;
  RC_ASSERT(gs::pixel_pipeline(off, in, o) == gs::pixel_pipeline(always, in, o));
}

// Options only matter where their unit is used: with TME = 0, ABE = 0 and DTHE = 0 the result does
// not depend on any option.
RC_GTEST_PROP(GsArithProperty, OptionsIrrelevantWithoutTheirUnits, ()) {
  auto regs = random_registers();
  regs.PRIM.TME = false;
  regs.PRIM.ABE = false;
  regs.DTHE.DTHE = false;
  const auto in = random_input(regs);
  RC_ASSERT(gs::pixel_pipeline(regs, in, *options_gen()).out == gs::pixel_pipeline(regs, in, {}).out);
}

// Every 64-bit value either decodes and re-encodes to itself, or is rejected.
RC_GTEST_PROP(GsArithProperty, DecodeEncodeIdentityOrError, ()) {
  const auto name = gs::register_names[*rc::gen::inRange<std::size_t>(0, std::size(gs::register_names))];
  // Sparse values reach the valid encodings often; dense ones exercise the reserved bits.
  const std::uint64_t v = *rc::gen::oneOf(
      rc::gen::arbitrary<std::uint64_t>(),
      rc::gen::map(rc::gen::arbitrary<std::uint64_t>(), [](std::uint64_t x) { return x & (x >> 7) & (x >> 13); }));
  gs::gs_registers regs;
  if (gs_test::decodes(regs, name, v)) RC_ASSERT(gs::register_value(regs, name) == v);
}

// Valid random registers survive encode -> decode.
RC_GTEST_PROP(GsArithProperty, RegistersRoundTrip, ()) {
  const auto regs = random_registers();
  gs::gs_registers copy;
  for (auto name : gs::register_names) gs::set_register(copy, name, gs::register_value(regs, name));
  RC_ASSERT(copy == regs);
}

// A 16-bit word read by the blender and packed again is the same word.
RC_GTEST_PROP(GsArithProperty, SixteenBitReadPackIdentity, ()) {
  const std::uint32_t w = *word_gen() & 0xFFFFu;
  RC_ASSERT(gs::frame_pack(gs::frame_psm::PSMCT16, gs::frame_read(gs::frame_psm::PSMCT16, w)) == w);
}

// Bilinear: four equal texels filter to that texel; a lerp lies between its ends.
RC_GTEST_PROP(GsArithProperty, BilinearStaysInRange, ()) {
  const rgba8 t = rgba8::from_u32(*word_gen());
  const auto wu = gs::u4::from_wrapped(*rc::gen::inRange(0, 16)), wv = gs::u4::from_wrapped(*rc::gen::inRange(0, 16));
  RC_ASSERT(gs::bilinear_filter(t, t, t, t, wu, wv) == t);
  const int c0 = *byte_gen(), c1 = *byte_gen();
  const int l = gs::lerp16_4(u8v(c0), u8v(c1), wu).value();
  RC_ASSERT(std::min(c0, c1) <= l && l <= std::max(c0, c1));
}

// Gouraud: along a span the value moves monotonically from c0 toward c1 and never passes c1.
RC_GTEST_PROP(GsArithProperty, GouraudSpanMonotone, ()) {
  const int c0 = *byte_gen(), c1 = *byte_gen(), n = *rc::gen::inRange(1, 2048);
  const auto step = gs::gouraud_gradient(u8v(c0), u8v(c1), n);
  const auto start = gs::gouraud_value(u8v(c0));
  const int k = *rc::gen::inRange(0, n);
  const long long here = gs::gouraud_at(start, step, k).value(), next = gs::gouraud_at(start, step, k + 1).value();
  const bool monotone = c1 >= c0 ? here <= next : here >= next;
  RC_ASSERT(monotone);
  RC_ASSERT(std::min(c0, c1) * 128 <= next && next <= std::max(c0, c1) * 128);
}

// A random triangle with 12.4 vertices in a `window`-pixel square, its set-up for a random reference
// pixel, and a random pixel around it; `rv` carries channel `channel` of the vertex colours.
struct random_triangle {
  gs_ref::plane_vertex rv[3];
  int xr, yr, x, y;
  std::optional<gs::gouraud_plane> plane;
};
random_triangle random_gouraud_triangle(int window, int channel) {
  random_triangle t;
  gs::gouraud_vertex gv[3];
  for (int i = 0; i < 3; ++i) {
    const int x = *rc::gen::inRange(0, window * 16), y = *rc::gen::inRange(0, window * 16);
    const std::uint32_t c = *word_gen();
    gv[i] = {x, y, rgba8::from_u32(c)};
    t.rv[i] = {x, y, gs_ref::byte(c, channel)};
  }
  const auto pixel = [&] { return *rc::gen::inRange(-16, window + 16); };
  t.xr = pixel(), t.yr = pixel(), t.x = pixel(), t.y = pixel();
  t.plane = gs::gouraud_triangle(gv[0], gv[1], gv[2], t.xr, t.yr);
  return t;
}

// Gouraud triangle setup against the barycentric formulation of the same documented rule, on random
// triangles with 12.4 vertices anywhere in a 256-pixel window and random pixels around them.
RC_GTEST_PROP(GsArithProperty, GouraudTriangleMatchesBarycentric, ()) {
  const auto t = random_gouraud_triangle(256, 1);  // the green channel
  RC_PRE(gs_ref::plane_det(t.rv) != 0);
  RC_ASSERT(t.plane.has_value());
  RC_ASSERT(static_cast<long long>(gs::gouraud_at(*t.plane, t.x, t.y).g.value()) ==
            gs_ref::gouraud_plane_at(t.rv, t.xr, t.yr, t.x, t.y));
}

// gouraud_setup = per_pixel and per_pixel_floor against the same barycentric formulation read at the
// pixel itself (the whole 2048-pixel window): its distance from vertex 0 truncated, and the value
// floored; per_pixel against plane_steps at the reference pixel (both the start value there).
RC_GTEST_PROP(GsArithProperty, GouraudExactAndFloorAtMatchBarycentric, ()) {
  const auto t = random_gouraud_triangle(2048, 0);  // the red channel
  RC_PRE(gs_ref::plane_det(t.rv) != 0);
  RC_ASSERT(t.plane.has_value());
  RC_ASSERT(static_cast<long long>(gs::gouraud_exact_at(*t.plane, t.x, t.y).r.value()) ==
            gs_ref::gouraud_exact_at(t.rv, t.x, t.y));
  RC_ASSERT(static_cast<long long>(gs::gouraud_floor_at(*t.plane, t.x, t.y).r.value()) ==
            gs_ref::gouraud_floor_at(t.rv, t.x, t.y));
  RC_ASSERT(gs::gouraud_colour(*t.plane, t.xr, t.yr, gs::gouraud_setup::per_pixel) ==
            gs::gouraud_colour(*t.plane, t.xr, t.yr, gs::gouraud_setup::plane_steps));
}

}  // namespace
