// The honest end-to-end test: the probe dump replayed through gs_packets' interpreter (its own
// rasteriser and register decoding, i15a's drawing) under each option value, the displayed frame taken
// from the dump's PMODE / DISPFB1 / DISPLAY1, then decoded. Every probed option value is recovered
// exactly: the interpreter keeps one texture buffer for a run of primitives with one state until
// TEXFLUSH (gs_packets/interpreter.cpp), as the probe's model and the section 3.4 proof
// (proofs/dpb_clear.cpp) do.
#include <gtest/gtest.h>

#include "gs_packets/display.hpp"
#include "gs_packets/interpreter.hpp"
#include "probe/decode.hpp"
#include "probe/design.hpp"
#include "probe/frame.hpp"
#include "probe/packets.hpp"

namespace {

using namespace gsdot3::probe;

rgb_frame replayed(const gs::model_options& o) {
  const gs::dump::gs_dump d = gs::dump::read_dump(gs::dump::write_dump(probe_dump()));
  gs::mem::local_memory m;
  gs::packets::interpreter it(m, {o, false});
  it.load_state(d.state, d.state_version);
  it.replay(d);
  EXPECT_TRUE(it.unmodelled_features().empty());
  const gs::packets::display_state shown = gs::packets::decode_display(it.privileged());
  EXPECT_EQ(shown.unmodelled, "");
  EXPECT_TRUE(shown.frame.has_value());
  if (!shown.frame) return {};
  const auto& f = *shown.frame;
  EXPECT_EQ(f.width, static_cast<std::uint32_t>(frame_width));
  EXPECT_EQ(f.height, static_cast<std::uint32_t>(frame_height));
  rgb_frame out(static_cast<std::size_t>(frame_width) * frame_height);
  for (int y = 0; y < frame_height; ++y)
    for (int x = 0; x < frame_width; ++x)
      out[static_cast<std::size_t>(y) * frame_width + x] =
          rgb_of(m.read_pixel(f.buffer, f.x + static_cast<std::uint32_t>(x), f.y + static_cast<std::uint32_t>(y)));
  return out;
}

TEST(ProbeReplay, TheInterpretersFrameDecodesToEachOptionValue) {
  for (const auto& row : gs::option_catalogue())
    for (auto value : row.values) {
      gs::model_options o;
      gs::set_option(o, row.name, value);
      const std::vector<verdict> v = decode(replayed(o));
      for (const verdict& x : v) {
        if (!x.not_probed.empty()) continue;
        std::string want = x.is_check ? "model" : x.name == row.name ? std::string(value) : "";
        if (want.empty())
          for (const auto& r : gs::option_catalogue())
            if (r.name == x.name) want = std::string(r.values[0]);
        // A whole-level set-up (parallel-gs) has no fraction to keep: P2 shows truncate_to_8 (evidence.md R9).
        if (x.name == "gouraud_fraction" && value == "per_pixel_level") want = "truncate_to_8";
        EXPECT_EQ(x.matches, std::vector<std::string>{want}) << x.name << " for " << row.name << "=" << value << "\n"
                                                             << format_verdicts(v);
      }
    }
}

// The interpreter's frame and the probe's model frame are the same pixels everywhere (not only on
// the sampled ones), under every texture_buffer value.
TEST(ProbeReplay, TheInterpretersFrameEqualsTheModels) {
  for (const char* tb : {"quarter_page", "per_fragment", "page", "draw_snapshot"}) {
    gs::model_options o;
    gs::set_option(o, "texture_buffer", tb);
    const rgb_frame a = replayed(o), b = model_rgb_frame(o);
    ASSERT_EQ(a.size(), b.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.size(); ++i) differ += a[i] != b[i];
    EXPECT_EQ(differ, 0u) << tb;
  }
}

}  // namespace
