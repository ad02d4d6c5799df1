// The probe design: every pair of values of every probed option is told apart by a patch, no patch
// depends on another option, tfx_rounding cannot be told apart by any input, and the model's patch
// values equal the ones worked out by hand from the GS rules (comments) — not from the code under test.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>
#include <string>

#include "gs_arith/texture_function.hpp"
#include "gs_memory/address.hpp"
#include "probe/design.hpp"
#include "probe/frame.hpp"

namespace {

using namespace gsdot3::probe;

std::vector<std::uint32_t> frame_with(const std::string& name, std::string_view value) {
  gs::model_options o;
  EXPECT_FALSE(gs::set_option(o, name, value).has_value());
  return model_frame(o);
}

std::uint32_t pixel(const std::vector<std::uint32_t>& f, const patch& p) {
  return rgb_of(f[static_cast<std::size_t>(p.y + 3) * frame_width + p.x + 3]);
}

const patch& find(const std::string& name) {
  for (const patch& p : probe_design().patches)
    if (p.name == name) return p;
  throw std::runtime_error("no patch " + name);
}

bool uniform(const std::vector<std::uint32_t>& f, const patch& p) {
  const std::uint32_t first = pixel(f, p);
  for (const auto& [x, y] : sample_pixels(p))
    if (rgb_of(f[static_cast<std::size_t>(y) * frame_width + x]) != first) return false;
  return true;
}

TEST(ProbeDesign, EveryOptionIsProbedOrNamedWithAReason) {
  for (const auto& row : gs::option_catalogue()) {
    bool probed = false, named = false;
    for (const patch& p : probe_design().patches) probed = probed || p.option == row.name;
    for (const unprobed& u : probe_design().not_probed) named = named || (u.option == row.name && !u.reason.empty());
    EXPECT_NE(probed, named) << row.name;
  }
}

TEST(ProbeDesign, EveryPairOfValuesIsToldApartByAPatch) {
  for (const auto& row : gs::option_catalogue()) {
    std::vector<const patch*> patches;
    for (const patch& p : probe_design().patches)
      if (p.option == row.name) patches.push_back(&p);
    if (patches.empty()) continue;
    std::vector<std::vector<std::uint32_t>> frames;
    for (auto v : row.values) frames.push_back(frame_with(std::string(row.name), v));
    for (std::size_t a = 0; a < frames.size(); ++a)
      for (std::size_t b = a + 1; b < frames.size(); ++b) {
        bool apart = false;
        for (const patch* p : patches)
          for (const auto& [x, y] : sample_pixels(*p)) {
            const std::size_t i = static_cast<std::size_t>(y) * frame_width + x;
            apart = apart || rgb_of(frames[a][i]) != rgb_of(frames[b][i]);
          }
        EXPECT_TRUE(apart) << row.name << ": " << row.values[a] << " and " << row.values[b];
      }
  }
}

// A patch of option X (or a check) shows the same pixels whatever value any other single option has.
TEST(ProbeDesign, NoPatchDependsOnAnotherOption) {
  const std::vector<std::uint32_t> base = model_frame({});
  for (const auto& row : gs::option_catalogue())
    for (auto value : row.values) {
      const std::vector<std::uint32_t> f = frame_with(std::string(row.name), value);
      for (const patch& p : probe_design().patches) {
        if (p.option == row.name) continue;
        // A whole-level set-up (parallel-gs) has no fraction to keep: P2 reads it as truncate_to_8 (R9).
        if (p.option == "gouraud_fraction" && value == "per_pixel_level") continue;
        for (const auto& [x, y] : sample_pixels(p)) {
          const std::size_t i = static_cast<std::size_t>(y) * frame_width + x;
          ASSERT_EQ(rgb_of(f[i]), rgb_of(base[i])) << p.name << " under " << row.name << "=" << value;
        }
      }
    }
}

// Every Ct × Cf (8.7) pair, both Gouraud modes: floor and truncate agree on (Ct·Cf) >> 7 (non-negative).
TEST(ProbeDesign, TfxRoundingIsNotProbedBecauseNoInputTellsItApart) {
  std::uint64_t n = 0;
  for (const auto g : {gs::gouraud_fraction::keep_fraction, gs::gouraud_fraction::truncate_to_8})
    for (int ct = 0; ct < 256; ++ct)
      for (int cf = 0; cf < 0x8000; ++cf, ++n) {
        gs::model_options fl, tr;
        fl.gouraud = tr.gouraud = g;
        tr.tfx = gs::tfx_rounding::truncate;
        const auto t = fixed::u8::from_wrapped(ct);
        const auto c = gs::gouraud_channel::from_wrapped(cf);
        ASSERT_EQ(gs::modulate_channel(t, c, fl), gs::modulate_channel(t, c, tr)) << ct << " " << cf;
      }
  EXPECT_EQ(n, 2u * 256 * 32768);
}

// The 16-bit cells: a PSMCT16 pixel v shows as R = B = v & 0xff, G = v >> 8 (design.hpp).
constexpr std::uint32_t shown16(std::uint32_t v) { return (v & 0xFF) << 16 | (v >> 8) << 8 | (v & 0xFF); }
// A1B5G5R5 by hand.
constexpr std::uint32_t w16(unsigned r, unsigned g, unsigned b, unsigned a) { return r | g << 5 | b << 10 | a << 15; }

TEST(ProbeDesign, PatchValuesAreTheOnesWorkedOutByHand) {
  // option -> value -> patch -> 0xRRGGBB
  const std::map<std::string, std::map<std::string, std::map<std::string, std::uint32_t>>> expected = {
      // (0xff · Cf_8.7) >> 14 for Cf_8.7 in 144..172: 2; (0xff · 1) >> 7: 1.
      {"gouraud_fraction",
       {{"keep_fraction", {{"gouraud_fraction.ramp", 0x020202}}},
        {"truncate_to_8", {{"gouraud_fraction.ramp", 0x010101}}}}},
      // Step trunc(4·128/514) = 0 from the reference pixel: Cf 0; exact: trunc(d·512/514) for d = 501..506 is
      // 499..504, (0xff · 499..504) >> 14 = 7.
      // Texel 0x80: (0x80 · Cf) >> 14 = Cf's whole levels. .ramp: trunc(4·128/514) = 0 from the reference pixel: 0; the
      // exact plane trunc(d·512/514) for d = 501..506: 499..504, 3; rows scissored to the cell start at 520 with
      // trunc(512·500/514) = 498 and offsets trunc(0.996·m) <= 6: 498..504, 3; floor((499..504 + 1/2)/128) = 3.
      // .rows, k = 601..606 from the row start 0, g = 1024/686: exact 897.1..904.6 units, 7; 4 lanes: 150 or 151 steps
      // of
      // trunc(5.971) = 5 plus trunc(g·m) for m = k mod 4 (0..2): k = 601: 750 + 1 = 751, .., 606: 755 + 2 = 757: 5; 8
      // lanes: 75 steps of trunc(11.942) = 11 plus trunc(g·m), m = 1..6: 826..833: 6; plane_steps: k steps of
      // trunc(g) = 1 from 0: 601..606, 4; a whole level floor((897.1..904.6 + 1/2)/128) = 7.
      // .falling, x = 625..630: 128 − (x − 623)/16 = 127.875 .. 127.5625 units, below level 1 by less than a unit:
      // floored 127 -> 0; the distance from vertex 0 (−0.125 .. −0.4375) truncated to 0 -> 128 -> 1; +1/2 unit then
      // floored to a level -> 1; rows from the scissor's left 624, trunc(127.9375) = 127 and offsets trunc(−m/16) = 0
      // -> 0; plane_steps: the reference pixel's value 128 + trunc(−1/16) = 128 (truncated toward vertex 0, as
      // per_pixel) and step trunc(−1/16) = 0 -> 1. The rising ramps
      // (.ramp, .rows) rise from vertex 0, where floor and truncation toward it agree.
      {"gouraud_setup",
       {{"plane_steps",
         {{"gouraud_setup.ramp", 0x000000}, {"gouraud_setup.rows", 0x040404}, {"gouraud_setup.falling", 0x010101}}},
        {"per_pixel",
         {{"gouraud_setup.ramp", 0x030303}, {"gouraud_setup.rows", 0x070707}, {"gouraud_setup.falling", 0x010101}}},
        {"pcsx2_rows_4",
         {{"gouraud_setup.ramp", 0x030303}, {"gouraud_setup.rows", 0x050505}, {"gouraud_setup.falling", 0x000000}}},
        {"pcsx2_rows_8",
         {{"gouraud_setup.ramp", 0x030303}, {"gouraud_setup.rows", 0x060606}, {"gouraud_setup.falling", 0x000000}}},
        {"per_pixel_level",
         {{"gouraud_setup.ramp", 0x030303}, {"gouraud_setup.rows", 0x070707}, {"gouraud_setup.falling", 0x010101}}},
        {"per_pixel_floor",
         {{"gouraud_setup.ramp", 0x030303}, {"gouraud_setup.rows", 0x070707}, {"gouraud_setup.falling", 0x000000}}}}},
      // 0x81 + floor(-129 / 128) = 0x7f; 0x81 + trunc(-129 / 128) = 0x80.
      {"blend_shift",
       {{"floor", {{"blend_shift.negative", 0x7F7F7F}}}, {"truncate", {{"blend_shift.negative", 0x808080}}}}},
      {"dither_targets",
       {{"sixteen_bit_only", {{"dither_targets.ct32", 0x808080}}},
        {"all_formats", {{"dither_targets.ct32", 0x838383}}}}},
      // R 0x80, G 0x82, B 0x83 plus d, >> 3; A bit 1. e4: d = -4 | 0 | -1; e7: d = -1 | -3 | -4.
      {"dither_decode",
       {{"twos_complement",
         {{"dither_decode.e4", shown16(w16(15, 15, 15, 1))}, {"dither_decode.e7", shown16(w16(15, 16, 16, 1))}}},
        {"sign_magnitude",
         {{"dither_decode.e4", shown16(w16(16, 16, 16, 1))}, {"dither_decode.e7", shown16(w16(15, 15, 16, 1))}}},
        {"inverted_magnitude",
         {{"dither_decode.e4", shown16(w16(15, 16, 16, 1))}, {"dither_decode.e7", shown16(w16(15, 15, 15, 1))}}}}},
      // 0xc0 >> 3 = 0x18 per channel; the A bit of 0xa108 cleared (FB_ONLY) or kept.
      {"rgb_only_targets",
       {{"thirty_two_bit_only", {{"rgb_only_targets.ct16", shown16(w16(0x18, 0x18, 0x18, 0))}}},
        {"all_formats", {{"rgb_only_targets.ct16", shown16(w16(0x18, 0x18, 0x18, 1))}}}}},
      // Weights (1, 2): R block 00 ff 01 fe: lerp 0 + 255/16 -> 15, 1 + 253/16 -> 16, 15 + 1·2/16 -> 15;
      // sum (15·14·0 + 1·14·255 + 15·2·1 + 1·2·254) / 256 = 4108 / 256 -> 16; nearest: texel (4, 4) = 0.
      // G 00 07 09 0f: lerp 0, 9 + 6/16 -> 9, 0 + 9·2/16 -> 1; sum (98 + 270 + 30) / 256 -> 1; nearest 0.
      // B 10 31 52 73: lerp 16 + 33/16 -> 18, 82 + 33/16 -> 84, 18 + 66·2/16 -> 26; sum
      // (3360 + 686 + 2460 + 230) / 256 = 6736 / 256 -> 26; nearest 0x10.
      {"bilinear",
       {{"lerp16_4", {{"bilinear.w1_2", 0x0F011A}}},
        {"weighted_sum_4", {{"bilinear.w1_2", 0x10011A}}},
        {"nearest", {{"bilinear.w1_2", 0x000010}}}}},
      // Section 3.4 copies (design.cpp): A1 0x1040c0, B0 0x202020, D1 0x10c040, E0 0x303030.
      {"texture_buffer",
       {{"quarter_page",
         {{"texture_buffer.other_quarter", 0x1040C0},
          {"texture_buffer.same_quarter", 0x303030},
          {"texture_buffer.after_leaving_page", 0x1040C0}}},
        {"per_fragment",
         {{"texture_buffer.other_quarter", 0x1040C0},
          {"texture_buffer.same_quarter", 0x10C040},
          {"texture_buffer.after_leaving_page", 0x1040C0}}},
        {"page",
         {{"texture_buffer.other_quarter", 0x202020},
          {"texture_buffer.same_quarter", 0x303030},
          {"texture_buffer.after_leaving_page", 0x1040C0}}},
        {"draw_snapshot",
         {{"texture_buffer.other_quarter", 0x202020},
          {"texture_buffer.same_quarter", 0x303030},
          {"texture_buffer.after_leaving_page", 0x202020}}}}},
  };
  for (const auto& [option, values] : expected)
    for (const auto& [value, patches] : values) {
      const std::vector<std::uint32_t> f = frame_with(option, value);
      for (const auto& [name, rgb] : patches) {
        EXPECT_EQ(pixel(f, find(name)), rgb) << name << " under " << option << "=" << value;
        EXPECT_TRUE(uniform(f, find(name))) << name;
      }
    }
  // gouraud_setup.level is not uniform: at (619, 434) the exact plane is 0.25·511 = 127.75 units, level 0 truncated,
  // floor((127.75 + 0.5)/128) = 1 with parallel-gs's bias; at (620, 434) 128 units, level 1 for both.
  {
    const patch& lv = find("gouraud_setup.level");
    EXPECT_EQ(lv.x, 616);
    const auto exact = frame_with("gouraud_setup", "per_pixel"),
               biased = frame_with("gouraud_setup", "per_pixel_level");
    EXPECT_EQ(rgb_of(exact[434 * frame_width + 619]), 0x000000u);
    EXPECT_EQ(rgb_of(biased[434 * frame_width + 619]), 0x010101u);
    EXPECT_EQ(rgb_of(exact[434 * frame_width + 620]), 0x010101u);
    EXPECT_EQ(rgb_of(biased[434 * frame_width + 620]), 0x010101u);
  }
  // uv_convert.below_texel: U = 14 + 15·(x − 116)/128 sixteenths (V 8: row 0, texel 0 white, texel 1 0x80):
  // x = 132: 15 111/128 (texel 0 either way); x = 133: 15 127/128, floor 15 -> texel 0, +1/64 -> 16 1/128 ->
  // texel 1; x = 134: 16 14/128, texel 1 either way. Every row of the cell alike.
  {
    const patch& uv = find("uv_convert.below_texel");
    EXPECT_EQ(uv.x, 128);
    const auto fl = frame_with("uv_convert", "floor"), biased = frame_with("uv_convert", "floor_1_64");
    for (int y = uv.y + sample_inset; y < uv.y + cell - sample_inset; ++y) {
      const auto at = [y](const std::vector<std::uint32_t>& f, int x) {
        return rgb_of(f[static_cast<std::size_t>(y) * frame_width + static_cast<std::size_t>(x)]);
      };
      EXPECT_EQ(at(fl, 132), 0xFFFFFFu) << y;
      EXPECT_EQ(at(biased, 132), 0xFFFFFFu) << y;
      EXPECT_EQ(at(fl, 133), 0xFFFFFFu) << y;
      EXPECT_EQ(at(biased, 133), 0x808080u) << y;
      EXPECT_EQ(at(fl, 134), 0x808080u) << y;
      EXPECT_EQ(at(biased, 134), 0x808080u) << y;
    }
  }
  // Checks, default options: 0xc0 + 0x80 wraps to 0x40; HIGHLIGHT clamps to 0xff; 16-bit FBMSK.
  const std::vector<std::uint32_t> f = model_frame({});
  EXPECT_EQ(pixel(f, find("check.colclamp_wrap")), 0x404040u);
  EXPECT_EQ(pixel(f, find("check.highlight_clamp")), 0xFFFFFFu);
  EXPECT_EQ(pixel(f, find("check.fbmsk16_low_bits")), shown16(0xFFFF));
  EXPECT_EQ(pixel(f, find("check.fbmsk16_alpha")), shown16(0x7FFF));
}

// The section 3.4 cells sit in the quarters the design's argument names (gs_memory's PSMCT32 layout:
// quarter = block number / 8 within the page).
TEST(ProbeDesign, SectionThreeFourCellsAreInTheirQuarters) {
  const gs::mem::buffer frame{fixed::uint<14>{}, fixed::uint<6>::from_wrapped(frame_fbw), gs::mem::psm::PSMCT32};
  auto where = [&](int x, int y) {
    const auto at = gs::mem::locate(frame, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
    return std::pair<std::uint32_t, std::uint32_t>{at.page(), at.block() % 32 / 8};
  };
  using q = std::pair<std::uint32_t, std::uint32_t>;
  EXPECT_EQ(where(8, 72), q(20, 0));                             // a
  EXPECT_EQ(where(8, 88), q(20, 1));                             // b
  EXPECT_EQ(where(40, 64), q(20, 2));                            // d
  EXPECT_EQ(where(40, 72), q(20, 2));                            // e
  for (int x : {40, 48, 56}) EXPECT_EQ(where(x, 88), q(20, 3));  // c, f, h
  EXPECT_EQ(where(72, 72).first, 21u);                           // g
}

}  // namespace

namespace {

// docs/evidence.md's probe list names exactly the design's patches in its last column.
TEST(ProbeDesign, TheEvidenceProbeListNamesEveryPatch) {
  std::ifstream in(GSDOT3_EVIDENCE_MD);
  ASSERT_TRUE(in) << GSDOT3_EVIDENCE_MD;
  std::set<std::string> named;
  bool in_list = false;
  for (std::string l; std::getline(in, l);) {
    if (l.rfind("## ", 0) == 0) in_list = l == "## Hardware probe list";
    if (!in_list || l.rfind("| P", 0) != 0) continue;
    const std::string last = l.substr(l.rfind('|', l.size() - 2) + 1);
    for (std::size_t b = last.find('`'); b != std::string::npos; b = last.find('`', last.find('`', b + 1) + 1)) {
      const std::string code = last.substr(b + 1, last.find('`', b + 1) - b - 1);
      if (code.find('.') != std::string::npos) named.insert(code);
    }
  }
  std::set<std::string> patches;
  for (const patch& p : probe_design().patches) patches.insert(p.name);
  EXPECT_EQ(named, patches);
}

}  // namespace
