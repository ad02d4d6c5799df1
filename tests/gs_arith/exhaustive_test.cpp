// gs_arith_exhaustive — each unit over its whole input domain, every mode, against the independent
// references in reference.hpp. Every test states the size of the domain it enumerates.
//
// Sanitizer builds (the `san` preset) run the six largest sweeps on a stated sub-lattice (every
// 17th value of one input), because ASan + UBSan make them ~20× slower; every other sweep is full.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>

#include "gs_arith/alpha_blend.hpp"
#include "gs_arith/alpha_test.hpp"
#include "gs_arith/bilinear.hpp"
#include "gs_arith/clut.hpp"
#include "gs_arith/colclamp.hpp"
#include "gs_arith/dither.hpp"
#include "gs_arith/frame_write.hpp"
#include "gs_arith/gouraud.hpp"
#include "gs_arith/registers.hpp"
#include "gs_arith/texture_function.hpp"
#include "model_calls.hpp"
#include "reference.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define GSDOT3_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer)
#define GSDOT3_SANITIZED 1
#endif
#endif

namespace {

using gs::rgba8;
using gs::u8;

#ifdef GSDOT3_SANITIZED
constexpr int big_stride = 17;
#else
constexpr int big_stride = 1;
#endif

using gs_test::u8v;

// Prints the number of cases a sweep checked; `strided` sweeps say when they ran on the sub-lattice.
void report(const char* what, unsigned long long cases, bool strided = false) {
  std::printf("%s: %llu cases%s\n", what, cases, strided && big_stride != 1 ? " (sanitizer build: sub-lattice)" : "");
}

// ((a − b)·c >> 7) + d over all 2^32 (a, b, c, d), both shift options (c stepped by big_stride
// only under sanitizers). The reference quotient is computed once per (a, b, c) and d added after.
TEST(GsArithExhaustive, BlendChannelAllInputs) {
  unsigned long long n = 0;
  for (auto shift : {gs::blend_shift::floor, gs::blend_shift::truncate}) {
    const bool fl = shift == gs::blend_shift::floor;
    for (int c = 0; c < 256; c += big_stride)
      for (int a = 0; a < 256; ++a)
        for (int b = 0; b < 256; ++b) {
          const int q = gs_ref::blend_channel(a, b, c, 0, fl);
          int bad = 0;
          for (int d = 0; d < 256; ++d)
            bad += gs::blend_channel(u8v(a), u8v(b), u8v(c), u8v(d), shift).value() != q + d;
          n += 256;
          if (bad != 0) FAIL() << "a " << a << " b " << b << " c " << c << " floor " << fl << ": " << bad << " d wrong";
        }
  }
  report("blend_channel (a, b, c, d) x 2 shifts", n, true);
}

// The 81 ALPHA_1 modes: for each, every (Cs, Cd) channel pair and every value of the selected C
// source (As, Ad or FIX), i.e. 81 × 256^3 per-channel cases, all three channels checked at once with
// different pairings. The other two alpha sources are set to values the mode must ignore.
TEST(GsArithExhaustive, AlphaBlendAllModes) {
  unsigned long long n = 0;
  gs::model_options o;
  for (int A = 0; A < 3; ++A)
    for (int B = 0; B < 3; ++B)
      for (int C = 0; C < 3; ++C)
        for (int D = 0; D < 3; ++D) {
          for (int cval = 0; cval < 256; cval += big_stride) {
            // The selected C source holds cval; the other two hold values the mode must ignore.
            const int as = C == 0 ? cval : 0x5A, ad = C == 1 ? cval : 0xA5, fix = C == 2 ? cval : 0x3C;
            const gs::alpha_reg reg{static_cast<gs::blend_colour>(A), static_cast<gs::blend_colour>(B),
                                    static_cast<gs::blend_alpha>(C), static_cast<gs::blend_colour>(D), u8v(fix)};
            int bad = 0;
            for (int s = 0; s < 256; ++s)
              for (int d = 0; d < 256; ++d) {
                const rgba8 cs{u8v(s), u8v(d), u8v(s), u8v(as)}, cd{u8v(d), u8v(s), u8v(255 - d), u8v(ad)};
                const auto got = gs::alpha_blend(reg, cs, cd, o);
                // Reference per channel: the selected operands by table, then gs_ref::blend_channel.
                auto want = [&](int cs_ch, int cd_ch) {
                  const int colours[3] = {cs_ch, cd_ch, 0};
                  return gs_ref::blend_channel(colours[A], colours[B], cval, colours[D], true);
                };
                bad += got.r.value() != want(s, d) || got.g.value() != want(d, s) || got.b.value() != want(s, 255 - d);
              }
            if (bad != 0) FAIL() << "mode " << A << B << C << D << " C " << cval << ": " << bad << " (Cs, Cd) wrong";
            n += 65536;
          }
        }
  report("alpha_blend 81 modes x (Cs, Cd, C)", n, true);
}

// TFX × TCC × tfx_rounding × gouraud_fraction over every texel byte and every 8.7 fragment value
// (256 × 32768 per mode; the four channels carry different pairings).
TEST(GsArithExhaustive, TextureFunctionAllModes) {
  unsigned long long n = 0;
  for (int fn = 0; fn < 4; ++fn)
    for (int cc = 0; cc < 2; ++cc)
      for (bool keep : {true, false})
        for (auto rounding : {gs::tfx_rounding::floor, gs::tfx_rounding::truncate}) {
          gs::model_options o;
          o.tfx = rounding;
          o.gouraud = keep ? gs::gouraud_fraction::keep_fraction : gs::gouraud_fraction::truncate_to_8;
          for (int t = 0; t < 256; ++t)
            for (int f = 0; f < 32768; f += (fn == 1 ? 1 : big_stride)) {
              const std::uint32_t texel = gs_ref::word(t, 255 - t, t, t);
              const int g = 32767 - f;
              const gs::fragment_colour frag{gs::gouraud_channel::from_wrapped(f), gs::gouraud_channel::from_wrapped(g),
                                             gs::gouraud_channel::from_wrapped(f),
                                             gs::gouraud_channel::from_wrapped(f)};
              const auto got = gs::texture_function(static_cast<gs::tfx>(fn), static_cast<gs::tcc>(cc),
                                                    rgba8::from_u32(texel), frag, o);
              const auto want = gs_ref::texture_function(fn, cc == 1, texel, {f, g, f, f}, keep);
              if (got.to_u32() != want)
                FAIL() << "tfx " << fn << " tcc " << cc << " keep " << keep << " Ct " << t << " Cf87 " << f;
              ++n;
            }
        }
  report("texture_function 32 modes x (Ct, Cf 8.7)", n, true);
}

// COLCLAMP over every s11 value, both modes (4096 cases).
TEST(GsArithExhaustive, ColclampAllWide) {
  for (int v = -1024; v < 1024; ++v)
    for (bool clamp : {true, false})
      ASSERT_EQ(gs::colclamp_channel(gs::s11::from_wrapped(v), clamp).value(), gs_ref::colclamp(v, clamp)) << v;
  report("colclamp s11 x 2", 4096);
}

// Dither: every blend output −509..763 × every 3-bit entry × both decodes, at each of the 16 matrix
// positions through a DIMX holding that entry everywhere (1273 × 8 × 2 × 16 cases).
TEST(GsArithExhaustive, DitherAllEntries) {
  unsigned long long n = 0;
  for (int dm = 0; dm < 8; ++dm) {
    const std::uint64_t all = 0x1111111111111111ull * static_cast<std::uint64_t>(dm);
    const gs::dimx_reg dimx = gs::decode_dimx(all);
    for (auto decode : {gs::dither_decode::twos_complement, gs::dither_decode::sign_magnitude}) {
      gs::model_options o;
      o.dither = decode;
      const int off =
          decode == gs::dither_decode::twos_complement ? gs_ref::dither_twos(dm) : gs_ref::dither_sign_magnitude(dm);
      for (int v = -509; v <= 763; ++v)
        for (unsigned pos = 0; pos < 16; ++pos) {
          const auto w = gs::s11::from_wrapped(v);
          const auto out = gs::dither({w, w, w}, dimx, pos % 4, pos / 4, true, gs::frame_psm::PSMCT16, o);
          ASSERT_EQ(out.g.value(), v + off) << "dm " << dm << " v " << v;
          ++n;
        }
    }
  }
  report("dither", n);
}

// Alpha test: ATE × 8 ATST × 4 AFAIL × all (A, AREF) × 32/24/16-bit targets.
TEST(GsArithExhaustive, AlphaTestAll) {
  unsigned long long n = 0;
  for (int method = 0; method < 8; ++method)
    for (int afail = 0; afail < 4; ++afail)
      for (bool ate : {false, true})
        for (auto psm : {gs::frame_psm::PSMCT32, gs::frame_psm::PSMCT24, gs::frame_psm::PSMCT16})
          for (int aref = 0; aref < 256; ++aref)
            for (int a = 0; a < 256; ++a) {
              const auto got = gs_test::alpha_test_of(ate, method, aref, afail, a, psm);
              const auto want = gs_ref::alpha_test(ate, method, aref, afail, a, psm == gs::frame_psm::PSMCT32);
              if (got.rgb != want[0] || got.a != want[1] || got.z != want[2])
                FAIL() << method << " " << afail << " " << ate << " " << aref << " " << a;
              ++n;
            }
  report("alpha_test", n);
}

// 16-bit frame words: every (R, G, B) triple with alpha = (R + G + B) mod 256, so every channel
// takes every value with every combination of the others (2^24 colours; every 17th R under
// sanitizers); and every 16-bit word read back (65536).
TEST(GsArithExhaustive, Pack16AllColours) {
  unsigned long long n = 0;
  for (int r = 0; r < 256; r += big_stride)
    for (int g = 0; g < 256; ++g) {
      int bad = 0;
      for (int b = 0; b < 256; ++b) {
        const std::uint32_t c = gs_ref::word(r, g, b, (r + g + b) % 256);
        bad += gs::frame_pack(gs::frame_psm::PSMCT16, rgba8::from_u32(c)) != gs_ref::pack16(c);
      }
      n += 256;
      if (bad != 0) FAIL() << "r " << r << " g " << g << ": " << bad << " wrong";
    }
  for (std::uint32_t w = 0; w < 65536; ++w)
    ASSERT_EQ(gs::frame_read(gs::frame_psm::PSMCT16, w).to_u32(), gs_ref::read16(w)) << std::hex << w;
  report("pack16 colours", n, true);
}

// FBA over every alpha byte × every frame format × FBA (256 × 8 × 2 cases); the FBMSK merge on a
// smaller instance, all (new, old, mask) bytes (2^24 cases; every 17th old under sanitizers), and at each of the 32 bit
// positions all 8 (new, old, mask) bit combinations. Reduction: masked_merge is a bitwise function, so its value at one
// bit depends only on that bit of each operand; the byte instance checks that independence by brute force, the
// per-position sweep covers every bit of the 32-bit word.
TEST(GsArithExhaustive, FbaAndMergeAll) {
  const gs::frame_psm all_psm[] = {gs::frame_psm::PSMCT32,  gs::frame_psm::PSMCT24, gs::frame_psm::PSMCT16,
                                   gs::frame_psm::PSMCT16S, gs::frame_psm::PSMZ32,  gs::frame_psm::PSMZ24,
                                   gs::frame_psm::PSMZ16,   gs::frame_psm::PSMZ16S};
  for (auto psm : all_psm)
    for (bool fba : {false, true})
      for (int a = 0; a < 256; ++a) {
        const bool is24 = psm == gs::frame_psm::PSMCT24 || psm == gs::frame_psm::PSMZ24;
        const int want = fba && !is24 ? (a < 128 ? a + 128 : a) : a;
        ASSERT_EQ(gs::apply_fba(rgba8::from_u32(gs_ref::word(1, 2, 3, a)), fba, psm).to_u32(),
                  gs_ref::word(1, 2, 3, want))
            << static_cast<int>(psm) << " " << fba << " " << a;
      }
  unsigned long long merge_cases = 0;
  for (std::uint32_t fresh = 0; fresh < 256; ++fresh)
    for (std::uint32_t old = 0; old < 256; old += static_cast<std::uint32_t>(big_stride)) {
      int bad = 0;
      for (std::uint32_t mask = 0; mask < 256; ++mask)
        bad += gs::masked_merge(fresh, old, mask) != gs_ref::merge(fresh, old, mask);
      merge_cases += 256;
      if (bad != 0) FAIL() << fresh << " " << old;
    }
  for (int bit = 0; bit < 32; ++bit)
    for (int combo = 0; combo < 8; ++combo) {
      const std::uint32_t b = 1u << bit;
      const std::uint32_t fresh = (combo & 1) ? b : 0, old = (combo & 2) ? b : 0, mask = (combo & 4) ? b : 0;
      ASSERT_EQ(gs::masked_merge(fresh, old, mask), gs_ref::merge(fresh, old, mask)) << bit << " " << combo;
    }
  report("fba + masked_merge", 256ull * 8 * 2 + merge_cases + 32 * 8, true);
}

// lerp16_4 over all (c0, c1, w): 2^20 cases.
TEST(GsArithExhaustive, Lerp16_4All) {
  for (int c0 = 0; c0 < 256; ++c0)
    for (int c1 = 0; c1 < 256; ++c1)
      for (int w = 0; w < 16; ++w)
        ASSERT_EQ(gs::lerp16_4(u8v(c0), u8v(c1), gs::u4::from_wrapped(w)).value(), gs_ref::lerp16_4(c0, c1, w))
            << c0 << " " << c1 << " " << w;
  report("lerp16_4", 1u << 20);
}

// Texel footprint over every signed 16-bit 12.4 coordinate, both modes (2 × 65536 cases):
// the footprint's first texel and weight rebuild the coordinate (minus half a texel for lerp16_4).
TEST(GsArithExhaustive, FootprintAllCoordinates) {
  for (int u = -32768; u < 32768; ++u) {
    const auto f = gs::footprint(u, -u, gs::bilinear_mode::lerp16_4);
    ASSERT_EQ(f.u0 * 16 + f.wu.value(), u - 8) << u;
    ASSERT_EQ(f.v0 * 16 + f.wv.value(), -u - 8) << u;
    const auto nf = gs::footprint(u, -u, gs::bilinear_mode::nearest);
    ASSERT_EQ(nf.u0, gs_ref::floor_div(u, 16)) << u;
    ASSERT_EQ(nf.v0, gs_ref::floor_div(-u, 16)) << u;
  }
  report("footprint", 2 * 65536);
}

// CSM1: csm1_position is a bijection on 0..255 equal to the 8×2-block layout (256 cases).
TEST(GsArithExhaustive, Csm1AllIndices) {
  bool seen[256] = {};
  for (int i = 0; i < 256; ++i) {
    const unsigned p = gs::csm1_position(u8v(i));
    ASSERT_EQ(static_cast<int>(p), gs_ref::csm1_position(i));
    ASSERT_FALSE(seen[p]);
    seen[p] = true;
  }
  report("csm1_position", 256);
}

// Gouraud gradients for every (c0, c1) and span length 1..2048 (2^27 cases; every 17th length
// under sanitizers).
TEST(GsArithExhaustive, GouraudGradientAll) {
  unsigned long long n = 0;
  for (int c0 = 0; c0 < 256; ++c0)
    for (int c1 = 0; c1 < 256; ++c1)
      for (int len = 1; len <= 2048; len += big_stride, ++n)
        if (gs::gouraud_gradient(u8v(c0), u8v(c1), len).value() != gs_ref::gradient(c0, c1, len))
          FAIL() << c0 << " " << c1 << " " << len;
  report("gouraud_gradient", n, true);
}

// Register decoding of every value of the small registers and every selector field: exactly the
// reserved encodings throw, every other value round-trips through encode.
class register_sweep {
 public:
  void check(const char* name, std::uint64_t v, bool valid) {
    ++cases_;
    gs::gs_registers regs;
    const bool ok = gs_test::decodes(regs, name, v);
    ASSERT_EQ(ok, valid) << name << " " << std::hex << v;
    if (ok) { ASSERT_EQ(gs::register_value(regs, name), v) << name << " " << std::hex << v; }
  }
  template <typename F>
  void all_below(const char* name, std::uint64_t count, F valid) {
    for (std::uint64_t v = 0; v < count; ++v) check(name, v, valid(v));
  }
  // Every bit from `first` to 63 alone is reserved.
  void reject_bits_from(const char* name, int first) {
    for (int bit = first; bit < 64; ++bit) check(name, std::uint64_t{1} << bit, false);
  }
  unsigned long long cases() const { return cases_; }

 private:
  unsigned long long cases_ = 0;
};

TEST(GsArithExhaustive, RegisterFieldsAll) {
  register_sweep r;
  r.all_below("PRIM", 1u << 11, [](std::uint64_t v) { return (v & 7) != 7; });
  r.reject_bits_from("PRIM", 11);
  r.all_below("TEST_1", 1u << 19, [](std::uint64_t) { return true; });
  r.reject_bits_from("TEST_1", 19);
  r.all_below("ALPHA_1", 1u << 8, [](std::uint64_t v) {
    return (v & 3) != 3 && (v >> 2 & 3) != 3 && (v >> 4 & 3) != 3 && (v >> 6 & 3) != 3;
  });
  for (const char* one : {"COLCLAMP", "PABE", "FBA_1", "DTHE"}) {
    r.all_below(one, 2, [](std::uint64_t) { return true; });
    r.reject_bits_from(one, 1);
  }
  r.all_below("DIMX", 1u << 16, [](std::uint64_t v) { return (v & 0x8888u) == 0; });
  // FRAME_1.PSM, TEX0_1.PSM / CPSM / TW / TH: every value of the field, the rest of the register 0.
  const auto frame_ok = [](std::uint64_t p) {
    return p == 0x00 || p == 0x01 || p == 0x02 || p == 0x0A || p == 0x30 || p == 0x31 || p == 0x32 || p == 0x3A;
  };
  for (std::uint64_t p = 0; p < 64; ++p) {
    r.check("FRAME_1", p << 24, frame_ok(p));
    r.check("TEX0_1", p << 20, frame_ok(p) || p == 0x13 || p == 0x14 || p == 0x1B || p == 0x24 || p == 0x2C);
  }
  for (std::uint64_t f = 0; f < 16; ++f) {
    r.check("TEX0_1", f << 51, f == 0 || f == 2 || f == 0xA);  // CPSM
    r.check("TEX0_1", f << 26, f <= 10);                       // TW
    r.check("TEX0_1", f << 30, f <= 10);                       // TH
  }
  report("register fields", r.cases());
}

}  // namespace
