// gs_arith_hardware — the PS2 recordings reproduced through the pixel pipeline, set up exactly as they
// were made (tests/data/hw/README.md). The recordings travel with the project as pixel vectors in
// tests/data/hw/ (GSDOT3_HW_DATA_DIR): blend: frame PSMCT32 cleared to 0, a sprite with vertex colour
// dst drawn without blending, then a sprite with vertex colour src and ALPHA_1 = (A, B, C, D, FIX)
// blending, COLCLAMP = 1, the pixel at (0, 0) read back; simpletexture: texel 0xFF808080, TFX =
// MODULATE, TCC = RGB, vertex 0x80808080. When ../shared/hw (GSDOT3_HW_DIR) is beside the clone, the
// re-encoding is compared with the original .expected files; that comparison alone skips without it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "gs_arith/pixel_pipeline.hpp"
#include "gs_arith/registers.hpp"

namespace {

const std::filesystem::path shared_hw_dir = GSDOT3_HW_DIR;  // ../shared/hw, the original recordings
const std::filesystem::path data_dir = GSDOT3_HW_DATA_DIR;  // tests/data/hw, their re-encoding

struct blend_record {
  std::string mode;  // "ABCD" digits
  std::uint32_t src, dst, result;
  unsigned fix;
  friend bool operator==(const blend_record&, const blend_record&) = default;
};

// Header lines "ABCD: ..." (digits 0..2) and rows "  src: SSSSSSSS, dst: DDDDDDDD, fix: FF => RRRRRRRR".
std::vector<blend_record> read_blend_records(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<blend_record> out;
  std::string line, mode;
  while (std::getline(in, line)) {
    unsigned src = 0, dst = 0, fix = 0, result = 0;
    if (line.size() > 5 && line[4] == ':' &&
        std::all_of(line.begin(), line.begin() + 4, [](char c) { return c >= '0' && c <= '2'; })) {
      mode = line.substr(0, 4);
    } else if (std::sscanf(line.c_str(), " src: %8x, dst: %8x, fix: %2x => %8x", &src, &dst, &fix, &result) == 4) {
      out.push_back({mode, src, dst, result, fix});
    }
  }
  return out;
}

// One case line of a pixel vector file: PRIM TEX0_1 ALPHA_1 TEST_1 FRAME_1 COLCLAMP PABE FBA_1 DTHE DIMX
// CfR CfG CfB CfA texel dst X Y => out (docs/vectors.md), all hex.
struct pixel_case {
  unsigned long long prim, tex0, alpha, test, frame, dimx;
  unsigned colclamp, pabe, fba, dthe, cf[4], texel, dst, x, y, out;
};
std::vector<pixel_case> read_pixel_cases(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<pixel_case> out;
  std::string line;
  bool header = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      header = line.rfind("gsdot3-vectors 1 unit=pixel", 0) == 0;
      continue;
    }
    pixel_case c{};
    const int n = std::sscanf(line.c_str(), "%llx %llx %llx %llx %llx %x %x %x %x %llx %x %x %x %x %x %x %x %x => %x",
                              &c.prim, &c.tex0, &c.alpha, &c.test, &c.frame, &c.colclamp, &c.pabe, &c.fba, &c.dthe,
                              &c.dimx, &c.cf[0], &c.cf[1], &c.cf[2], &c.cf[3], &c.texel, &c.dst, &c.x, &c.y, &c.out);
    if (n == 19) out.push_back(c);
  }
  return out;
}

// A blend case back as (mode, src, dst, fix, result): ALPHA_1 digits and FIX, src from the flat 8.7 colour.
blend_record blend_of(const pixel_case& c) {
  blend_record r;
  for (int i = 0; i < 4; ++i) r.mode += static_cast<char>('0' + ((c.alpha >> (2 * i)) & 3));
  r.fix = static_cast<unsigned>((c.alpha >> 32) & 0xFF);
  r.src = 0;
  for (int i = 0; i < 4; ++i) r.src |= (c.cf[i] >> 7) << (8 * i);
  r.dst = c.dst;
  r.result = c.out;
  return r;
}

std::vector<blend_record> recorded_blends() {
  std::vector<blend_record> out;
  for (const auto& c : read_pixel_cases(data_dir / "ps2autotests-gs-blend.vectors")) out.push_back(blend_of(c));
  return out;
}

// ALPHA_1 register value from the header digits and FIX.
std::uint64_t alpha_value(const std::string& mode, unsigned fix) {
  const auto d = [&](int i) { return static_cast<std::uint64_t>(mode[static_cast<std::size_t>(i)] - '0'); };
  return d(0) | d(1) << 2 | d(2) << 4 | d(3) << 6 | std::uint64_t{fix} << 32;
}

// One sprite pixel: flat vertex colour, no texture (PRIM = SPRITE, TME = 0).
std::uint32_t draw(const gs::gs_registers& regs, std::uint32_t vertex, std::uint32_t old, const gs::model_options& o) {
  const gs::pixel_input in{gs::fragment_colour::flat(gs::rgba8::from_u32(vertex)), gs::rgba8{}, old, 0, 0};
  return gs::pixel_pipeline(regs, in, o).out;
}

std::uint32_t replay(const blend_record& r, const gs::model_options& o) {
  gs::gs_registers regs;              // FRAME_1 = PSMCT32, FBMSK 0; COLCLAMP = 1; no dither, PABE, FBA
  gs::set_register(regs, "PRIM", 6);  // SPRITE, no blending
  const std::uint32_t frame = draw(regs, r.dst, 0x00000000u, o);
  gs::set_register(regs, "PRIM", 6 | 1 << 6);  // SPRITE, ABE = 1
  gs::set_register(regs, "ALPHA_1", alpha_value(r.mode, r.fix));
  return draw(regs, r.src, frame, o);
}

int mismatches(const std::vector<blend_record>& records, const gs::model_options& o, bool print) {
  int bad = 0;
  for (const auto& r : records) {
    const std::uint32_t got = replay(r, o);
    if (got != r.result) {
      ++bad;
      if (print)
        std::printf("  mode %s src %08x dst %08x fix %02x => hw %08x model %08x\n", r.mode.c_str(), r.src, r.dst, r.fix,
                    r.result, got);
    }
  }
  return bad;
}

// An independent reference for the recorded blends, without the model: per channel
// clamp(((a − b)·c) / 128 + d) with the quotient rounded as `variant` says (floor, C's truncating
// division, or floor with C clamped to 128). Returns how many records it gets wrong.
enum class variant { floor, truncate, clamp_c };
int reference_mismatches(const std::vector<blend_record>& records, variant v) {
  int n = 0;
  for (const auto& r : records) {
    auto byte = [](std::uint32_t w, int i) { return static_cast<int>((w >> (8 * i)) & 0xFF); };
    std::uint32_t out = r.src & 0xFF000000u;  // output alpha is As
    for (int ch = 0; ch < 3; ++ch) {
      const int pick[3] = {byte(r.src, ch), byte(r.dst, ch), 0};
      const int alpha[3] = {byte(r.src, 3), byte(r.dst, 3), static_cast<int>(r.fix)};
      const int a = pick[r.mode[0] - '0'], b = pick[r.mode[1] - '0'], d = pick[r.mode[3] - '0'];
      int c = alpha[r.mode[2] - '0'];
      if (v == variant::clamp_c && c > 128) c = 128;
      const int p = (a - b) * c;
      const int q = v == variant::truncate ? p / 128 : (p >= 0 ? p / 128 : -((-p + 127) / 128));
      const int x = q + d;
      out |= static_cast<std::uint32_t>(x < 0 ? 0 : x > 255 ? 255 : x) << (8 * ch);
    }
    if (out != r.result) ++n;
  }
  return n;
}

TEST(GsArithHardware, Blend486) {
  const auto records = recorded_blends();
  ASSERT_EQ(records.size(), 486u) << "unexpected re-encoding in " << data_dir;

  gs::model_options floor_opts;
  const int floor_bad = mismatches(records, floor_opts, true);
  gs::model_options trunc_opts;
  trunc_opts.shift = gs::blend_shift::truncate;
  const int trunc_bad = mismatches(records, trunc_opts, false);
  std::printf("hardware blend matches: blend_shift=floor %d/486, blend_shift=truncate %d/486\n", 486 - floor_bad,
              486 - trunc_bad);
  std::printf("independent reference mismatches: floor %d, truncate %d, C clamped to 128 %d\n",
              reference_mismatches(records, variant::floor), reference_mismatches(records, variant::truncate),
              reference_mismatches(records, variant::clamp_c));
  EXPECT_EQ(floor_bad, 0);
  EXPECT_EQ(reference_mismatches(records, variant::floor), 0);
  EXPECT_EQ(trunc_bad, reference_mismatches(records, variant::truncate));
  EXPECT_GT(trunc_bad, 0) << "the recordings must distinguish the two shifts";
}

// Each re-encoded case, replayed exactly as its fields say (registers decoded strictly), gives the
// recorded word: the file is a valid vector file of the recordings, whatever the replay above assumed.
TEST(GsArithHardware, ReencodedCasesReplayAsPixelVectors) {
  for (const char* name : {"ps2autotests-gs-blend.vectors", "ps2autotests-gs-simpletexture.vectors"}) {
    const auto cases = read_pixel_cases(data_dir / name);
    ASSERT_FALSE(cases.empty()) << name;
    for (const auto& c : cases) {
      gs::gs_registers regs;
      gs::set_register(regs, "PRIM", c.prim);
      gs::set_register(regs, "TEX0_1", c.tex0);
      gs::set_register(regs, "ALPHA_1", c.alpha);
      gs::set_register(regs, "TEST_1", c.test);
      gs::set_register(regs, "FRAME_1", c.frame);
      gs::set_register(regs, "COLCLAMP", c.colclamp);
      gs::set_register(regs, "PABE", c.pabe);
      gs::set_register(regs, "FBA_1", c.fba);
      gs::set_register(regs, "DTHE", c.dthe);
      gs::set_register(regs, "DIMX", c.dimx);
      auto ch = [](unsigned v) { return gs::gouraud_channel::from_wrapped(v); };
      const gs::pixel_input px{
          {ch(c.cf[0]), ch(c.cf[1]), ch(c.cf[2]), ch(c.cf[3])}, gs::rgba8::from_u32(c.texel), c.dst, c.x, c.y};
      EXPECT_EQ(gs::pixel_pipeline(regs, px, gs::model_options{}).out, c.out) << name;
    }
  }
}

TEST(GsArithHardware, SimpleTexture) {
  const auto cases = read_pixel_cases(data_dir / "ps2autotests-gs-simpletexture.vectors");
  ASSERT_EQ(cases.size(), 1u);
  const std::uint32_t recorded = cases.front().out;
  for (auto tfx_round : {gs::tfx_rounding::floor, gs::tfx_rounding::truncate}) {
    for (auto frac : {gs::gouraud_fraction::keep_fraction, gs::gouraud_fraction::truncate_to_8}) {
      gs::model_options o;
      o.tfx = tfx_round;
      o.gouraud = frac;
      gs::gs_registers regs;
      gs::set_register(regs, "PRIM", 6 | 1 << 4);  // SPRITE, TME = 1
      gs::set_register(regs, "TEX0_1", 0);         // PSMCT32, TCC = RGB, TFX = MODULATE
      const gs::pixel_input px{gs::fragment_colour::flat(gs::rgba8::from_u32(0x80808080u)),
                               gs::rgba8::from_u32(0xFF808080u), 0u, 0, 0};
      EXPECT_EQ(gs::pixel_pipeline(regs, px, o).out, recorded)
          << gs::option_value(o, "tfx_rounding") << " " << gs::option_value(o, "gouraud_fraction");
    }
  }
}

// The re-encoding is faithful: the same samples in the same order as the console's .expected output.
TEST(GsArithHardware, ReencodingMatchesSharedRecordings) {
  const auto blend = shared_hw_dir / "ps2autotests-gs-blend.expected";
  const auto texture = shared_hw_dir / "ps2autotests-gs-simpletexture.expected";
  if (!std::filesystem::exists(blend) || !std::filesystem::exists(texture))
    GTEST_SKIP() << "original recordings not found in " << shared_hw_dir
                 << ": only this cross-check of tests/data/hw against ../shared/hw is skipped";
  const auto original = read_blend_records(blend);
  ASSERT_EQ(original.size(), 486u);
  EXPECT_TRUE(original == recorded_blends());
  std::ifstream in(texture);
  std::string line;
  unsigned colour = 0;
  bool found = false;
  while (std::getline(in, line)) found = found || std::sscanf(line.c_str(), "color: %8x", &colour) == 1;
  ASSERT_TRUE(found) << "no 'color:' line in " << texture;
  EXPECT_EQ(read_pixel_cases(data_dir / "ps2autotests-gs-simpletexture.vectors").at(0).out, colour);
}

}  // namespace
