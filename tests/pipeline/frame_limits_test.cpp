// frame_limits.hpp: the one check of what the GS methods draw. Each limit is tested against a rule
// written another way (the 4 MiB as bytes of whole pages, not pages), and the renderer and the packet
// stream must refuse exactly what broken_limit names, with its words: one check, not copies of it.
#include <gtest/gtest.h>

#include <optional>
#include <stdexcept>
#include <string>

#include "pipeline/default_scene.hpp"
#include "pipeline/frame_limits.hpp"
#include "pipeline/frame_packets.hpp"
#include "pipeline/lod.hpp"
#include "pipeline/render.hpp"

namespace gsdot3::pipeline {
namespace {

// Four PSMCT32 buffers of whole 64×32-pixel pages (FBW = ceil(width / 64)), 4 bytes a pixel, in 4 MiB.
bool four_buffers_fit(long w, long h) {
  const long padded_w = (w + 63) / 64 * 64, padded_h = (h + 31) / 32 * 32;
  return 4 * padded_w * padded_h * 4 <= 4L * 1024 * 1024;
}

TEST(FrameLimits, TheBuffersFitExactlyWhereFourPaddedBuffersFillAtMost4MiB) {
  scene s;
  render_options memory;
  memory.memory_path = true;
  long refused = 0, n = 0;
  for (int w = 16; w <= 2048; w += 7)
    for (int h = 16; h <= 2048; h += 5, ++n) {
      s.width = w, s.height = h;
      const bool fits = four_buffers_fit(w, h);
      refused += !fits;
      ASSERT_EQ(!broken_limit(s, method::two_pass, memory, frame_use::render), fits) << w << "x" << h;
      ASSERT_FALSE(broken_limit(s, method::two_pass, render_options{}, frame_use::render)) << w << "x" << h;
    }
  EXPECT_GT(refused, 0);
  EXPECT_LT(refused, n);
  s.width = 512;
  for (const auto& [h, fits] : {std::pair{448, true}, {512, true}, {513, false}}) {
    s.height = h;
    EXPECT_EQ(!broken_limit(s, method::four_pass, memory, frame_use::render), fits) << h;
  }
}

TEST(FrameLimits, EachLimitNamesItsOption) {
  const scene base = default_scene(16);
  auto why = [](const scene& s, method m, const render_options& o, frame_use use) {
    const std::optional<std::string> w = broken_limit(s, m, o, use);
    return w ? *w : std::string("(accepted)");
  };
  auto starts = [](const std::string& text, const std::string& head) { return text.rfind(head, 0) == 0; };
  EXPECT_FALSE(broken_limit(base, method::four_pass, render_options{}, frame_use::packets));

  scene wide = base;
  wide.width = 1024, wide.height = 128;  // fits the 4 MiB (4 × 16 × 4 pages), not a sprite's 10.4 UV
  EXPECT_TRUE(starts(why(wide, method::two_pass, {}, frame_use::packets), "frame packets: 1024x128:"));
  EXPECT_EQ(why(wide, method::two_pass, {}, frame_use::render), "(accepted)");

  render_options z;
  z.dpb_clear = dpb_clear_mode::z_trick;
  EXPECT_EQ(why(base, method::two_pass, z, frame_use::packets), "(accepted)");
  EXPECT_EQ(why(base, method::two_pass, z, frame_use::render), "(accepted)");
  scene tall = base;
  tall.height = 1024;
  EXPECT_TRUE(starts(why(tall, method::two_pass, z, frame_use::render), "memory path: four 512x1024"));

  render_options one;
  one.buffers = draw_buffers::one;
  scene four = base;
  four.lights.resize(4, base.lights.front());
  EXPECT_TRUE(starts(why(four, method::gouraud, one, frame_use::render), "--draw-buffers 1: 4 lights"));
  four.lights.resize(3);
  EXPECT_EQ(why(four, method::gouraud, one, frame_use::render), "(accepted)");
  one.dpb_clear = dpb_clear_mode::z_trick_psmz32;
  EXPECT_TRUE(starts(why(four, method::gouraud, one, frame_use::render), "--draw-buffers 1 needs --dpb-clear"));

  scene spot = base;
  spot.lights.front().kind = light_kind::spot;
  EXPECT_EQ(why(spot, method::four_pass, {}, frame_use::render), "(accepted)");
  spot.lights = split_for_lod(spot.lights, 0.5);
  EXPECT_TRUE(starts(why(spot, method::four_pass, {}, frame_use::render), "--light spot:... and --lod-fade"));

  render_options after_first;
  after_first.spot_after_first_pass = true;
  EXPECT_EQ(why(base, method::four_pass, after_first, frame_use::packets), "(accepted)");
  for (const method m : {method::two_pass, method::three_pass, method::baseline, method::gouraud})
    EXPECT_TRUE(starts(why(base, m, after_first, frame_use::render), "--spot-after-first-pass: four-pass's"))
        << name(m);
}

// The renderer and the packet stream refuse with broken_limit's own line, before drawing anything.
TEST(FrameLimits, TheRendererAndThePacketStreamRefuseWithTheCheck) {
  scene s = default_scene(16);
  s.width = 640;  // FBW 10: 4 × 10 × 14 = 560 pages
  render_options o;
  o.memory_path = true;
  const std::string expected = *broken_limit(s, method::two_pass, o, frame_use::render);
  const prepared_scene ps = prepare(s);
  try {
    (void)render(s, ps, method::two_pass, o);
    ADD_FAILURE() << "render drew a frame whose buffers do not fit";
  } catch (const std::invalid_argument& e) { EXPECT_EQ(e.what(), expected); }
  try {
    (void)build_frame_packets(s, ps, method::two_pass, render_options{});
    ADD_FAILURE() << "the packet stream wrote a frame whose buffers do not fit";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(e.what(), *broken_limit(s, method::two_pass, render_options{}, frame_use::packets));
  }
  s.width = 512;
  o.spot_after_first_pass = true;
  EXPECT_THROW((void)render(s, prepare(s), method::baseline, o), std::invalid_argument);
}

}  // namespace
}  // namespace gsdot3::pipeline
