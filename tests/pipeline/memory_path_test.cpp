// The register-level memory path (frame buffers in the modelled GS local memory, the post filter as
// channel-fetch sprites through the PSMT8 swizzle, the PSMT8H pass, step 4's channel move) gives the
// value-level frame bit for bit: every method, the embedded scene and random scenes, both filters,
// specular on and off.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "pipeline/default_scene.hpp"
#include "pipeline/gs_inputs.hpp"
#include "pipeline/memory_picture.hpp"
#include "pipeline/normal_map.hpp"
#include "pipeline/render.hpp"
#include "method_param.hpp"

namespace gsdot3::pipeline {
namespace {

class MemoryPath : public ::testing::TestWithParam<method> {};

// Returns the number of pixels a triangle covers (so that a test can insist the scene is in view).
long expect_same(const scene& s, const prepared_scene& ps, method m, render_options o, const std::string& what) {
  o.memory_path = false;
  const frame a = render(s, ps, m, o);
  o.memory_path = true;
  const frame b = render(s, ps, m, o);
  EXPECT_EQ(a.colour.size(), b.colour.size());
  long differing = 0;
  for (std::size_t i = 0; i < a.colour.size() && i < b.colour.size(); ++i)
    if (a.colour[i] != b.colour[i] && differing++ < 3)
      ADD_FAILURE() << what << " pixel (" << i % static_cast<std::size_t>(a.width) << ", "
                    << i / static_cast<std::size_t>(a.width) << "): value level 0x" << std::hex << a.colour[i]
                    << ", memory path 0x" << b.colour[i];
  EXPECT_EQ(differing, 0) << what;
  EXPECT_EQ(a.dot, b.dot) << what;
  EXPECT_EQ(a.visible_triangle, b.visible_triangle) << what;
  return std::count_if(a.visible_triangle.begin(), a.visible_triangle.end(), [](std::int32_t t) { return t >= 0; });
}

TEST_P(MemoryPath, EqualsTheValueLevelFrameOnTheEmbeddedScene) {
  static const scene s = default_scene();
  const prepared_scene ps = prepare(s);
  for (bool bilinear : {false, true})
    for (bool specular : {false, true}) {
      render_options o;
      o.bilinear = bilinear;
      o.specular = specular;
      o.specular_power = specular ? 8.0 : 1.0;
      expect_same(s, ps, GetParam(), o,
                  std::string("bilinear ") + (bilinear ? "on" : "off") + ", specular " + (specular ? "on" : "off"));
    }
}

// Section 3.8's 4-bit map: stored as PSMT4 (the nibbles through the PSMT4 swizzle, its palettes loaded
// by TEX0 with PSM = PSMT4: 16 entries at CSA 0), the memory path gives the value path's frame, and the
// frame of the same indices stored as PSMT8 (an 8-bit map of 16 entries, the storage the tests above
// check); and not the 8-bit map's frame (the 16 normals are drawn).
TEST_P(MemoryPath, AFourBitMapEqualsTheValueLevelFrameAndItsPsmt8Storage) {
  static const scene eight = default_scene();
  scene four = eight;
  four.normals = with_index_bits(eight.normals, 4);
  scene as_psmt8 = four;
  as_psmt8.normals.bits = 8;
  const method m = GetParam();
  ASSERT_EQ(place_inputs(make_inputs(four, m, {}), buffer_layout_for(four.width, four.height).first_texture_block())
                .nm_at[0]
                .PSM,
            gs::mem::psm::PSMT4);
  const prepared_scene ps = prepare(four);
  for (bool bilinear : {false, true}) {
    render_options o;
    o.bilinear = bilinear;
    const std::string what = std::string("4-bit map, bilinear ") + (bilinear ? "on" : "off");
    EXPECT_GT(expect_same(four, ps, m, o, what), 1000);
    o.memory_path = true;
    const frame f = render(four, ps, m, o);
    EXPECT_EQ(f.colour, render(as_psmt8, ps, m, o).colour) << what << ": PSMT4 vs PSMT8 storage";
    if (m != method::gouraud) {
      EXPECT_NE(f.colour, render(eight, ps, m, o).colour) << what << ": the 8-bit map's frame";
    }
  }
}

// Section 3.6's "three 8 bit normal maps" (a 24-bit map): four-pass places three PSMT8 component maps
// and the memory path gives the value path's frame. Against an independent route: when every texel's
// normal is exactly its palette entry (unquantised = palette[index]), the component maps (the byte
// 128 + nearest(127·n_axis) per texel, read through the ramp CLUT) must give the frame of the reordered
// palettes (the same byte in the CLUT entry, read through the index map); with the real unquantised
// normals they must not. The other methods read the 8-bit map: their frames do not change.
TEST_P(MemoryPath, ATwentyFourBitMapIsThreeComponentMapsForFourPass) {
  static const scene eight = default_scene();
  scene wide = eight;
  wide.normals = with_index_bits(eight.normals, 24);
  scene exact = wide;
  for (std::size_t i = 0; i < exact.normals.index.size(); ++i)
    exact.normals.unquantised[i] = exact.normals.palette[exact.normals.index[i]];
  const method m = GetParam();
  const gs_inputs placed =
      place_inputs(make_inputs(wide, m, {}), buffer_layout_for(wide.width, wide.height).first_texture_block());
  ASSERT_EQ(normal_map_count(placed), m == method::four_pass ? 3u : 1u);
  if (m == method::four_pass) {
    EXPECT_NE(placed.nm_at[1].BP.value(), placed.nm_at[0].BP.value());
    EXPECT_NE(placed.nm_at[2].BP.value(), placed.nm_at[1].BP.value());
  }
  const prepared_scene ps = prepare(wide);
  for (bool bilinear : {false, true}) {
    render_options o;
    o.bilinear = bilinear;
    const std::string what = std::string("24-bit map, bilinear ") + (bilinear ? "on" : "off");
    EXPECT_GT(expect_same(wide, ps, m, o, what), 1000);
    o.memory_path = true;
    const frame f = render(wide, ps, m, o), palettised = render(eight, ps, m, o);
    EXPECT_EQ(render(exact, ps, m, o).colour, palettised.colour) << what << ": exact palette normals";
    if (m == method::four_pass) {
      EXPECT_NE(f.colour, palettised.colour) << what << ": the 8-bit map's frame";
    } else {
      EXPECT_EQ(f.colour, palettised.colour) << what << ": the 8-bit map is what this method reads";
    }
  }
}

TEST_P(MemoryPath, EqualsTheValueLevelFrameOnRandomScenes) {
  std::mt19937 rng(41 + static_cast<unsigned>(GetParam()));
  std::uniform_real_distribution<float> pos(-3.0f, 3.0f), yaw(0.0f, 360.0f);
  std::uniform_int_distribution<int> byte(0, 255), scale(60, 127), threads(1, 4), size(40, 200);
  static const scene base = [] {
    scene s = default_scene(64);
    return s;
  }();
  auto colour = [&] {
    return std::array<std::uint8_t, 3>{static_cast<std::uint8_t>(byte(rng)), static_cast<std::uint8_t>(byte(rng)),
                                       static_cast<std::uint8_t>(byte(rng))};
  };
  for (int trial = 0; trial < 8; ++trial) {
    scene s = base;
    s.width = size(rng);
    s.height = size(rng);
    // Even trials make the second light directional (section 3: the same tolight at every vertex).
    const light_kind second = trial % 2 == 0 ? light_kind::directional : light_kind::point;
    s.lights = {{{pos(rng), pos(rng), pos(rng)}, colour()}, {{pos(rng), pos(rng), pos(rng)}, colour(), second}};
    s.view.eye = glm::vec3(pos(rng), pos(rng), 3.0f + std::fabs(pos(rng)));
    const prepared_scene ps = prepare(s, yaw(rng), trial % 3 == 2);
    render_options o;
    o.s = scale(rng);
    o.bilinear = trial % 2 == 1;
    o.specular = trial % 4 >= 2;
    o.threads = threads(rng);
    EXPECT_GT(expect_same(s, ps, GetParam(), o, "trial " + std::to_string(trial)), 200)
        << "trial " << trial << ": the head should be in view";
    // Section 3.4's z-trick (the DPB drawn in PSMZ32, cleared by the ILP pass's Z writes) on the
    // memory path gives the value-level frame too (every texture_buffer model: each Z write lands on
    // the word just read).
    render_options z = o;
    z.memory_path = true;
    z.dpb_clear = dpb_clear_mode::z_trick;
    z.model.tex_buffer = trial % 2 == 0 ? gs::texture_buffer::per_fragment : gs::texture_buffer::quarter_page;
    o.memory_path = false;
    const frame a = render(s, ps, GetParam(), o), b = render(s, ps, GetParam(), z);
    EXPECT_TRUE(a.colour == b.colour && a.dot == b.dot) << "trial " << trial << ": z-trick on the memory path";
  }
}

// Every buffer the trace records, over the whole frame after each pass (the frame program's clears
// included, which outside the sprite area no later pass overwrites), but step 3's, is the value path's: the memory
// path's clears set whole pages in memory order and the rest pixel by pixel, at a size with part
// pages (97×61) and at whole pages (128×64).
TEST_P(MemoryPath, EveryTracedBufferEqualsTheValueLevelOne) {
  for (const auto& [w, h] : {std::array<int, 2>{97, 61}, std::array<int, 2>{128, 64}}) {
    scene s = default_scene();
    s.width = w, s.height = h;
    const prepared_scene ps = prepare(s);
    std::vector<pass_record> value, memory;
    render_options o;
    o.trace = &value;
    render(s, ps, GetParam(), o);
    o.trace = &memory, o.memory_path = true;
    render(s, ps, GetParam(), o);
    ASSERT_EQ(value.size(), memory.size());
    for (std::size_t k = 0; k < value.size(); ++k) {
      EXPECT_EQ(value[k].label, memory[k].label);
      // Step 3's diffuse layer: the value path draws it into an array of its own, the memory path into
      // the DPB, which outside the sprite area still holds the DPB's clear (memory_steps.hpp).
      if (value[k].target == "diffuse") continue;
      EXPECT_EQ(value[k].word, memory[k].word)
          << w << "x" << h << ": " << value[k].label << " (" << value[k].target << ")";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, MemoryPath, ::testing::ValuesIn(gs_methods), method_param_name);

}  // namespace
}  // namespace gsdot3::pipeline

namespace gsdot3::pipeline {
namespace {

// Section 3.4 claim (e): the multi-light frame with the Z-buffer clear equals the frame with explicit
// clears. z-trick: under every texture_buffer model (each fragment's Z write lands on the word it has
// just read). z-trick-psmz32: only where the texture buffer holds the page (page, draw_snapshot);
// under quarter_page and per_fragment the Z writes clear texels before they are read and the frame
// differs (the per-page count is proofs' dpb-clear.read-before-write).
TEST_P(MemoryPath, ZBufferClearOfTheDpbEqualsExplicitClears) {
  static const scene s = default_scene();
  ASSERT_GE(s.lights.size(), 2u);
  const prepared_scene ps = prepare(s);
  const frame expl = render(s, ps, GetParam(), render_options{});
  for (const auto tb : {gs::texture_buffer::quarter_page, gs::texture_buffer::per_fragment, gs::texture_buffer::page,
                        gs::texture_buffer::draw_snapshot})
    for (const auto mode : {dpb_clear_mode::z_trick, dpb_clear_mode::z_trick_psmz32}) {
      render_options o;
      o.memory_path = true;
      o.dpb_clear = mode;
      o.model.tex_buffer = tb;
      const frame f = render(s, ps, GetParam(), o);
      const bool expect_equal =
          mode == dpb_clear_mode::z_trick || tb == gs::texture_buffer::page || tb == gs::texture_buffer::draw_snapshot;
      EXPECT_EQ(f.colour == expl.colour && f.dot == expl.dot, expect_equal)
          << name(mode) << ", texture_buffer " << gs::option_value(o.model, "texture_buffer");
    }
}

}  // namespace
}  // namespace gsdot3::pipeline

namespace gsdot3::pipeline {
namespace {

// The report's DPB pictures: the display is the PSMCT32 words' RGB; the PSMT8 view follows the
// channel-fetch formula of ../shared/spec/gs-memory-facts.md ( "Reading a PSMCT32 buffer as PSMT8"):
// texel (u, v) of a page is byte c of pixel (x, y) with x = ((u & ~15) >> 1) | (u & 7), x ^= 4 when
// bit 2 of v differs from bit 1, y = ((v & ~3) >> 1) | (v & 1), c = v & 2 ? (u & 8 ? A : G) : (u & 8 ? B : R).
TEST(MemoryPicture, DpbPicturesFollowTheChannelFetchFormula) {
  const int w = 128, h = 64;  // 2 × 2 pages
  std::vector<pass_record> trace(2);
  trace[0] = {"2.3 x", 0, "DPB", std::vector<std::uint32_t>(w * h), {}, {}, {}};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      trace[0].word[static_cast<std::size_t>(y * w + x)] = static_cast<std::uint32_t>(x) |
                                                           static_cast<std::uint32_t>(y) << 8 | 0x40u << 16 |
                                                           static_cast<std::uint32_t>(x ^ y) << 24;
  trace[1] = {"2.4 R += G", 0, "DPB", {}, {}, {}, {}};
  const dpb_pictures p = post_filter_dpb_pictures(trace, w, h, false);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * w + x) * 3;
      ASSERT_EQ(p.display.data[i], x);
      ASSERT_EQ(p.display.data[i + 1], y);
      ASSERT_EQ(p.display.data[i + 2], 0x40);
    }
  ASSERT_EQ(p.as_psmt8.width, 2 * w);
  for (int v = 0; v < 2 * h; ++v)
    for (int u = 0; u < 2 * w; ++u) {
      const int pu = u % 128, pv = v % 64;  // within the PSMT8 page; the page is PSMCT32 page (u / 128, v / 64)
      int x = ((pu & ~15) >> 1) | (pu & 7);
      if (((pv >> 2) & 1) != ((pv >> 1) & 1)) x ^= 4;
      const int y = ((pv & ~3) >> 1) | (pv & 1);
      const std::uint32_t word = trace[0].word[static_cast<std::size_t>((v / 64 * 32 + y) * w + u / 128 * 64 + x)];
      const int c = (pv & 2) ? ((pu & 8) ? 3 : 1) : ((pu & 8) ? 2 : 0);
      ASSERT_EQ(p.as_psmt8.data[static_cast<std::size_t>(v * 2 * w + u)], (word >> (8 * c)) & 0xFF)
          << "texel (" << u << ", " << v << ")";
    }
  EXPECT_THROW(post_filter_dpb_pictures({trace[1]}, w, h, false),
               std::logic_error);  // a trace without a DPB pass: a bug (e4bb708)
}

// The memory path's buffers (three 32-bit colour buffers and the Z buffer, each FBW·rows pages)
// must fit in the 512 pages of the 4 MiB: 512×448 does (4 × 112), 640×512 does not (4 × 160).
TEST(MemoryPath, FourBuffersMustFitTheFourMebibytes) {
  scene s = default_scene(64);
  const prepared_scene ok = prepare(s);
  render_options o;
  o.memory_path = true;
  EXPECT_NO_THROW(render(s, ok, method::two_pass, o));
  s.width = 640;
  s.height = 512;
  EXPECT_THROW(render(s, prepare(s), method::two_pass, o), std::invalid_argument);
}

}  // namespace
}  // namespace gsdot3::pipeline
