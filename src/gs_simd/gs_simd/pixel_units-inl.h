// gs_simd/pixel_units-inl.h — the GS per-pixel units over a vector of pixels (Google Highway), one
// function per scalar unit of src/gs_arith, which stays the reference: each function here is checked
// bit for bit against the scalar unit it names (tests/gs_simd: exhaustively where the unit's domain is
// at most 2^32 inputs, by rapidcheck elsewhere; fuzz/alu_diff compares the whole chain).
// Every lane is one pixel, one channel per vector, in 32-bit lanes (all intermediate values of the
// chain fit: the widest is the blend's (A − B)·C, s17). Register fields and model options are scalars
// shared by the whole span, so the per-span `switch`es pick the unit's variant and the lanes do only
// the arithmetic. Included once per SIMD target by pixel_span.cpp (foreach_target.h).
#if defined(GSDOT3_PIXEL_UNITS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef GSDOT3_PIXEL_UNITS_INL_H_
#undef GSDOT3_PIXEL_UNITS_INL_H_
#else
#define GSDOT3_PIXEL_UNITS_INL_H_
#endif

#include <cstdint>

#include "gs_arith/depth_test.hpp"
#include "gs_arith/pixel_pipeline.hpp"
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace gsdot3::simd::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::ScalableTag<std::int32_t>;
using V = hn::Vec<D>;
using M = hn::Mask<D>;

HWY_INLINE V set(int v) { return hn::Set(D(), v); }
HWY_INLINE V byte_of(V word, int k) { return hn::And(hn::ShiftRightSame(word, 8 * k), set(0xFF)); }
// A logical right shift of a 32-bit word (the lanes are signed; the top bits are masked off).
HWY_INLINE V bits_of_word(V word, int shift, int width) {
  return hn::And(hn::ShiftRightSame(word, shift), set(static_cast<int>((1u << width) - 1u)));
}

// The four channels of a pixel, one vector each.
struct rgba_v {
  V r, g, b, a;
};
HWY_INLINE rgba_v unpack(V word) { return {byte_of(word, 0), byte_of(word, 1), byte_of(word, 2), byte_of(word, 3)}; }
// One colour in every lane: a flat colour's four 8.7 channels.
HWY_INLINE rgba_v flat(const gs::fragment_colour& c) {
  return {set(c.r.value()), set(c.g.value()), set(c.b.value()), set(c.a.value())};
}
// Byte b of the GS local memory held as 32-bit words (byte b = bits 8·(b % 4) of word b / 4, as
// gs::mem::local_memory::byte reads it).
HWY_INLINE std::uint32_t memory_byte(const std::uint32_t* memory, std::uint32_t b) {
  return (memory[b >> 2] >> (8 * (b & 3))) & 0xFFu;
}
// gs::rgba8::to_u32: A8B8G8R8.
HWY_INLINE V pack32(const rgba_v& c) {
  return hn::Or(hn::Or(c.r, hn::ShiftLeft<8>(c.g)), hn::Or(hn::ShiftLeft<16>(c.b), hn::ShiftLeft<24>(c.a)));
}

// gs::modulate_channel: (Ct·Cf_8.7) >> 14 (keep_fraction) or (Ct·(Cf_8.7 >> 7)) >> 7 (truncate_to_8).
// Both products are non-negative (u8 × u15 < 2^23), where floor and toward zero agree; the 9-bit
// wrap of the scalar unit never acts (255·32767 >> 14 = 509), and is applied all the same.
HWY_INLINE V modulate(V ct, V cf, const gs::model_options& o) {
  const V p = o.gouraud == gs::gouraud_fraction::keep_fraction ? hn::ShiftRight<14>(hn::Mul(ct, cf))
                                                               : hn::ShiftRight<7>(hn::Mul(ct, hn::ShiftRight<7>(cf)));
  return hn::And(p, set(511));
}
// gs::clamp_255 of a non-negative value.
HWY_INLINE V clamp_255(V v) { return hn::Min(v, set(255)); }

// gs::texture_function (TFX × TCC); cf holds the four 8.7 channels.
HWY_INLINE rgba_v texture_function(gs::tfx fn, gs::tcc cc, const rgba_v& ct, const rgba_v& cf,
                                   const gs::model_options& o) {
  const V af = hn::ShiftRight<7>(cf.a);
  auto rgb = [&](V t, V f) {
    switch (fn) {
      case gs::tfx::MODULATE: return clamp_255(modulate(t, f, o));
      case gs::tfx::DECAL: return t;
      case gs::tfx::HIGHLIGHT:
      case gs::tfx::HIGHLIGHT2: return clamp_255(hn::Add(modulate(t, f, o), af));
    }
    return t;
  };
  V a = af;
  if (cc == gs::tcc::RGBA) {
    switch (fn) {
      case gs::tfx::MODULATE: a = clamp_255(modulate(ct.a, cf.a, o)); break;
      case gs::tfx::DECAL: a = ct.a; break;
      case gs::tfx::HIGHLIGHT: a = clamp_255(hn::Add(ct.a, af)); break;
      case gs::tfx::HIGHLIGHT2: a = ct.a; break;
    }
  }
  return {rgb(ct.r, cf.r), rgb(ct.g, cf.g), rgb(ct.b, cf.b), a};
}
// gs::texture_off (PRIM.TME = 0): the integer parts.
HWY_INLINE rgba_v texture_off(const rgba_v& cf) {
  return {hn::ShiftRight<7>(cf.r), hn::ShiftRight<7>(cf.g), hn::ShiftRight<7>(cf.b), hn::ShiftRight<7>(cf.a)};
}

// gs::alpha_test_passes: "A ATST AREF" per lane.
HWY_INLINE M alpha_test_passes(gs::atst method, V a, int aref) {
  const V r = set(aref);
  switch (method) {
    case gs::atst::NEVER: return hn::FirstN(D(), 0);
    case gs::atst::ALWAYS: return hn::Eq(a, a);
    case gs::atst::LESS: return hn::Lt(a, r);
    case gs::atst::LEQUAL: return hn::Not(hn::Gt(a, r));
    case gs::atst::EQUAL: return hn::Eq(a, r);
    case gs::atst::GEQUAL: return hn::Not(hn::Lt(a, r));
    case gs::atst::GREATER: return hn::Gt(a, r);
    case gs::atst::NOTEQUAL: return hn::Ne(a, r);
  }
  return hn::FirstN(D(), 0);
}
// gs::alpha_test: which of RGB, A and Z each lane writes.
struct write_masks {
  M rgb, a, z;
};
HWY_INLINE write_masks alpha_test(const gs::test_reg& t, V a, gs::frame_psm psm, const gs::model_options& o) {
  const M all = hn::Eq(a, a);
  if (!t.ATE) return {all, all, all};
  const M pass = alpha_test_passes(t.ATST, a, t.AREF.value());
  const M none = hn::FirstN(D(), 0);
  switch (t.AFAIL) {
    case gs::afail::KEEP: return {pass, pass, pass};
    case gs::afail::FB_ONLY: return {all, all, pass};
    case gs::afail::ZB_ONLY: return {pass, pass, all};
    case gs::afail::RGB_ONLY:
      if (gs::bits_of(psm) == gs::pixel_bits::b32 || o.rgb_only == gs::rgb_only_targets::all_formats)
        return {all, pass, pass};
      return {all, all, pass};
  }
  return {all, all, none};
}

// gs::frame_read: (Cd, Ad) as the blender reads a frame-buffer word.
HWY_INLINE rgba_v frame_read(gs::frame_psm psm, V word) {
  switch (gs::bits_of(psm)) {
    case gs::pixel_bits::b32: return unpack(word);
    case gs::pixel_bits::b24: {
      rgba_v c = unpack(word);
      c.a = set(0x80);
      return c;
    }
    case gs::pixel_bits::b16: {
      auto five = [&](int shift) { return hn::ShiftLeft<3>(bits_of_word(word, shift, 5)); };
      return {five(0), five(5), five(10), hn::ShiftLeft<7>(bits_of_word(word, 15, 1))};
    }
  }
  return unpack(word);
}

// gs::blend_channel: ((a − b)·c >> 7) + d, the shift floor or toward zero. The scalar unit's s10
// wrap never acts: |a − b|·c ≤ 255·255 = 65025, >> 7 gives −509..508.
HWY_INLINE V blend_channel(V a, V b, V c, V d, gs::blend_shift shift) {
  const V product = hn::Mul(hn::Sub(a, b), c);
  if (shift == gs::blend_shift::floor) return hn::Add(hn::ShiftRight<7>(product), d);
  const V bias = hn::IfThenElseZero(hn::Lt(product, set(0)), set(127));  // toward zero
  return hn::Add(hn::ShiftRight<7>(hn::Add(product, bias)), d);
}
HWY_INLINE V select_colour(gs::blend_colour sel, V cs, V cd) {
  switch (sel) {
    case gs::blend_colour::Cs: return cs;
    case gs::blend_colour::Cd: return cd;
    case gs::blend_colour::zero: return set(0);
  }
  return set(0);
}
// gs::alpha_blend's three RGB channels (s11 in 32-bit lanes).
struct rgb_v {
  V r, g, b;
};
HWY_INLINE rgb_v alpha_blend(const gs::alpha_reg& reg, const rgba_v& cs, const rgba_v& cd, const gs::model_options& o) {
  const V c = reg.C == gs::blend_alpha::As ? cs.a : reg.C == gs::blend_alpha::Ad ? cd.a : set(reg.FIX.value());
  auto channel = [&](V s, V d) {
    return blend_channel(select_colour(reg.A, s, d), select_colour(reg.B, s, d), c, select_colour(reg.D, s, d),
                         o.shift);
  };
  return {channel(cs.r, cd.r), channel(cs.g, cd.g), channel(cs.b, cd.b)};
}

// gs::dither_value over lanes of 3-bit entries.
HWY_INLINE V dither_value(V dm, gs::dither_decode decode) {
  const V magnitude = hn::And(dm, set(3));
  const M negative = hn::Ne(hn::And(dm, set(4)), set(0));
  switch (decode) {
    case gs::dither_decode::twos_complement: return hn::IfThenElse(negative, hn::Sub(dm, set(8)), dm);
    case gs::dither_decode::sign_magnitude: return hn::IfThenElse(negative, hn::Neg(magnitude), magnitude);
    case gs::dither_decode::inverted_magnitude: return hn::IfThenElse(negative, hn::Sub(set(-1), magnitude), magnitude);
  }
  return set(0);
}
// gs::dither: the DIMX entry of each lane's (x & 3, y & 3), decoded, added with the s11 saturation.
HWY_INLINE V dither_offsets(const gs::dimx_reg& dimx, V x, V y, gs::dither_decode decode) {
  alignas(64) std::int32_t entries[16];
  for (int i = 0; i < 16; ++i)
    entries[i] = dimx.DM[static_cast<std::size_t>(i / 4)][static_cast<std::size_t>(i % 4)].value();
  const V index = hn::Or(hn::ShiftLeft<2>(hn::And(y, set(3))), hn::And(x, set(3)));
  return dither_value(hn::GatherIndex(D(), entries, index), decode);
}
HWY_INLINE V dither_add(V v, V offset) { return hn::Min(hn::Max(hn::Add(v, offset), set(-1024)), set(1023)); }

// gs::colclamp_channel: 0..255 (CLAMP = 1) or the low 8 bits (CLAMP = 0).
HWY_INLINE V colclamp_channel(V v, bool clamp) {
  return clamp ? hn::Min(hn::Max(v, set(0)), set(255)) : hn::And(v, set(0xFF));
}
// gs::apply_fba on the alpha lanes.
HWY_INLINE V apply_fba(V a, bool FBA, gs::frame_psm psm) {
  return FBA && gs::bits_of(psm) != gs::pixel_bits::b24 ? hn::Or(a, set(0x80)) : a;
}
// gs::pack16: A1B5G5R5.
HWY_INLINE V pack16(const rgba_v& c) {
  return hn::Or(hn::Or(hn::ShiftRight<3>(c.r), hn::ShiftLeft<5>(hn::ShiftRight<3>(c.g))),
                hn::Or(hn::ShiftLeft<10>(hn::ShiftRight<3>(c.b)), hn::ShiftLeft<15>(hn::ShiftRight<7>(c.a))));
}
// gs::frame_pack.
HWY_INLINE V frame_pack(gs::frame_psm psm, const rgba_v& c) {
  switch (gs::bits_of(psm)) {
    case gs::pixel_bits::b32: return pack32(c);
    case gs::pixel_bits::b24: return hn::And(pack32(c), set(0x00FFFFFF));
    case gs::pixel_bits::b16: return pack16(c);
  }
  return pack32(c);
}
// gs::frame_mask of a per-lane FBMSK.
HWY_INLINE V frame_mask(gs::frame_psm psm, V fbmsk) {
  switch (gs::bits_of(psm)) {
    case gs::pixel_bits::b32: return fbmsk;
    case gs::pixel_bits::b24: return hn::Or(fbmsk, set(static_cast<int>(0xFF000000u)));
    case gs::pixel_bits::b16: return hn::Or(pack16(unpack(fbmsk)), set(static_cast<int>(0xFFFF0000u)));
  }
  return fbmsk;
}
// gs::masked_merge: a 1 in keep keeps the old bit.
HWY_INLINE V masked_merge(V fresh, V old, V keep) { return hn::Or(hn::AndNot(keep, fresh), hn::And(old, keep)); }

// gs::depth_test per lane: z the source depths (bits as unsigned), zd the stored words; zs the clamped
// depths the Z buffer takes where `write`.
struct depth_lanes {
  M pass, write;
  V zs;
};
HWY_INLINE depth_lanes depth_test(const gs::test_reg& t, const gs::zbuf_reg& zbuf, V z, V zd) {
  const D d;
  const hn::RebindToUnsigned<D> du;
  const unsigned bits = gs::z_bits(zbuf.PSM);
  const auto max = hn::Set(du, bits == 32 ? 0xFFFFFFFFu : (std::uint32_t{1} << bits) - 1);
  const auto zs = hn::Min(hn::BitCast(du, z), max), stored = hn::And(hn::BitCast(du, zd), max);
  M pass = hn::Eq(z, z);
  if (t.ZTE) {
    switch (t.ZTST) {
      case gs::ztst::NEVER: pass = hn::FirstN(d, 0); break;
      case gs::ztst::ALWAYS: break;
      case gs::ztst::GEQUAL: pass = hn::RebindMask(d, hn::Not(hn::Lt(zs, stored))); break;
      case gs::ztst::GREATER: pass = hn::RebindMask(d, hn::Gt(zs, stored)); break;
    }
  }
  return {pass, zbuf.ZMSK ? hn::FirstN(d, 0) : pass, hn::BitCast(d, zs)};
}

// gs::pixel_pipeline's `out` for one vector of pixels: texel and dst are words, cf the four 8.7
// channels, x and y the window coordinates.
HWY_INLINE V pixel_pipeline(const gs::gs_registers& regs, const gs::model_options& o, V texel, const rgba_v& cf, V dst,
                            V x, V y) {
  const gs::frame_psm psm = regs.FRAME_1.PSM;
  const rgba_v cs =
      regs.PRIM.TME ? texture_function(regs.TEX0_1.TFX, regs.TEX0_1.TCC, unpack(texel), cf, o) : texture_off(cf);
  const write_masks test = alpha_test(regs.TEST_1, cs.a, psm, o);
  rgb_v v{cs.r, cs.g, cs.b};
  if (regs.PRIM.ABE) {
    const rgb_v blended = alpha_blend(regs.ALPHA_1, cs, frame_read(psm, dst), o);
    if (regs.PABE.PABE) {
      const M skip = hn::Lt(cs.a, set(0x80));
      v = {hn::IfThenElse(skip, cs.r, blended.r), hn::IfThenElse(skip, cs.g, blended.g),
           hn::IfThenElse(skip, cs.b, blended.b)};
    } else {
      v = blended;
    }
  }
  if (gs::dither_applies(regs.DTHE.DTHE, psm, o)) {
    const V d = dither_offsets(regs.DIMX, x, y, o.dither);
    v = {dither_add(v.r, d), dither_add(v.g, d), dither_add(v.b, d)};
  }
  const bool clamp = regs.COLCLAMP.CLAMP;
  const rgba_v c{colclamp_channel(v.r, clamp), colclamp_channel(v.g, clamp), colclamp_channel(v.b, clamp),
                 apply_fba(cs.a, regs.FBA_1.FBA, psm)};
  const V disabled = hn::Or(hn::IfThenZeroElse(test.rgb, set(0x00FFFFFF)),
                            hn::IfThenZeroElse(test.a, set(static_cast<int>(0xFF000000u))));
  const V keep = frame_mask(psm, hn::Or(set(static_cast<int>(regs.FRAME_1.FBMSK)), disabled));
  return masked_merge(frame_pack(psm, c), dst, keep);
}

// The first n < lanes words at p replaced by f(their vector): with masked moves where the target has
// them (AVX2's and AVX-512's touch no memory outside the mask), through a copy elsewhere.
template <class F>
HWY_INLINE void part_vector(std::int32_t* p, std::size_t n, F&& f) {
  const D d;
#if HWY_TARGET <= HWY_AVX2
  const M m = hn::FirstN(d, n);
  hn::BlendedStore(f(hn::MaskedLoad(m, d, p)), m, d, p);
#else
  alignas(64) std::int32_t copy[HWY_MAX_BYTES / 4] = {};
  for (std::size_t j = 0; j < n; ++j) copy[j] = p[j];
  hn::Store(f(hn::Load(d, copy)), d, copy);
  for (std::size_t j = 0; j < n; ++j) p[j] = copy[j];
#endif
}

}  // namespace gsdot3::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // GSDOT3_PIXEL_UNITS_INL_H_
