// Section 3.1's variant "if there is not enough VRAM for two draw buffers" (render_options::buffers =
// draw_buffers::one, method.hpp): every light's dot layer and then the LAB's channels wait in free
// alphas while the output buffer is the DPB, the LAB and the diffuse layer in turn. Its passes are not
// the two-buffer method's (the ILP read from an alpha, step 4 as Cd·As instead of Cs·Ad), yet the
// moves are exact (alpha-layer.round-trip) and the blend's product takes the same two bytes, so the
// expected frame is the two-buffer render of the same scene (an independent sequence of passes), on
// both paths, for every method, one to three lights, and the model options that change the passes'
// arithmetic; and the dump of the variant replays to that frame, with the Z buffer's depths intact
// under the alpha kept in its top byte.
#include <gtest/gtest.h>

#include <array>
#include <random>
#include <stdexcept>
#include <string>

#include "gs_memory/address.hpp"
#include "gs_packets/dump.hpp"
#include "gs_packets/interpreter.hpp"
#include "pipeline/default_scene.hpp"
#include "pipeline/frame_packets.hpp"
#include "pipeline/render.hpp"
#include "method_param.hpp"

namespace gsdot3::pipeline {
namespace {

long differing(const frame& a, const frame& b, const std::string& what) {
  long n = 0;
  for (std::size_t i = 0; i < a.colour.size(); ++i)
    if (a.colour[i] != b.colour[i] && n++ < 3)
      ADD_FAILURE() << what << ": pixel " << i << " two buffers 0x" << std::hex << a.colour[i] << ", one buffer 0x"
                    << b.colour[i];
  for (std::size_t l = 0; l < a.dot.size(); ++l) n += a.dot[l] != b.dot[l];
  return n;
}

// Scenes with 1, 2 and 3 lights (point and directional), random views and colours bright enough that
// the LAB saturates somewhere (COLCLAMP in 2.6), the embedded scene's mesh at 64 segments.
std::vector<scene> light_counts(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> pos(-3.0f, 3.0f);
  std::uniform_int_distribution<int> byte(0, 255), size(40, 160);
  static const scene base = default_scene(64);
  std::vector<scene> out;
  for (std::size_t lights = 1; lights <= max_free_alpha_lights; ++lights) {
    scene s = base;
    s.width = size(rng), s.height = size(rng);
    s.lights.clear();
    for (std::size_t l = 0; l < lights; ++l)
      s.lights.push_back({{pos(rng), pos(rng), pos(rng)},
                          {static_cast<std::uint8_t>(byte(rng)), static_cast<std::uint8_t>(byte(rng)),
                           static_cast<std::uint8_t>(byte(rng))},
                          l == 1 ? light_kind::directional : light_kind::point});
    s.ambient = {static_cast<std::uint8_t>(byte(rng) / 2), static_cast<std::uint8_t>(byte(rng) / 2),
                 static_cast<std::uint8_t>(byte(rng) / 2)};
    s.view.eye = glm::vec3(pos(rng), pos(rng), 3.0f + std::fabs(pos(rng)));
    out.push_back(s);
  }
  return out;
}

class OneBuffer : public ::testing::TestWithParam<method> {};

TEST_P(OneBuffer, FramesEqualTheTwoBufferFramesOnBothPaths) {
  std::vector<scene> scenes = light_counts(3100 + static_cast<unsigned>(GetParam()));
  scenes.push_back(default_scene());
  int trial = 0;
  for (const scene& s : scenes) {
    const prepared_scene ps = prepare(s);
    for (const bool memory : {false, true}) {
      render_options o;
      o.memory_path = memory;
      o.bilinear = trial % 2 == 1;
      if (trial % 3 == 1) o.model.shift = gs::blend_shift::truncate;
      if (trial % 3 == 2) o.model.tfx = gs::tfx_rounding::truncate;
      const frame two = render(s, ps, GetParam(), o);
      o.buffers = draw_buffers::one;
      const frame one = render(s, ps, GetParam(), o);
      const std::string what = std::to_string(s.lights.size()) + " lights, " + (memory ? "memory" : "value") + " path";
      EXPECT_EQ(differing(two, one, what), 0) << what;
      ++trial;
    }
  }
}

// A traced render (one band, every pass recorded) draws the same frame.
TEST_P(OneBuffer, TracedFrameIsTheFrame) {
  const scene s = light_counts(77)[1];
  const prepared_scene ps = prepare(s);
  render_options o;
  o.buffers = draw_buffers::one;
  const frame plain = render(s, ps, GetParam(), o);
  std::vector<pass_record> trace;
  o.trace = &trace;
  const frame traced = render(s, ps, GetParam(), o);
  EXPECT_EQ(plain.colour, traced.colour);
  ASSERT_FALSE(trace.empty());
  EXPECT_EQ(trace.back().target, "frame");
}

// The variant's dump replayed: the displayed buffer is the two-buffer frame, and the Z buffer's
// depths (its words' low 24 bits) are the two-buffer dump's, although its top bytes held a free alpha.
TEST_P(OneBuffer, ReplayedDumpIsTheFrameAndKeepsTheDepths) {
  for (const scene& s : light_counts(4200 + static_cast<unsigned>(GetParam()))) {
    const prepared_scene ps = prepare(s);
    render_options o;
    const frame two = render(s, ps, GetParam(), o);
    struct replayed {
      std::vector<std::uint32_t> out, z;
    };
    auto replay = [&](draw_buffers b) {
      o.buffers = b;
      const frame_packets fp = build_frame_packets(s, ps, GetParam(), o);
      const gs::dump::gs_dump d = gs::dump::read_dump(gs::dump::write_dump(frame_dump(fp)));
      gs::mem::local_memory mem;
      gs::packets::interpreter gs(mem, {o.model, false});
      gs.replay(d);
      for (const auto& u : gs.unmodelled_features())
        ADD_FAILURE() << "unmodelled at byte " << u.offset << ": " << u.what;
      replayed r;
      const auto bw = fixed::uint<6>::from_wrapped(fp.buffers.fbw);
      const gs::mem::buffer out{fixed::uint<14>::from_wrapped(32 * fp.buffers.output()), bw, gs::mem::psm::PSMCT32},
          z{fixed::uint<14>::from_wrapped(32 * fp.buffers.z()), bw, gs::mem::psm::PSMZ32};
      for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
          const auto ux = static_cast<std::uint32_t>(x), uy = static_cast<std::uint32_t>(y);
          r.out.push_back(mem.read_pixel(out, ux, uy) | 0xFF000000u);
          r.z.push_back(mem.read_pixel(z, ux, uy));
        }
      return r;
    };
    const replayed r2 = replay(draw_buffers::two), r1 = replay(draw_buffers::one);
    const std::string what = std::to_string(s.lights.size()) + " lights";
    EXPECT_EQ(r1.out, two.colour) << what;
    EXPECT_EQ(r2.out, two.colour) << what;
    long depths = 0, alphas = 0;
    for (std::size_t i = 0; i < r1.z.size(); ++i) {
      depths += (r1.z[i] & 0xFFFFFFu) != (r2.z[i] & 0xFFFFFFu);
      alphas += (r1.z[i] >> 24) != 0;
    }
    EXPECT_EQ(depths, 0) << what;
    EXPECT_GT(alphas, 0) << what << ": the LAB's green should be in the Z buffer's top bytes";
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, OneBuffer, ::testing::ValuesIn(gs_methods), method_param_name);

TEST(OneBufferLimits, MoreThanThreeLightsOrAZTrickClearAreErrors) {
  scene s = default_scene(16);
  s.lights.resize(4, s.lights.front());
  const prepared_scene ps = prepare(s);
  render_options o;
  o.buffers = draw_buffers::one;
  try {
    (void)render(s, ps, method::two_pass, o);
    ADD_FAILURE() << "four lights in one buffer should be refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("at most 3"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)build_frame_packets(s, ps, method::two_pass, o), std::invalid_argument);
  s.lights.resize(2);
  o.dpb_clear = dpb_clear_mode::z_trick;
  EXPECT_THROW((void)render(s, prepare(s), method::two_pass, o), std::invalid_argument);
}

}  // namespace
}  // namespace gsdot3::pipeline
